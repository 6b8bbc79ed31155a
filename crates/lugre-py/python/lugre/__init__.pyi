"""Type stubs of the package `lugre` (defined in the compiled module `lugre._lugre`)."""

from . import chunk as chunk

from typing import (
    Any,
    Dict,
    Iterable,
    Iterator,
    Literal,
    Mapping,
    Optional,
    Sequence,
    SupportsFloat,
    SupportsIndex,
    Tuple,
    TypedDict,
    Union,
    overload,
    type_check_only,
)

import os

import numpy as np
import numpy.typing as npt
from typing_extensions import NotRequired

__version__: str

_Real = Union[float, int, SupportsFloat]
_Reals = Union[Sequence[_Real], npt.ArrayLike]
_Floats = npt.NDArray[np.float64]

class LuGre:
    """The LuGre friction model (paper eq. 1) with the Stribeck curve and viscous friction."""

    # The keywords and properties of the core's table (lugre.PARAMETERS), written from it:
    # LUGRE_BLESS=1 python -m pytest crates/lugre-py/tests/test_tables.py rewrites them.
    def __init__(
        self,
        *,
        sigma0: _Real = 1.0,
        sigma1: _Real = 1.0,
        sigma2: _Real = 0.0,
        fc: _Real = 1.0,
        fs: _Real = 2.0,
        vs: _Real = 1.0,
        beta: _Real = 1.0,
    ) -> None: ...
    @property
    def sigma0(self) -> float: ...
    @property
    def sigma1(self) -> float: ...
    @property
    def sigma2(self) -> float: ...
    @property
    def fc(self) -> float: ...
    @property
    def fs(self) -> float: ...
    @property
    def vs(self) -> float: ...
    @property
    def beta(self) -> float: ...
    # end of the table's parameters
    @staticmethod
    def preset(name: Literal["canudas1995"], **parameters: _Real) -> LuGre:
        """A published parameter set by name, the keywords (the constructor's) overriding it."""
    @property
    def g0(self) -> float: ...
    @property
    def a(self) -> float: ...
    @overload
    def g(self, v: float) -> float: ...
    @overload
    def g(self, v: _Reals) -> _Floats: ...
    @overload
    def f(self, v: float) -> float: ...
    @overload
    def f(self, v: _Reals) -> _Floats: ...
    def loop(self, turning_points: _Reals) -> HysteresisLoop: ...
    def loop_bimodal(self, umin1: _Real, umin2: _Real, umax1: _Real, umax2: _Real) -> HysteresisLoop: ...
    def simulate(
        self,
        turning_points: Optional[_Reals] = None,
        t: Optional[_Reals] = None,
        u: Optional[_Reals] = None,
        sine: Optional[Sequence[_Real]] = None,
        gamma: _Real = 1.0,
        periods: SupportsIndex = 1,
        x0: _Real = 0.0,
        times: Optional[Union[_Reals, Literal["knots"]]] = None,
        samples_per_period: Optional[SupportsIndex] = None,
        tol: _Real = 1e-10,
        interpolate: Literal["linear", "cubic"] = "linear",
        speed: Optional[_Real] = None,
    ) -> dict[str, _Floats]: ...
    def to_dict(self) -> dict[str, float]: ...
    def __eq__(self, other: object) -> bool: ...

