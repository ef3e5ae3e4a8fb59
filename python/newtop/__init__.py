"""newtop from Python.

Today this package holds the pictures (``newtop.plot``) and the readers of the files that the
``newtop`` program writes (``newtop.results``); both are pure Python (numpy, matplotlib).

The compiled extension (pybind11: ``Body``, the fields, ``Model``, ``State``, ``integrate`` and one
function per subcommand) will be the module ``newtop._newtop``. When it is built, its names are
re-exported here; without it ``import newtop`` still works and ``newtop.HAVE_EXTENSION`` is False.
"""

__version__ = "0.1.0"

try:  # the compiled extension, when the build made one (PYTHONPATH=build/python)
    from ._newtop import *  # noqa: F401,F403

    HAVE_EXTENSION = True
except ModuleNotFoundError as e:  # absent is fine; present but broken is an error
    if e.name != __name__ + "._newtop":
        raise
    HAVE_EXTENSION = False

__all__ = ["HAVE_EXTENSION", "__version__"]
