"""Type stubs of the compiled module newtop._newtop (python/src)."""

from typing import Any, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

Vec3 = npt.ArrayLike

class InputError(ValueError): ...

class Body:
    @staticmethod
    def from_principal(inertia: Vec3, mass: float = 0.0, center_of_mass: Vec3 = ...,
                       gyrostat: Vec3 = ...) -> Body: ...
    @staticmethod
    def from_tensor(inertia_tensor: npt.ArrayLike, mass: float = 0.0,
                    center_of_mass: Vec3 = ..., gyrostat: Vec3 = ...) -> Body: ...
    @property
    def inertia(self) -> np.ndarray: ...
    @property
    def A(self) -> float: ...
    @property
    def B(self) -> float: ...
    @property
    def C(self) -> float: ...
    @property
    def mass(self) -> float: ...
    @property
    def center_of_mass(self) -> np.ndarray: ...
    @property
    def gyrostat(self) -> np.ndarray: ...
    @property
    def principal_axes(self) -> np.ndarray: ...

class QuadraticField:
    g: float
    lambda_: float
    @staticmethod
    def coulomb(g: float, lambda_: float) -> QuadraticField: ...
    @staticmethod
    def from_g_R(g: float, R: float) -> QuadraticField: ...
    @staticmethod
    def from_mu_R(mu: float, R: float) -> QuadraticField: ...
    @staticmethod
    def uniform(g: float) -> QuadraticField: ...
    @staticmethod
    def brun(N: float, plane_offset: float = 0.0) -> QuadraticField: ...

class State:
    m: np.ndarray
    gamma: np.ndarray
    def __init__(self, m: Vec3, gamma: Vec3, *, normalize: bool = False) -> None: ...
    @staticmethod
    def from_omega(body: Body, omega: Vec3, gamma: Vec3, *, normalize: bool = False) -> State: ...
    def omega(self, body: Body) -> np.ndarray: ...

class MassModel:
    @staticmethod
    def point_masses(masses: Sequence[float], positions: npt.ArrayLike) -> MassModel: ...
    @staticmethod
    def point_masses_file(path: str) -> MassModel: ...
    @staticmethod
    def polyhedron(vertices: npt.ArrayLike, faces: npt.ArrayLike, density: float) -> MassModel: ...
    @staticmethod
    def polyhedron_file(path: str, density: float, scale: float = 1.0) -> MassModel: ...
    @staticmethod
    def box(dimensions: Vec3, density: float, center: Vec3 = ...) -> MassModel: ...
    @staticmethod
    def ellipsoid(semi_axes: Vec3, density: float, center: Vec3 = ...) -> MassModel: ...
    @property
    def kind(self) -> str: ...
    @property
    def mass(self) -> float: ...
    @property
    def center_of_mass(self) -> np.ndarray: ...
    @property
    def inertia_tensor(self) -> np.ndarray: ...
    @property
    def max_radius(self) -> float: ...

class Model:
    def __init__(self, body: Body, field: QuadraticField) -> None: ...
    @staticmethod
    def exact(mass_model: MassModel, mu: float, R: float, gyrostat: Vec3 = ...) -> Model: ...
    @staticmethod
    def multipole(mass_model: MassModel, order: int, mu: float, R: float,
                  gyrostat: Vec3 = ...) -> Model: ...
    @staticmethod
    def quadratic_on(mass_model: MassModel, field: QuadraticField, gyrostat: Vec3 = ...) -> Model: ...
    @property
    def body(self) -> Body: ...
    @property
    def kind(self) -> str: ...
    def potential(self, gamma: Vec3) -> float: ...
    def grad_gamma(self, gamma: Vec3) -> np.ndarray: ...
    def hessian_gamma(self, gamma: Vec3) -> np.ndarray: ...
    def moment(self, gamma: Vec3) -> np.ndarray: ...
    def rhs(self, x: Union[State, Sequence[float]]) -> npt.NDArray[np.float64]: ...
    def quadratic_approximation(self) -> Model: ...

class Scenario:
    def __init__(self, model: Model, initial: State, *, t0: float = 0.0,
                 t_end: Optional[float] = None, method: Optional[str] = None,
                 step: Optional[float] = None, tol: Optional[float] = None,
                 max_steps: Optional[int] = None) -> None: ...
    @property
    def source(self) -> str: ...
    model: Model
    initial: State
    @property
    def attitude(self) -> Optional[npt.NDArray[np.float64]]: ...
    t0: float
    t_end: Optional[float]
    method: Optional[str]
    step: Optional[float]
    tol: Optional[float]
    @property
    def input_files(self) -> list[str]: ...

