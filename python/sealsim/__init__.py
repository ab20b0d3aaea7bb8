"""sealsim: leak rate and life of rubber seals from rough-surface contact mechanics.

The physics follows B.N.J. Persson and C. Yang, *Theory of the leak-rate of seals*,
J. Phys.: Condens. Matter 20 (2008) 315011; the model reference is docs/model.md of the
repository. This package calls the Rust library's workflows and reports in process (not the
``sealsim`` binary), so its numbers are the command line's, bit for bit.

Every number is an SI float (Pa, m, s, K, m³/s); tables are pandas DataFrames when pandas is
importable, else dicts of numpy arrays, with the column names of the command line's CSV files.

>>> import sealsim
>>> scenario = sealsim.Scenario.from_file("scenarios/oring-nbr-water-80c.toml")
>>> result = scenario.run()
>>> result.time_to_failure, result.failure_mode          # doctest: +SKIP
(24302880.0, 'retained_force')
>>> result.history["leak_rate_m3_per_s"]                 # doctest: +SKIP

Long calls release the GIL and can be interrupted with Ctrl-C (``KeyboardInterrupt``). Invalid
input raises :class:`ScenarioError` (a ``ValueError``) with the command line's
``file:line: key: message``; a bug in sealsim raises :class:`InternalError` (a
``RuntimeError``), never a crash.
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Union

import numpy

from . import _sealsim
from ._fit import FitResult, SurfaceResult, fit_prony, surface
from ._sealsim import InternalError, ScenarioError, quantity

__version__ = _sealsim.__version__

__all__ = [
    "Scenario",
    "RunResult",
    "StudyResult",
    "ScenarioError",
    "InternalError",
    "compare",
    "study",
    "materials",
    "contact",
    "quantity",
    "fit_prony",
    "FitResult",
    "surface",
    "SurfaceResult",
    "__version__",
]

PathLike = Union[str, "os.PathLike[str]"]


def _table(columns: Mapping[str, list]) -> Any:
    """Columns (name -> list of floats or of strings) as a DataFrame, or a dict of arrays."""
    arrays = {}
    for name, values in columns.items():
        if values and isinstance(values[0], str):
            arrays[name] = numpy.array(values, dtype=object)
        else:
            arrays[name] = numpy.array(values, dtype=numpy.float64)
    try:
        import pandas
    except ImportError:
        return arrays
    return pandas.DataFrame(arrays)


class RunResult:
    """The life of a scenario's seal (``sealsim run``).

    Attributes:
        history: one row per output time (the first is the installation, t = 0) with the
            columns of the history CSV (``time_s``, ``temperature_K``, ...,
            ``leak_rate_m3_per_s``, ``state``, ...); a blank cell of the CSV is NaN.
        summary: the ``--summary`` JSON as a dict.
        time_to_failure: seconds, or None when the seal survives.
        failure_mode: ``leak_rate``, ``leaked_volume``, ``retained_force``, ``lift_off``, ...,
            or ``none``.
        verdict: ``fails``, ``open`` or ``survives``; ``verdict_text`` the sentence.
        warnings: the validity findings, a list of dicts (as in the summary JSON).
    """

    def __init__(self, scenario: "Scenario", columns: Mapping[str, list], summary: Dict[str, Any]):
        self.scenario = scenario
        self._columns = columns
        self._history: Any = None
        self.summary = summary
        self.time_to_failure: Optional[float] = summary.get("time_to_failure_s")
        self.failure_mode: str = summary["failure_mode"]
        self.verdict: str = summary["verdict"]
        self.verdict_text: str = summary["verdict_text"]
        self.warnings: List[Dict[str, Any]] = summary.get("warnings", [])

    @property
    def history(self) -> Any:
        """The history table (built on first use: a loop that wants only the summary does not
        pay for a DataFrame per run)."""
        if self._history is None:
            self._history = _table(self._columns)
        return self._history

    def __repr__(self) -> str:
        return f"RunResult({self.scenario.name!r}: {self.verdict_text})"

    def plot(self, ax: Any = None) -> Any:
        """A matplotlib figure of the leak rate, the sealing force and the temperature
        against time (three stacked axes; the failure marked). Needs matplotlib."""
        import matplotlib.pyplot as plt

        h = self.history
        t = numpy.asarray(h["time_s"], dtype=float)
        duration = t[-1] if len(t) else 0.0
        year, day = 365.25 * 86400.0, 86400.0
        scale, unit = (year, "years") if duration >= 2 * year else (day, "days")
        fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
        q = numpy.asarray(h["leak_rate_m3_per_s"], dtype=float)
        positive = q[q > 0]
        floor = positive.min() if positive.size else 1e-30
        axes[0].semilogy(t / scale, numpy.maximum(q, floor))
        axes[0].set_ylabel("leak rate [m³/s]")
        axes[1].plot(t / scale, numpy.asarray(h["sealing_force_N_per_m"], dtype=float))
        axes[1].set_ylabel("sealing force [N/m]")
        axes[2].plot(t / scale, numpy.asarray(h["temperature_K"], dtype=float) - 273.15)
        axes[2].set_ylabel("temperature [°C]")
        axes[2].set_xlabel(f"time [{unit}]")
        if self.time_to_failure is not None:
            for a in axes:
                a.axvline(self.time_to_failure / scale, color="red", linestyle="--")
        axes[0].set_title(f"{self.scenario.name}: {self.verdict_text}", fontsize="small")
        fig.tight_layout()
        return fig


class StudyResult:
    """A tolerance study (``sealsim study``).

    Attributes:
        cases: one row per case (the cases CSV: the inputs in SI, time to failure, mode, ...).
        summary: the ``--summary`` JSON as a dict.
        b_lives: ``{"b10": {"estimate": s, "lower": s, "upper": s}, ...}`` (None where not
            reached).
        weibull: the Weibull fit (shape, scale_s, fits, ks_distance, ...) or None.
    """

    def __init__(self, cases: Any, summary: Dict[str, Any]):
        self.cases = cases
        self.summary = summary
        self.b_lives: Dict[str, Dict[str, Optional[float]]] = {}
        for key in summary:
            if key.startswith("b") and key.endswith("_s") and key[1:-2].isdigit():
                name = key[:-2]
                self.b_lives[name] = {
                    "estimate": summary[key],
                    "lower": summary.get(f"{name}_lower_s"),
                    "upper": summary.get(f"{name}_upper_s"),
                }
        self.weibull: Optional[Dict[str, Any]] = summary.get("weibull")

    def __repr__(self) -> str:
        s = self.summary
        return f"StudyResult({s.get('study')!r}: {s.get('cases')} cases, {s.get('failures')} failures)"


class Scenario:
    """A validated scenario (TOML with unit strings, read once into SI).

    Build one with :meth:`from_file` or :meth:`from_toml`; :meth:`replace` gives a changed
    copy. Invalid input raises :class:`ScenarioError` naming the file, the line and the key.
    """

    __slots__ = ("_inner",)

    def __init__(self, inner: "_sealsim.Scenario"):
        self._inner = inner

    @classmethod
    def from_file(cls, path: PathLike) -> "Scenario":
        """Reads and validates the scenario file at ``path`` (relative data files are resolved
        against its directory). A missing file raises ``FileNotFoundError``."""
        return cls(_sealsim.Scenario.from_file(os.fspath(path)))

    @classmethod
    def from_toml(cls, text: str, path: Optional[PathLike] = None) -> "Scenario":
        """Validates scenario TOML ``text``. ``path`` names it in messages and resolves relative
        data files (default ``<string>``: the working directory)."""
        return cls(_sealsim.Scenario.from_toml(text, None if path is None else os.fspath(path)))

    def replace(self, values: Optional[Mapping[str, Any]] = None, **kwargs: Any) -> "Scenario":
        """A new scenario with dotted keys set as a study's ``[vary]`` sets them, e.g.
        ``replace({"seal.squeeze": "22 %", "environment.temperature": "60 C"})`` (values: str
        with units, numbers, bools, lists, dicts). Setting ``material.library`` or
        ``material.file`` replaces the compound."""
        merged = dict(values or {})
        merged.update(kwargs)
        return Scenario(self._inner.replace(merged))

    @property
    def name(self) -> str:
        """The scenario's ``name`` (or the file stem)."""
        return self._inner.name

    @property
    def path(self) -> str:
        """The file as given, or ``<string>``."""
        return self._inner.path

    @property
    def text(self) -> str:
        """The scenario's TOML text."""
        return self._inner.text

    @property
    def fidelity(self) -> str:
        """The fidelity level it runs at (``simulation.fidelity``)."""
        return self._inner.fidelity

    @property
    def input_warnings(self) -> List[str]:
        """Warnings about the input (``FILE:LINE: KEY: ...``), e.g. a gland fill above the
        guidance."""
        return self._inner.input_warnings

    def run(self, fidelity: Optional[str] = None) -> RunResult:
        """The seal's life (``sealsim run``), at ``fidelity`` if given (``exact``,
        ``critical-junction``, ``effective-medium``, ``rule-of-thumb``, ``numerical``)."""
        history, summary = self._inner._run(fidelity)
        return RunResult(self, history, json.loads(summary))

    def leak(
        self,
        pressures: Optional[Sequence[Union[float, str]]] = None,
        fidelity: Optional[str] = None,
    ) -> Any:
        """The leak at each nominal pressure (``sealsim leak``): Pa floats or strings with
        units (``"2 bar"``); None for the scenario's own. The table has the columns of
        ``sealsim leak``'s CSV; its validity findings are ``.attrs["warnings"]`` of a
        DataFrame."""
        columns, findings = self._inner._leak(None if pressures is None else list(pressures), fidelity)
        table = _table(columns)
        if hasattr(table, "attrs"):
            table.attrs["warnings"] = json.loads(findings)
        return table

    def __repr__(self) -> str:
        return f"Scenario({self.name!r}, path={self.path!r})"