class Dahl:
    """The Dahl friction model: w' = rho (u' - |u'| w), y = fc w."""

    # The keywords and properties of the core's table (lugre.PARAMETERS), written from it:
    # LUGRE_BLESS=1 python -m pytest crates/lugre-py/tests/test_tables.py rewrites them.
    def __init__(
        self,
        *,
        rho: _Real = 1.0,
        fc: _Real = 1.0,
    ) -> None: ...
    @property
    def rho(self) -> float: ...
    @property
    def fc(self) -> float: ...
    # end of the table's parameters
    @property
    def sigma0(self) -> float: ...
    @property
    def g0(self) -> float: ...
    @property
    def a(self) -> float: ...
    def to_lugre(self) -> LuGre: ...
    def loop(self, turning_points: _Reals) -> HysteresisLoop: ...
    def loop_bimodal(self, umin1: _Real, umin2: _Real, umax1: _Real, umax2: _Real) -> HysteresisLoop: ...
    def simulate(
        self,
        turning_points: Optional[_Reals] = None,
        t: Optional[_Reals] = None,
        u: Optional[_Reals] = None,
        sine: Optional[Sequence[_Real]] = None,
        gamma: _Real = 1.0,
        periods: SupportsIndex = 1,
        x0: _Real = 0.0,
        times: Optional[Union[_Reals, Literal["knots"]]] = None,
        samples_per_period: Optional[SupportsIndex] = None,
        tol: _Real = 1e-10,
        interpolate: Literal["linear", "cubic"] = "linear",
        speed: Optional[_Real] = None,
    ) -> dict[str, _Floats]: ...
    def to_dict(self) -> dict[str, float]: ...
    def __eq__(self, other: object) -> bool: ...

class HysteresisLoop:
    """The hysteresis loop y° of a model for one periodic input, with all its minor loops."""

    @property
    def rho(self) -> _Floats: ...
    @property
    def u(self) -> _Floats: ...
    @property
    def y(self) -> _Floats: ...
    @property
    def period(self) -> float: ...
    @property
    def work_per_period(self) -> float: ...
    @property
    def g0(self) -> float: ...
    @property
    def a(self) -> float: ...
    @property
    def model(self) -> Union[LuGre, Dahl]: ...
    @property
    def theorem_a(self) -> Optional[TheoremA]: ...
    @property
    def loops(self) -> list[Loop]: ...
    @property
    def loop_table(self) -> LoopTable: ...
    @overload
    def y_at(self, rho: float) -> float: ...
    @overload
    def y_at(self, rho: _Reals) -> _Floats: ...
    @overload
    def u_at(self, rho: float) -> float: ...
    @overload
    def u_at(self, rho: _Reals) -> _Floats: ...
    def sample(self, n: SupportsIndex = 1001) -> Curve: ...
    def __len__(self) -> int: ...

class ZooModel:
    """A model of the zoo (lugre.ZOO_MODELS) by name, its parameters as keywords by the table's
    names (element arrays as sequences or arrays, scalars as numbers; defaults from the table)."""

    def __init__(self, name: str, **parameters: Union[float, _Reals]) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def label(self) -> str: ...
    @property
    def parameters(self) -> dict[str, Union[float, _Floats]]: ...
    def loop(self, turning_points: _Reals) -> ZooLoop: ...
    def simulate(
        self,
        turning_points: Optional[_Reals] = None,
        t: Optional[_Reals] = None,
        u: Optional[_Reals] = None,
        speed: Optional[_Real] = None,
        samples_per_period: Optional[SupportsIndex] = None,
    ) -> ZooSimulation: ...
    def __eq__(self, other: object) -> bool: ...

class ZooSimulation(TypedDict):
    """What ``ZooModel.simulate`` and ``simulate(model=ZooModel(...))`` return: the keys of
    ``lugre simulate --model NAME --json``."""

    model: dict[str, Union[str, float, _Floats]]
    t: _Floats
    u: _Floats
    y: _Floats

class ZooLoop:
    """The loop of a model of the zoo for one periodic input, with every minor loop (the
    surface of HysteresisLoop; y is the model's force)."""

    @property
    def rho(self) -> _Floats: ...
    @property
    def u(self) -> _Floats: ...
    @property
    def y(self) -> _Floats: ...
    @property
    def period(self) -> float: ...
    @property
    def work_per_period(self) -> float: ...
    @property
    def model(self) -> ZooModel: ...
    @property
    def loops(self) -> list[Loop]: ...
    @property
    def loop_table(self) -> LoopTable: ...
    @overload
    def y_at(self, rho: float) -> float: ...
    @overload
    def y_at(self, rho: _Reals) -> _Floats: ...
    @overload
    def u_at(self, rho: float) -> float: ...
    @overload
    def u_at(self, rho: _Reals) -> _Floats: ...
    def sample(self, n: SupportsIndex = 1001) -> Curve: ...
    def __len__(self) -> int: ...

