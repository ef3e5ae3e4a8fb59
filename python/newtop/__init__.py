"""newtop from Python.

The compiled extension ``newtop._newtop`` (pybind11) gives the library: ``Body``,
``QuadraticField``, ``Model``, ``State``, ``Scenario``, ``load_scenario``, ``integrate`` (numpy
arrays), the orbit model; ``newtop.analyses`` gives every analysis on those objects, on a Scenario
read from a file or on a path (``newtop.equilibria``, ``stability``, ``section``, ``chaos``,
``analytic``, ``rotations``, ``find_integrals``, ``field``, ``integrals``, ``simulate``,
``libration``, ``view``, ``sweep``: typed results with numpy arrays, computed in this process).
``newtop.commands`` is the command line from Python: it runs the ``newtop`` program as a separate
process and returns its JSON as a dict (docs/python.md).

The pictures (``newtop.plot``) and the readers of newtop's files (``newtop.results``) are pure
Python (numpy, matplotlib): without the extension ``import newtop`` still works for them and
``newtop.HAVE_EXTENSION`` is False.
"""

__version__ = "0.1.0"

try:  # the compiled extension, when the build made one (PYTHONPATH=build/python)
    from ._newtop import (Body, InputError, MassModel, Model, QuadraticField, Scenario, State,  # noqa: F401
                          brun_state_at, conserved_integrals, equilibrium_family, integrate,
                          integrate_ensemble, chaos_ensemble, is_orbit_scenario,
                          load_scenario, parse_scenario, resonance_family, rotation_family)
    from ._newtop import lyapunov_family, rest_family  # noqa: F401  (docs/continuation.md)
    from ._newtop import integrals as integrals_at  # noqa: F401  (the library's, at a state)
    from ._newtop import (AnalyticResult, ChaosResult, Equilibria, Section,  # noqa: F401
                          StabilityReport)
    from ._newtop import (DebraDelpDiagram, OrbitModel, OrbitScenario, OrbitState,  # noqa: F401
                          LibrationReport, OrbitChaosResult, OrbitSection, RelativeEquilibria, RelativeStability,
                          debra_delp)
    from ._newtop import IntegralSearch, RotationFamilies  # noqa: F401
    from . import commands  # noqa: F401  (the command line from Python)
    from .analyses import (analytic, chaos, equilibria, field, find_integrals,  # noqa: F401
                           integrals, libration, rotations, section, simulate, stability,
                           sweep, view)

    HAVE_EXTENSION = True
except ModuleNotFoundError as e:  # absent is fine; present but broken is an error
    if e.name != __name__ + "._newtop":
        raise
    HAVE_EXTENSION = False

__all__ = ["HAVE_EXTENSION", "__version__"]
if HAVE_EXTENSION:
    __all__ += ["AnalyticResult", "ChaosResult", "Equilibria", "IntegralSearch", "RotationFamilies",
                "Section", "StabilityReport",
                "Body", "InputError", "MassModel", "Model", "QuadraticField", "Scenario", "State",
                "analytic", "chaos", "conserved_integrals", "equilibria", "field", "find_integrals",
                "integrals", "integrals_at", "integrate", "integrate_ensemble", "chaos_ensemble",
                "is_orbit_scenario", "libration", "LibrationReport",
                "load_scenario", "parse_scenario", "rotations", "section", "simulate", "stability", "sweep",
                "view", "DebraDelpDiagram", "OrbitChaosResult", "OrbitModel", "OrbitScenario",
                "OrbitSection", "OrbitState",
                "RelativeEquilibria", "RelativeStability", "debra_delp"]