def load_scenario(path: str) -> Union[Scenario, OrbitScenario]: ...
def parse_scenario(text: str, source: str = "<string>") -> Union[Scenario, OrbitScenario]: ...
def is_orbit_scenario(path: str) -> bool: ...
def integrals(model: Model, state: State) -> dict[str, float]: ...
def conserved_integrals(model: Model) -> list[str]: ...
@overload
def integrate(model: Model, state: State, t_end: float, *, t0: float = 0.0,
              method: Optional[str] = None, step: Optional[float] = None,
              tol: Optional[float] = None, max_steps: Optional[int] = None,
              quaternion: Optional[Sequence[float]] = None,
              t_eval: Optional[Sequence[float]] = None) -> dict[str, Any]: ...
@overload
def integrate(scenario: Scenario, *, t_end: Optional[float] = None, method: Optional[str] = None,
              step: Optional[float] = None, tol: Optional[float] = None) -> dict[str, Any]: ...
def integrate_ensemble(model_or_models: Union[Model, Sequence[Model], OrbitModel,
                                              Sequence[OrbitModel]],
                       states: Union[Sequence[State], Sequence[OrbitState], Any], t_end: float,
                       *, tol: float,
                       t0: float = 0.0, max_steps: Optional[int] = None,
                       t_eval: Optional[Sequence[float]] = None) -> dict[str, Any]: ...
def chaos_ensemble(model_or_models: Union[Model, Sequence[Model]],
                   states: Union[Sequence[State], Any], t_end: float, *, tol: float,
                   t0: float = 0.0, max_steps: Optional[int] = None) -> dict[str, Any]: ...
def brun_state_at(model: Model, state: State, t: float) -> State: ...
def resonance_family(eccentricity: float, k: float, parameter: str, end: float, p: int = 1,
                     q: int = 1, line: float = 0.0, switch: bool = False) -> dict[str, Any]: ...
def rest_family(body: Body, g: float, lambda_: float, key: str, p0: float, p1: float,
                gamma: npt.ArrayLike) -> dict[str, Any]: ...
def lyapunov_family(body: Body, g: float, lambda_: float, gamma: npt.ArrayLike, mode: int,
                    p0: float, p1: float) -> dict[str, Any]: ...
def rotation_family(body: Body, lambda_: float, omega0: float, omega1: float,
                    axis: Optional[int] = None) -> dict[str, Any]: ...
def equilibrium_family(inertia: npt.ArrayLike, radial: int, normal: int, index: int, p0: float,
                       p1: float) -> dict[str, Any]: ...

Array = npt.NDArray[np.float64]

class Equilibria:
    count: int
    gamma: Array
    kappa: Array
    potential: Array
    hessian_eigenvalues: Array
    staude_residual: Array
    type: list[str]
    every_orientation: bool
    circles: list[dict[str, Any]]
    minima: int
    saddles: int
    maxima: int
    degenerate: int
    euler_characteristic: int
    count_rule_holds: bool

class StabilityReport:
    state: State
    eigenvalues: npt.NDArray[np.complex128]
    max_real_part: float
    linearly_stable: bool
    lyapunov_stable: Optional[bool]
    threshold_omega_formula: Optional[float]
    threshold_omega_numeric: Optional[float]
    formula_note: str
    axis: Optional[str]
    gamma: Array
    residual: float
    polish: dict[str, float]

class ChaosResult:
    lyapunov_max: float
    megno: float
    megno_y: float
    fli: float
    spectrum: Optional[Array]
    t_end: float
    outcome: str
    steps: int
    method: str
    history: Optional[dict[str, Array]]

class Section:
    stopped_by: str
    surface: str
    count: int
    orbit: npt.NDArray[np.int32]
    t: Array
    m: Array
    gamma: Array
    omega: Array
    outcomes: list[str]
    max_surface_residual: float

class AnalyticResult:
    case: str
    reason: str
    period: Optional[float]
    t: Array
    omega: Array
    gamma: Array
    m: Array
    numeric_omega: Array
    numeric_gamma: Array
    max_abs_error: Optional[float]
    reference_outcome: str