class LoopPoint:
    """A point of the loop: rho, u = psi_u(rho), y = y°(rho)."""

    @property
    def rho(self) -> float: ...
    @property
    def u(self) -> float: ...
    @property
    def y(self) -> float: ...
    def __len__(self) -> int: ...
    def __getitem__(self, i: int) -> float: ...
    def __iter__(self) -> Iterator[float]: ...
    def to_dict(self) -> dict[str, float]: ...

class Loop:
    """One loop: the arc from start through reversal to end, with its energies."""

    @property
    def kind(self) -> Literal["major", "minor"]: ...
    @property
    def start(self) -> LoopPoint: ...
    @property
    def reversal(self) -> LoopPoint: ...
    @property
    def end(self) -> LoopPoint: ...
    @property
    def work(self) -> float: ...
    @property
    def stored_energy_change(self) -> float: ...
    @property
    def dissipation(self) -> float: ...
    @property
    def closure_gap(self) -> float: ...
    @property
    def parent(self) -> Optional[int]: ...
    @property
    def depth(self) -> int: ...
    def to_dict(self) -> dict[str, object]: ...

class TheoremA:
    """Theorem A for a bimodal input: rho_0..rho_5, y° there, the minor loop [rho_1, rho_5]."""

    @property
    def rho(self) -> _Floats: ...
    @property
    def y(self) -> _Floats: ...
    @property
    def minor_loop(self) -> Tuple[float, float]: ...
    def to_dict(self) -> dict[str, list[float]]: ...

class Curve:
    """Points of the loop: float64 arrays rho, u, y; unpacks as `rho, u, y = curve`."""

    @property
    def rho(self) -> _Floats: ...
    @property
    def u(self) -> _Floats: ...
    @property
    def y(self) -> _Floats: ...
    def __iter__(self) -> Iterator[_Floats]: ...
    def to_dict(self) -> dict[str, _Floats]: ...
    def to_frame(self) -> Any: ...

@type_check_only
class LoopTable(TypedDict):
    """HysteresisLoop.loop_table: every loop as columns (a dict at runtime), rows as in .loops."""

    kind: npt.NDArray[np.int64]  # 0 major, 1 minor
    start_rho: _Floats
    start_u: _Floats
    start_y: _Floats
    reversal_rho: _Floats
    reversal_u: _Floats
    reversal_y: _Floats
    end_rho: _Floats
    end_u: _Floats
    end_y: _Floats
    work: _Floats
    stored_energy_change: _Floats
    dissipation: _Floats
    closure_gap: _Floats
    parent: npt.NDArray[np.int64]  # -1 for the major loop
    depth: npt.NDArray[np.int64]

@type_check_only
class CycleReversals(TypedDict):
    """The reversals of lugre.cycles (a dict at runtime)."""

    index: npt.NDArray[np.int64]
    u: _Floats

@type_check_only
class CycleTotals(TypedDict):
    """The energy totals along the whole history (a dict at runtime)."""

    y_start: float
    y_end: float
    work: float
    stored_energy_change: float
    dissipation: float

@type_check_only
class CycleSummary(TypedDict):
    """The summary of lugre.cycles (a dict at runtime)."""

    samples: int
    reversals: int
    full_cycles: int
    half_cycles: int
    energy: Optional[CycleTotals]

class CyclesResult(Dict[str, Any]):
    """The result of lugre.cycles: a dict with "reversals" (CycleReversals or None), "cycles"
    (each column name to a numpy array, one row per cycle: float64 "range", "mean", "count";
    int64 "start", "end"; unless closures=False, int64 "closure" and float64
    "closure_position"; with a model, float64 "work", "stored_energy_change", "dissipation",
    "closure_gap") and "summary" (CycleSummary). ``to_frame()`` gives the cycle table as a
    ``pandas.DataFrame``."""

    def to_frame(self) -> Any: ...

