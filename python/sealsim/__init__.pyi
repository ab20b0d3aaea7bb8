"""Type stubs of the sealsim package (issue 34). Tables are pandas DataFrames when pandas is
importable, else dicts of numpy arrays: typed ``Table`` here."""

import os
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union


__version__: str

PathLike = Union[str, os.PathLike[str]]
# a pandas.DataFrame, or a Dict[str, numpy.ndarray] without pandas
Table = Any
# None, True (a text bar on stderr), a tqdm-style bar (has .update), or a callable (done, total)
Progress = Union[None, bool, Any, Callable[[int, int], Any]]

class ScenarioError(ValueError):
    """Invalid scenario, study or input: ``file:line: key: message`` as the CLI prints it."""

class InternalError(RuntimeError):
    """A bug in sealsim (a panic or a non-finite result), raised instead of a crash."""

class SealsimWarning(UserWarning):
    code: str
    record: Dict[str, Any]
    def __init__(self, message: str, code: str = ..., record: Optional[Dict[str, Any]] = ...) -> None: ...

class ValidityWarning(SealsimWarning): ...

class InputWarning(SealsimWarning): ...

class RunResult:
    scenario: Scenario
    history: Table
    summary: Dict[str, Any]
    time_to_failure: Optional[float]
    failure_mode: str
    verdict: str
    verdict_text: str
    warnings: List[Dict[str, Any]]
    def plot(self, ax: Any = ...) -> Any: ...

class StudyResult:
    cases: Table
    summary: Dict[str, Any]
    b_lives: Dict[str, Dict[str, Optional[float]]]
    weibull: Optional[Dict[str, Any]]

class Scenario:
    @classmethod
    def from_file(cls, path: PathLike) -> Scenario: ...
    @classmethod
    def from_toml(cls, text: str, path: Optional[PathLike] = ...) -> Scenario: ...
    def replace(self, values: Optional[Mapping[str, Any]] = ..., **kwargs: Any) -> Scenario: ...
    @property
    def name(self) -> str: ...
    @property
    def path(self) -> str: ...
    @property
    def text(self) -> str: ...
    @property
    def fidelity(self) -> str: ...
    @property
    def input_warnings(self) -> List[str]: ...
    def run(self, fidelity: Optional[str] = ..., progress: Progress = ...) -> RunResult: ...
    def leak(
        self,
        pressures: Optional[Sequence[Union[float, str]]] = ...,
        fidelity: Optional[str] = ...,
        progress: Progress = ...,
    ) -> Table: ...

def compare(
    scenario: Scenario,
    compounds: Iterable[str],
    fidelity: Optional[str] = ...,
    progress: Progress = ...,
    raw: bool = ...,
) -> Table: ...
def study(
    source: Union[PathLike, str], threads: Optional[int] = ..., progress: Progress = ...
) -> StudyResult: ...
class GlandDesign:
    summary: Dict[str, Any]
    toml: str
    def __init__(self, summary: Dict[str, Any], toml: str) -> None: ...
    @property
    def stack_up(self) -> Table: ...
    @property
    def backup_rings_needed(self) -> int: ...
    def scenario(self) -> Scenario: ...

def gland(
    size: str,
    service: str,
    dynamic: bool = ...,
    pressure: Optional[str] = ...,
    backup_rings: int = ...,
    bore: Union[str, float, None] = ...,
    rod: Union[str, float, None] = ...,
    fit: str = ...,
    temperature: Optional[Sequence[Union[str, float]]] = ...,
    pressure_difference: Union[str, float, None] = ...,
    material: str = ...,
    housing: str = ...,
) -> GlandDesign: ...
def materials() -> Table: ...
def quantity(text: str, dimension: Optional[str] = ...) -> float: ...
class ContactResult:
    table: Table
    fields: List[Dict[str, Any]]
    n: int
    pixel_size: float
    realisations: int
    effective_modulus: float
    viscosity: float
    boundary: str
    control: str
    tolerance: float
    flow: Optional[str]

def contact(
    pressures: Union[Sequence[Union[float, str]], float, str, None] = ...,
    scenario: Optional[Scenario] = ...,
    *,
    displacement: Union[Sequence[Union[float, str]], float, str, None] = ...,
    boundary: str = ...,
    tolerance: Optional[float] = ...,
    height_map: Any = ...,
    pixel_size: Union[float, str, None] = ...,
    height_unit: Optional[str] = ...,
    youngs_modulus: Optional[float] = ...,
    poisson_ratio: float = ...,
    rms_roughness: Optional[float] = ...,
    hurst_exponent: Optional[float] = ...,
    q0: Optional[float] = ...,
    q1: Optional[float] = ...,
    fidelity: Optional[str] = ...,
    viscosity: Optional[float] = ...,
) -> Union[Table, ContactResult]: ...

class FitResult:
    material_toml: str
    terms: Table
    E_inf: float
    E0: float
    summary: List[str]
    warnings: List[str]
    name: str
    source: str
    points: int
    rms_relative_residual: float
    max_relative_residual: float
    window: Tuple[float, float]
    def relaxation(self, t: Any) -> Any: ...
    def write(self, path: PathLike) -> None: ...

def fit_prony(
    data: Any,
    kind: str,
    *,
    terms_per_decade: float = ...,
    regularisation: str = ...,
    honour: str = ...,
    name: Optional[str] = ...,
    temperature: Union[float, str, None] = ...,
    like: Optional[str] = ...,
    test_piece: Optional[str] = ...,
    squeeze: Union[float, str, None] = ...,
    cross_section: Union[float, str, None] = ...,
    mean_diameter: Union[float, str, None] = ...,
    diameter: Union[float, str, None] = ...,
    height: Union[float, str, None] = ...,
    initial_force: Union[float, str, None] = ...,
    reference_modulus: Union[float, str, None] = ...,
    shift: Optional[str] = ...,
    reference_temperature: Union[float, str, None] = ...,
    units: Optional[Mapping[str, str]] = ...,
    source: Optional[str] = ...,
) -> FitResult: ...

class SurfaceResult(Dict[str, Any]):
    spectrum: Table
    law: Table

def surface(
    source: Any,
    *,
    pixel_size: Union[float, str, None] = ...,
    height_unit: Optional[str] = ...,
    cutoff: Union[float, str, None] = ...,
    short_cutoff: Union[float, str, None] = ...,
    tip_radius: Union[float, str, None] = ...,
    name: Union[str, Sequence[str], None] = ...,
) -> SurfaceResult: ...