def compare(scenario: Scenario, compounds: Iterable[str], fidelity: Optional[str] = None) -> Any:
    """The scenario run with each compound (library ids such as ``"nbr-70"`` or material-file
    paths) in place of its own (``sealsim compare``): one row per compound with the columns of
    its CSV. Each compound's findings are ``.attrs["warnings"]`` of a DataFrame."""
    columns, findings = _sealsim._compare(scenario._inner, list(compounds), fidelity)
    table = _table(columns)
    if hasattr(table, "attrs"):
        table.attrs["warnings"] = json.loads(findings)
    return table


def study(source: Union[PathLike, str], threads: Optional[int] = None) -> StudyResult:
    """Runs a tolerance study (``sealsim study``): ``source`` is a study file's path or its
    TOML text (a text's ``base`` is relative to the working directory). ``threads``: None for
    all cores."""
    columns, summary = _sealsim._study(os.fspath(source), threads)
    return StudyResult(_table(columns), json.loads(summary))


def materials() -> Any:
    """The material library: id, name, status, E0_Pa, E_inf_Pa, glass_transition_K,
    low_temperature_limit_K (NaN where a compound has none)."""
    return _table(_sealsim._materials())


def contact(
    pressures: Sequence[Union[float, str]],
    scenario: Optional[Scenario] = None,
    *,
    youngs_modulus: Optional[float] = None,
    poisson_ratio: float = 0.5,
    rms_roughness: Optional[float] = None,
    hurst_exponent: Optional[float] = None,
    q0: Optional[float] = None,
    q1: Optional[float] = None,
) -> Any:
    """Persson's contact mechanics on its own (docs/model.md §2): at each nominal pressure (Pa
    floats or strings with units) the reduced pressure P0/E*, the relative contact area
    ``area_fraction`` A/A0 at full magnification (q1), the mean gap ``mean_gap_m`` ū(ζ = 1) of
    the interface, and the
    critical junction ``zeta_c``, ``u_c_m``, ``lambda_c_m`` (NaN where sealed).

    The surface and the rubber are ``scenario``'s (its spectrum, relaxed modulus and ``[model]``
    settings), or a self-affine surface (``rms_roughness`` m, ``hurst_exponent``, ``q0``,
    ``q1`` 1/m) on an elastic rubber (``youngs_modulus`` Pa, ``poisson_ratio``)."""
    return _table(
        _sealsim._contact(
            list(pressures),
            None if scenario is None else scenario._inner,
            youngs_modulus,
            poisson_ratio,
            rms_roughness,
            hurst_exponent,
            q0,
            q1,
        )
    )