def cycles(
    series: _Reals,
    gate: _Real = 0.0,
    model: Optional[Union[LuGre, Dahl, ZooModel]] = None,
    x0: Optional[_Real] = None,
    *,
    reversals: bool = True,
    closures: bool = True,
) -> CyclesResult:
    """Reversals and ASTM E1049-85 rainflow cycles of a measured history, with loop closure and,
    with a model, the energy of each full cycle, as columns of numpy arrays (LuGre and Dahl from
    y*(0) = sigma0 x0, default 0; a ZooModel from rest at series[0], no x0)."""
    ...

@type_check_only
class FitEstimate(TypedDict):
    """One fitted parameter of lugre.fit (a dict at runtime)."""

    value: float
    stderr: float
    ci95: Tuple[float, float]
    at_bound: bool

# The noise levels estimated in the record and how the fit used them ("lambda" with
# "smoothed", the smoothing's; "gate" with "gate"). Functional form: "lambda" is a keyword.
FitNoise = TypedDict(
    "FitNoise",
    {
        "position": float,
        "force": float,
        "handling": Literal["smoothed", "as_given", "uneven", "gate"],
        "description": str,
        "lambda": float,
        "gate": float,
    },
    total=False,
)

@type_check_only
class FitCovariance(TypedDict, total=False):
    """Which covariance the standard errors come from, and the test that chose it."""

    method: Literal["classical", "newey-west"]
    description: str
    lags: int
    lag1_autocorrelation: float
    ljung_box: float
    ljung_box_95: float

@type_check_only
class StagedEstimate(FitEstimate):
    """One parameter of a staged fit, with the stage that determined it (a dict at runtime)."""

    stage: Literal["stribeck", "presliding", "full"]

@type_check_only
class SteadyPoints(TypedDict):
    """The points of a Stribeck fit: one a constant-velocity run (a dict at runtime)."""

    v: _Floats
    F: _Floats
    stderr: Optional[_Floats]  # None for a table (v, F)

@type_check_only
class PlateauRuns(TypedDict):
    """The steady part of each run found in a record, as columns (a dict at runtime)."""

    v: _Floats
    F: _Floats
    stderr: _Floats
    sd: _Floats
    samples: npt.NDArray[np.uint64]
    t_start: _Floats
    t_end: _Floats

@type_check_only
class Plateaus(TypedDict):
    """The constant-velocity runs found in a record (a dict at runtime)."""

    skipped: int
    velocity_noise: float
    runs: PlateauRuns

@type_check_only
class FitResult(TypedDict):
    """The result of lugre.fit (a dict at runtime)."""

    parameters: dict[str, FitEstimate]
    fixed: dict[str, float]
    values: dict[str, float]
    rms: float
    samples: int
    dof: int
    t_quantile: float
    condition_number: float
    correlation: _Floats
    iterations: int
    evaluations: int
    starts: int
    converged: bool
    termination: str
    turning_points: Optional[int]
    model: Literal["lugre", "dahl"]
    kind: Literal["slow", "full", "stribeck", "presliding"]
    normal_force: bool
    noise: Optional[FitNoise]
    warnings: list[str]
    covariance: FitCovariance
    fitted: _Floats
    residuals: _Floats  # kind="stribeck": at the points
    # kind="stribeck" only: the points fitted, and the runs found in a record (None: a table).
    points: NotRequired[SteadyPoints]
    plateaus: NotRequired[Optional[Plateaus]]

@type_check_only
class StagedResult(TypedDict):
    """The result of lugre.fit(kind="staged") (a dict at runtime)."""

    parameters: dict[str, StagedEstimate]
    fixed: dict[str, float]
    values: dict[str, float]
    stages: dict[str, FitResult]  # "stribeck", "presliding", "full"; without "values"
    model: Literal["lugre"]
    kind: Literal["staged"]