def _equilibria(model: Model) -> Equilibria: ...
def _stability(model: Model, *, equilibrium: Optional[int] = None, state: Optional[State] = None,
               axis: Union[str, int, None] = None,
               omega: Optional[float] = None) -> StabilityReport: ...
def _chaos(model: Model, state: State, t_end: float, *, t0: float = 0.0,
           method: Optional[str] = None, step: Optional[float] = None,
           tol: Optional[float] = None, spectrum: bool = False, max_steps: Optional[int] = None,
           history: bool = False) -> ChaosResult: ...
def _section(model: Model, states: Sequence[State], t_end: float, *, surface: str = "gamma3 = 0",
             crossings: int = 1000, direction: str = "up", t0: float = 0.0,
             method: Optional[str] = None, step: Optional[float] = None,
             tol: Optional[float] = None, max_steps: Optional[int] = None) -> Section: ...
def _analytic(model: Model, state: State, times: Sequence[float], *,
              max_steps: Optional[int] = None) -> AnalyticResult: ...


# --- the satellite on an orbit (orbit.cpp, orbit_run.cpp, orbit_analyses.cpp) -----------------

class OrbitModel:
    @staticmethod
    def circular(body: Body, *, mu: Optional[float] = None, radius: Optional[float] = None,
                 rate: Optional[float] = None) -> OrbitModel: ...
    @staticmethod
    def elliptic(body: Body, *, mu: float, a: float, e: float,
                 true_anomaly: float = 0.0) -> OrbitModel: ...
    @property
    def kind(self) -> str: ...
    @property
    def body(self) -> Body: ...
    @property
    def mu(self) -> Optional[float]: ...
    @property
    def radius(self) -> Optional[float]: ...
    @property
    def rate(self) -> float: ...
    @property
    def lambda_(self) -> Optional[float]: ...
    @property
    def eccentricity(self) -> float: ...
    @property
    def true_anomaly(self) -> float: ...
    @property
    def period(self) -> float: ...
    def rhs(self, state: OrbitState, nu: Optional[float] = None) -> np.ndarray: ...
    def integral(self, state: OrbitState, nu: Optional[float] = None) -> float: ...

class OrbitState:
    def __init__(self, m: Vec3, gamma: Vec3, normal: Vec3) -> None: ...
    @staticmethod
    def from_omega(body: Body, omega: Vec3, gamma: Vec3, normal: Vec3) -> OrbitState: ...
    @staticmethod
    def from_lvlh(model: OrbitModel, *, roll_pitch_yaw: Optional[Vec3] = None,
                  lvlh_quaternion: Optional[npt.ArrayLike] = None,
                  omega_relative: Vec3 = ...) -> OrbitState: ...
    @property
    def m(self) -> np.ndarray: ...
    @property
    def gamma(self) -> np.ndarray: ...
    @property
    def normal(self) -> np.ndarray: ...
    def omega(self, body: Body) -> np.ndarray: ...
    def lvlh_quaternion(self) -> list[float]: ...
    def roll_pitch_yaw(self) -> np.ndarray: ...

class OrbitScenario:
    def __init__(self, model: OrbitModel, initial: OrbitState, *, t0: float = 0.0,
                 t_end: Optional[float] = None, method: Optional[str] = None,
                 step: Optional[float] = None, tol: Optional[float] = None,
                 max_steps: Optional[int] = None) -> None: ...
    source: str
    model: OrbitModel
    initial: OrbitState
    kind: str
    t0: float
    t_end: Optional[float]
    method: Optional[str]
    step: Optional[float]
    tol: Optional[float]
    max_steps: Optional[int]

@overload
def integrate(model: OrbitModel, state: OrbitState, t_end: float, *, t0: float = 0.0,
              method: Optional[str] = None, step: Optional[float] = None,
              tol: Optional[float] = None, max_steps: Optional[int] = None,
              t_eval: Optional[Sequence[float]] = None) -> dict[str, Any]: ...
@overload
def integrate(scenario: OrbitScenario, *, t_end: Optional[float] = None,
              method: Optional[str] = None, step: Optional[float] = None,
              tol: Optional[float] = None,
              t_eval: Optional[Sequence[float]] = None) -> dict[str, Any]: ...

