"""Type stubs of the sealsim package (issue 34). Tables are pandas DataFrames when pandas is
importable, else dicts of numpy arrays: typed ``Table`` here."""

import os
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Union


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
) -> Table: ...
def study(
    source: Union[PathLike, str], threads: Optional[int] = ..., progress: Progress = ...
) -> StudyResult: ...
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

def contact(
    pressures: Sequence[Union[float, str]],
    scenario: Optional[Scenario] = ...,
    *,
    height_map: Any = ...,
    pixel_size: Optional[float] = ...,
    youngs_modulus: Optional[float] = ...,
    poisson_ratio: float = ...,
    rms_roughness: Optional[float] = ...,
    hurst_exponent: Optional[float] = ...,
    q0: Optional[float] = ...,
    q1: Optional[float] = ...,
    fidelity: Optional[str] = ...,
    viscosity: Optional[float] = ...,
) -> Union[Table, ContactResult]: ...