# A record of the staged fit: (t, u, F), a table of runs (v, F) (stribeck= only), or columns by
# role ("t", "u" or "v", "F") as lugre.read returns them.
_Record = Union[Tuple[_Reals, _Reals, _Reals], Tuple[_Reals, _Reals], Mapping[str, _Reals]]

@overload
def fit(
    u: Optional[_Reals],
    f: Optional[_Reals],
    *,
    t: Optional[_Reals] = None,
    model: Union[Literal["lugre"], str, LuGre] = "lugre",
    kind: Literal["staged"],
    fix: Union[str, Iterable[str], Mapping[str, _Real]] = (),
    free: Union[str, Iterable[str]] = (),
    start: Optional[Mapping[str, _Real]] = None,
    bounds: Optional[Mapping[str, Tuple[Optional[_Real], Optional[_Real]]]] = None,
    x0: None = None,
    starts: None = None,
    interpolate: Literal["linear"] = "linear",
    normal: None = None,
    v: Optional[_Reals] = None,
    noise: None = None,
    gate: None = None,
    stribeck: _Record,
    presliding: _Record,
    elements: None = None,
) -> StagedResult:
    """The staged identification: the Stribeck fit of the constant-velocity runs `stribeck`,
    the presliding fit of `presliding`, then, with (t, u, f), a full fit started from them."""
    ...

@overload
def fit(
    u: _Reals,
    f: _Reals,
    *,
    t: None = None,
    model: Union[
        Literal["maxwell-slip", "prandtl-ishlinskii", "bouc-wen", "elastoplastic"], ZooModel
    ],
    kind: Literal["slow", "full"] = "slow",
    fix: Union[str, Iterable[str], Mapping[str, Union[_Real, _Reals]]] = (),
    free: Union[str, Iterable[str]] = (),
    start: Optional[Mapping[str, Union[_Real, _Reals]]] = None,
    bounds: None = None,
    x0: None = None,
    starts: None = None,
    interpolate: Literal["linear"] = "linear",
    normal: None = None,
    v: None = None,
    noise: Literal["auto", "off"] = "auto",
    gate: Optional[_Real] = None,
    stribeck: None = None,
    presliding: None = None,
    elements: Optional[SupportsIndex] = None,
) -> ZooFitResult:
    """The slow-loop fit of a model of the zoo to one or more periods of a slow periodic test
    (u, f): every parameter of its slow loop by name with standard errors and 95 % intervals
    (the engine of `lugre fit --model NAME`). An element model's thresholds are held on a grid
    spanning the record's amplitude (`elements` of them, default 4) or taken from a
    lugre.ZooModel given as the model, whose values are the start values."""
    ...

@overload
def fit(
    u: _Reals,
    f: _Reals,
    *,
    t: _Reals,
    model: Union[Literal["maxwell-slip", "elastoplastic"], ZooModel],
    kind: Literal["full"],
    fix: Union[str, Iterable[str], Mapping[str, Union[_Real, _Reals]]] = (),
    free: Union[str, Iterable[str]] = (),
    start: Optional[Mapping[str, Union[_Real, _Reals]]] = None,
    bounds: None = None,
    x0: Optional[_Real] = None,
    starts: Optional[SupportsIndex] = None,
    interpolate: Literal["linear"] = "linear",
    normal: None = None,
    v: None = None,
    noise: Literal["auto", "off"] = "auto",
    gate: None = None,
    stribeck: None = None,
    presliding: None = None,
    elements: Optional[SupportsIndex] = None,
) -> ZooFitResult:
    """The full fit of a model of the zoo with a finite-rate form (GMS as "maxwell-slip", the
    elasto-plastic model) to a rate-dependent record (t, u, f): every parameter of its table on
    the model's exact path from rest at the record's rate, from `starts` start points (the
    engine of `lugre fit --model NAME --fit full`); x0, if given, must be 0 (the model starts
    from rest)."""
    ...

