"""newtop from Python.

The compiled extension ``newtop._newtop`` (pybind11) gives the library: ``Body``,
``QuadraticField``, ``Model``, ``State``, ``load_scenario``, ``integrals``, ``integrate`` (numpy
arrays); ``newtop.analyses`` gives the analyses on those objects (``newtop.equilibria(model)``,
``newtop.stability``, ``newtop.chaos``, ``newtop.section``, ``newtop.analytic``: typed results
with numpy arrays); ``newtop.commands`` gives one function per subcommand (``newtop.simulate``,
``newtop.integrals``, ``newtop.equilibria``, ``newtop.stability``, ``newtop.analytic``, ...) that
returns the subcommand's JSON as a dict. Both are re-exported here (docs/python.md).

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