class RelativeEquilibria:
    count: int
    gamma: np.ndarray
    normal: np.ndarray
    lvlh_quaternion: np.ndarray
    roll_pitch_yaw: np.ndarray
    jacobi: np.ndarray
    residual: np.ndarray
    eigenvalues: np.ndarray
    max_real_part: np.ndarray
    linearly_stable: np.ndarray
    lyapunov_stable: list[Optional[bool]]
    verdict: list[str]
    lyapunov: int
    gyroscopic: int
    unstable: int
    unverified: int
    resultant_tail: float
    polish_distance: float
    def __len__(self) -> int: ...

class RelativeStability:
    eigenvalues: np.ndarray
    characteristic_polynomial: np.ndarray
    max_real_part: float
    linearly_stable: bool
    lyapunov_stable: Optional[bool]
    verdict: str
    state: OrbitState
    omega: np.ndarray
    gamma: np.ndarray
    normal: np.ndarray
    jacobi: float
    residual: float

class DebraDelpDiagram:
    k_R: np.ndarray
    k_Y: np.ndarray
    region: list[str]
    closed_form: list[str]
    boundary: np.ndarray
    max_real_part: np.ndarray
    characteristic: np.ndarray
    counts: dict[str, int]
    disagreements_with_closed_form: int
    def __len__(self) -> int: ...

def debra_delp(k_R: tuple[float, float, int] = (-0.99, 0.99, 67),
               k_Y: tuple[float, float, int] = (-0.99, 0.99, 67)) -> DebraDelpDiagram: ...
def _orbit_equilibria(model: OrbitModel) -> RelativeEquilibria: ...
def _orbit_stability(model: OrbitModel, *, equilibrium: Optional[int] = None,
                     state: Optional[OrbitState] = None) -> RelativeStability: ...

class OrbitSection:
    surface: str
    direction: str
    method: str
    count: int
    orbit: str
    t: npt.NDArray[np.float64]
    nu: Optional[npt.NDArray[np.float64]]
    crossing_orbit: npt.NDArray[np.int32]
    omega: npt.NDArray[np.float64]
    gamma: npt.NDArray[np.float64]
    m: npt.NDArray[np.float64]
    normal: npt.NDArray[np.float64]
    euler_321: npt.NDArray[np.float64]
    omega_relative: npt.NDArray[np.float64]
    roll_pitch_yaw: npt.NDArray[np.float64]
    lvlh_quaternion: npt.NDArray[np.float64]
    stopped_by: str
    max_surface_residual: float
    integrals_drift: dict[str, float]
    outcome: str
class OrbitChaosResult:
    lyapunov_max: float
    megno: float
    megno_y: float
    fli: float
    spectrum: Optional[npt.NDArray[np.float64]]
    t_end: float
    outcome: str
    method: str
    tol: float
    orbit: str
    history: Optional[dict[str, npt.NDArray[np.float64]]]
class LibrationReport:
    eccentricity: float
    k: float
    iterates: int
    chaos_threshold: float
    chaotic_starts: int
    resonances: list[dict[str, Any]]
    theta0: npt.NDArray[np.float64]
    dtheta0: npt.NDArray[np.float64]
    spin0: npt.NDArray[np.float64]
    lyapunov: npt.NDArray[np.float64]
    chaotic: npt.NDArray[np.bool_]
    points: list[npt.NDArray[np.float64]]
def _orbit_section(scenario: OrbitScenario, **kwargs: Any) -> OrbitSection: ...
def _orbit_chaos(scenario: OrbitScenario, **kwargs: Any) -> OrbitChaosResult: ...
def _libration(scenario: OrbitScenario, **kwargs: Any) -> LibrationReport: ...
def _chaos_scenario(scenario: Scenario, **kwargs: Any) -> ChaosResult: ...
def _section_scenario(scenario: Scenario, **kwargs: Any) -> Section: ...
def _simulation_summary(model: Model, t: Any, m: Any, gamma: Any) -> dict[str, Any]: ...
def _write_trajectory_csv(path: str, model: Model, t: Any, m: Any, gamma: Any,
                          **kwargs: Any) -> None: ...
def _view(csv: str, out: str, scenario: Any = None, max_frames: int = 5000) -> int: ...
def _sweep_file(path: str, threads: int = 0) -> dict[str, Any]: ...