@overload
def fit(
    u: Optional[_Reals],
    f: _Reals,
    *,
    t: Optional[_Reals] = None,
    model: Union[Literal["lugre", "dahl"], str, LuGre, Dahl] = "lugre",
    kind: Union[Literal["slow", "full", "stribeck", "presliding"], str] = "slow",
    fix: Union[str, Iterable[str], Mapping[str, _Real]] = (),
    free: Union[str, Iterable[str]] = (),
    start: Optional[Mapping[str, _Real]] = None,
    bounds: Optional[Mapping[str, Tuple[Optional[_Real], Optional[_Real]]]] = None,
    x0: Optional[_Real] = None,
    starts: Optional[SupportsIndex] = None,
    interpolate: Literal["linear", "cubic"] = "linear",
    normal: Optional[_Reals] = None,
    v: Optional[_Reals] = None,
    noise: Literal["auto", "off"] = "auto",
    gate: Optional[_Real] = None,
    stribeck: None = None,
    presliding: None = None,
    elements: None = None,
) -> FitResult:
    """The LuGre or Dahl parameters from measured (u, f) or (t, u, f) samples, with standard
    errors, 95 % confidence intervals and correlations (the engine of `lugre fit`)."""
    ...

@type_check_only
class ZooFitResult(TypedDict):
    """The result of lugre.fit(u, f, model=NAME or a lugre.ZooModel) for a model of the zoo (a
    dict at runtime): the keys of FitResult; "parameters" by name, an element model's weights
    as "stiffness[i]" or "weights[i]"; "values" the fitted model's parameters
    (lugre.ZooModel(r["model"], **r["values"])); "fixed" the held parameters and an element
    model's thresholds ("thresholds", or Maxwell-slip's "slip_displacement")."""

    parameters: dict[str, FitEstimate]
    fixed: dict[str, Union[float, _Floats]]
    values: dict[str, Union[float, _Floats]]
    rms: float
    samples: int
    dof: int
    t_quantile: float
    condition_number: float
    correlation: _Floats
    iterations: int
    evaluations: int
    starts: int
    converged: bool
    termination: str
    turning_points: Optional[int]  # None for kind="full"
    model: str
    kind: Literal["slow"]
    normal_force: bool
    noise: FitNoise
    warnings: list[str]
    covariance: FitCovariance
    fitted: _Floats
    residuals: _Floats


class Columns(dict[str, _Floats]):
    """A data file's columns by role ("t", "u", "v", "F", "N" or a column's own name), with the
    header's units and names."""
    units: dict[str, Optional[str]]
    names: dict[str, Optional[str]]
    path: str
    def __init__(
        self,
        values: Mapping[str, _Floats],
        units: Mapping[str, Optional[str]],
        names: Mapping[str, Optional[str]],
        path: str,
    ) -> None: ...

def read(
    path: Union[str, "os.PathLike[str]"],
    columns: Optional[Union[Mapping[str, Union[str, int]], str]] = None,
    scale: Optional[Union[Mapping[str, _Real], str]] = None,
    delimiter: Optional[Literal["comma", "semicolon", "tab", "space", ",", ";", "\t", " "]] = None,
    *,
    roles: Optional[Sequence[str]] = None,
) -> Columns:
    """The columns of a data file by role, with their units, read as the `lugre` command reads
    `--input` files (header synonyms, units, comments, delimiters; ValueError naming the file,
    line and column)."""
    ...


class DynamicsEvent(TypedDict):
    t: float
    kind: Literal["velocity_zero", "velocity_up", "kink"]
    x: float


class DynamicsStats(TypedDict):
    steps: int
    rejected: int
    rhs_evaluations: int
    jacobians: int
    restarts: int


class Breakaway(TypedDict):
    t: float
    force: float
    x: float


class EnergyBalance(TypedDict):
    input: float
    stored_start: float
    stored_end: float
    dissipated: float


class FrictionLoop(TypedDict):
    t_start: float
    t_turn: float
    t_close: float
    turning_points: np.ndarray
    work: float
    # The change of the energy stored in the friction over the loop: the bristles'
    # (LuGre, elasto-plastic), the elements' springs sum F_i^2 / (2 k_i) (GMS).
    bristle_energy_change: float
    dissipation: float
    rate_independent_work: float


DYNAMICS_COLUMNS: Tuple[str, ...]
DYNAMICS_FIELDS: Tuple[str, ...]
# The core's tables: each model's parameters by name (symbol, description, unit, default,
# domain), in the order of its keywords; the columns of cycles and of a sampled loop.
PARAMETERS: Dict[str, Dict[str, Dict[str, Any]]]
ZOO_MODELS: Dict[str, Dict[str, Any]]
CYCLE_COLUMNS: Tuple[str, ...]
LOOP_COLUMNS: Tuple[str, ...]
SWEEP_COLUMNS: Tuple[str, ...]


class SweepResult(Dict[str, Any]):
    """What ``sweep`` returns: one array per column of ``SWEEP_COLUMNS`` (one entry per point,
    amplitude-major) and "loops" (a list of dicts t, u, force) when ``loop_samples`` was
    given."""

    def columns(self) -> Dict[str, np.ndarray]: ...
    def to_frame(self) -> Any: ...


def sweep(
    model: Union[LuGre, Dahl],
    *,
    amplitudes: Union[str, _Reals],
    frequencies: Union[str, _Reals],
    offset: Optional[float] = None,
    tol: Optional[float] = None,
    loop_samples: Optional[int] = None,
) -> SweepResult:
    """The periodic steady state under u = offset + A sin(2 pi f t) for every amplitude with
    every frequency (``lugre sweep``): energy dissipated per cycle, peak force, equivalent
    stiffness and damping, describing function (gain, phase in radians). amplitudes and
    frequencies: numbers > 0, or "a,b,c" / "start:stop:count" (log spacing). Defaults: the core
    request's (offset 0, tol 1e-12, no loops)."""
    ...


@overload
def simulate(model: ZooModel, *args: Any, **keywords: Any) -> ZooSimulation:
    """A model of the zoo from rest (``ZooModel.simulate``, its arguments): model, t, u, y."""
    ...
@overload
def simulate(model: Optional[Union[LuGre, Dahl]] = None, *args: Any, **keywords: Any) -> dict[str, _Floats]:
    """LuGre's or Dahl's response (``LuGre.simulate``; None: LuGre's defaults): t, u, z, dz, y."""
    ...


class DynamicsResult(Dict[str, Any]):
    """What ``dynamics`` returns: a dict with the keys t, x, v, z, friction, drive (arrays of
    one length), events, stats, energy, description, and where they apply breakaway,
    slip_onsets, period, loops."""

    def columns(self) -> Dict[str, np.ndarray]: ...
    def to_frame(self) -> Any: ...


def dynamics(
    model: Optional[Union[LuGre, Dahl, ZooModel]] = None,
    *,
    scenario: Optional[Literal["presliding", "breakaway", "stick-slip", "lag", "pid"]] = None,
    mass: Optional[float] = None,
    damping: Optional[float] = None,
    force: Optional[Tuple[_Reals, _Reals]] = None,
    force_rate: Optional[float] = None,
    spring: Optional[float] = None,
    pull: Optional[float] = None,
    end: Optional[Tuple[_Reals, _Reals]] = None,
    pid: Optional[Tuple[float, float, float]] = None,
    setpoint: Optional[Union[_Real, Tuple[_Reals, _Reals]]] = None,
    velocity: Optional[Tuple[_Reals, _Reals]] = None,
    t_end: Optional[float] = None,
    times: Optional[_Reals] = None,
    samples: Optional[int] = None,
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    loops: Optional[bool] = None,
) -> DynamicsResult:
    """The motion of a mass with LuGre friction from rest, driven by a force, a spring, a PID
    controller or a prescribed velocity (``lugre dynamics``), with the sign changes of the
    velocity located as events; ``scenario`` runs the experiments of Canudas de Wit et al.
    (1995) as presets whose fields the other keywords replace. Defaults: the core request's
    (mass 1 kg, 1001 samples, rtol 1e-8)."""
    ...
