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

Every call does its work on a worker thread with the GIL released: Ctrl-C
(``KeyboardInterrupt``) stops the wait within 50 ms, whatever the call (the abandoned
computation finishes in the background and its result is dropped), and ``progress=`` reports
studies, comparisons and the numerical level. Invalid input raises :class:`ScenarioError` (a
``ValueError``) with the command line's ``file:line: key: message``, an argument of the wrong
type ``TypeError``, a number out of range ``ValueError``, a missing file ``FileNotFoundError``;
a bug in sealsim (a panic) raises :class:`InternalError` (a ``RuntimeError``), never a crash
nor pyo3's ``PanicException`` (python/tests/test_fuzz.py holds the public API to these).

The warnings the command line prints on stderr are issued with :func:`warnings.warn`: a
validity finding of a run or leak table as a :class:`ValidityWarning`, a scenario's input
warning as an :class:`InputWarning`, both :class:`SealsimWarning` (a ``UserWarning``) with
``.code`` (``"W001"``, expanded by ``sealsim explain W001`` and the guide's warnings page) and
``.record`` (the JSON record). The message starts with the code, so one code is silenced with
``warnings.filterwarnings("ignore", message="W001")``, a kind with ``category=ValidityWarning``.
"""

from __future__ import annotations

import json
import os
import warnings
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
    "SealsimWarning",
    "ValidityWarning",
    "InputWarning",
    "compare",
    "study",
    "gland",
    "GlandDesign",
    "materials",
    "contact",
    "ContactResult",
    "quantity",
    "fit_prony",
    "FitResult",
    "surface",
    "SurfaceResult",
    "__version__",
]

PathLike = Union[str, "os.PathLike[str]"]


class SealsimWarning(UserWarning):
    """A warning of sealsim's (the line the command line prints on stderr): ``.code`` is its
    stable code (``"W001"``; ``sealsim explain W001`` and the guide's warnings page explain it),
    ``.record`` its JSON record. The message starts with the code, so
    ``warnings.filterwarnings("ignore", message="W001")`` silences that code alone."""

    def __init__(self, message: str, code: str = "", record: Optional[Dict[str, Any]] = None):
        super().__init__(message)
        self.code = code
        self.record: Dict[str, Any] = dict(record or {})


class ValidityWarning(SealsimWarning):
    """A validity limit of the model crossed by a run or a leak table (docs/model.md §9): the
    result is still computed; the warning says how far to trust it. ``.record`` is the
    summary's record (``id``, ``quantity``, ``value``, ``bound``, ``worst_time_s``, …)."""


class InputWarning(SealsimWarning):
    """A scenario input accepted but questionable (``file:line: key: …``: a gland fill above
    the guidance, ageing constants measured in another medium, …)."""


def _warn(category: type, records: Iterable[Dict[str, Any]], stacklevel: int) -> None:
    """Issues one warning of ``category`` per record that has a code (notes excluded)."""
    for record in records:
        code = record.get("code")
        if not code or record.get("kind") == "note":
            continue
        text = f"{code} {record.get('id', '')}: {record.get('message', '')}"
        warnings.warn(category(text, code, record), stacklevel=stacklevel + 1)


def _warn_slip(message: str, stacklevel: int) -> None:
    """A height map's or trace's likely unit slip (docs/model.md §2.4) as the scenario's W044."""
    record = {"code": "W044", "id": "height_unit_slip", "kind": "warning", "message": message}
    warnings.warn(InputWarning(f"W044 height_unit_slip: {message}", "W044", record),
                  stacklevel=stacklevel + 1)


def _table(columns: Mapping[str, Any]) -> Any:
    """Columns (name -> the bytes of native f64s, a list of floats, or a list of strings) as a
    DataFrame, or a dict of arrays."""
    arrays = {}
    for name, values in columns.items():
        if isinstance(values, bytes):
            arrays[name] = numpy.frombuffer(values, dtype=numpy.float64)
        elif values and isinstance(values[0], str):
            arrays[name] = numpy.array(values, dtype=object)
        elif values and isinstance(values[0], bool):
            arrays[name] = numpy.array(values, dtype=bool)
        else:
            arrays[name] = numpy.array(values, dtype=numpy.float64)
    try:
        import pandas
    except ImportError:
        # frombuffer's arrays are read-only views of the bytes: give the caller its own
        return {k: (v.copy() if not v.flags.writeable else v) for k, v in arrays.items()}
    return pandas.DataFrame(arrays)


class _TextBar:
    """A plain text progress bar on standard error: ``what [=====     ] done/total``."""

    def __init__(self, what: str):
        self.what = what
        self.width = 30

    def __call__(self, done: int, total: int) -> None:
        import sys

        filled = self.width * done // total if total else 0
        bar = "=" * filled + " " * (self.width - filled)
        end = "\n" if done >= total else ""
        sys.stderr.write(f"\r{self.what} [{bar}] {done}/{total}{end}")
        sys.stderr.flush()


def _progress(progress: Any, what: str) -> Any:
    """The ``progress`` argument as a callable ``(done, total)``: None or False for none, True
    for a text bar on standard error, a tqdm-style bar (an object with ``update``: its
    ``total`` is set and it is advanced by the units done), or any callable taking
    ``(done, total)``."""
    if progress is None or progress is False:
        return None
    if progress is True:
        return _TextBar(what)
    if hasattr(progress, "update"):
        bar = progress
        state = {"done": 0}

        def advance(done: int, total: int) -> None:
            if getattr(bar, "total", None) != total:
                bar.total = total
                if hasattr(bar, "refresh"):
                    bar.refresh()
            bar.update(done - state["done"])
            state["done"] = done

        return advance
    if callable(progress):
        return progress
    raise TypeError(
        f"progress must be None, True, a tqdm-style bar or a callable (done, total), "
        f"not {type(progress).__name__}"
    )


class RunResult:
    """The life of a scenario's seal (``sealsim run``; docs/model.md §1 chains the model).

    At each output time the relaxed modulus E(t_r) = E∞ + Σ E_i exp(−t_r/τ_i) in reduced time
    t_r = ∫ dt/a_T(T) (WLF or Arrhenius, §5), aged by the two-network model (§6.5), gives the
    sealing pressure of the gland (§6); Persson's contact at that pressure (§2) gives the
    critical constriction u_c, and the leak rate Q̇ = (L_y/L_x) α u_c³ ΔP/(12η) (Persson &
    Yang 2008, eq. 3; §3.1). The failure time is where a criterion of ``[failure]`` is first
    crossed (§8), the state (sealed, leaking, pressure_held, lift_off) decided by the
    tolerances of §8.1.

    Attributes:
        history: one row per output time (the first is the installation, t = 0) with the
            columns of the history CSV (``time_s``, ``temperature_K``, ...,
            ``leak_rate_m3_per_s``, ``state``, ...); a blank cell of the CSV is NaN.
        summary: the ``--summary`` JSON as a dict (its ``input_warnings``: the scenario's
            input warnings and notes with their codes).
        time_to_failure: seconds, or None when the seal survives.
        failure_mode: ``leak_rate``, ``leaked_volume``, ``retained_force``, ``lift_off``, ...,
            ``low_temperature``, or ``none``.
        verdict: ``fails``, ``open`` or ``survives``; ``verdict_text`` the sentence.
        warnings: the validity findings, a list of dicts (as in the summary JSON, each with
            its ``code``); :meth:`Scenario.run` also issues each as a :class:`ValidityWarning`.
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

    def plot(self, ax: Any = None, leak_floor: Union[float, str, None] = None) -> Any:
        """A matplotlib figure of the leak rate, the sealing force and the temperature
        against time (three stacked axes; the failure marked). Needs matplotlib.

        The leak axis is clipped at the leak floor as ``sealsim run``'s chart clips it
        (docs/model.md §15.2): ``leak_floor`` as ``--leak-floor`` takes it (m³/s, or a string
        with units: ``"1e-15 m^3/s"``, a gas's ``"1e-9 mbar*L/s"``), default one molecule a
        second. A rate below the floor, zero included, is drawn on the floor, never below; the
        floor is a grey dashed line, and a run sealed throughout is labelled "sealed (below
        floor)"."""
        import matplotlib.pyplot as plt

        floor = self.scenario._inner._leak_floor(leak_floor)
        h = self.history
        t = numpy.asarray(h["time_s"], dtype=float)
        duration = t[-1] if len(t) else 0.0
        year, day = 365.25 * 86400.0, 86400.0
        scale, unit = (year, "years") if duration >= 2 * year else (day, "days")
        fig, axes = plt.subplots(3, 1, sharex=True, figsize=(7, 7))
        q = numpy.asarray(h["leak_rate_m3_per_s"], dtype=float)
        # as life_chart.rs: below the floor (0 included, NaN too) reads on the floor
        q_drawn = numpy.where(q >= floor, q, floor)
        sealed = bool(numpy.all(q_drawn <= floor))
        what = (
            "the floor given"
            if leak_floor is not None
            else "one molecule a second"
        )
        label = f"sealed (below floor {floor:.2g} m³/s)" if sealed else "leak rate"
        axes[0].semilogy(t / scale, q_drawn, label=label)
        axes[0].axhline(
            floor,
            color="grey",
            linestyle="--",
            linewidth=1,
            label=f"floor {floor:.2g} m³/s ({what}): below it reads sealed",
        )
        axes[0].set_ylim(bottom=10 ** numpy.floor(numpy.log10(floor)))
        axes[0].set_ylabel("leak rate [m³/s]")
        axes[0].legend(fontsize="x-small", loc="upper left")
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

    def advise(
        self,
        life: Union[str, float] = "10y",
        threads: Optional[int] = None,
        max_runs: Optional[int] = None,
        progress: Any = None,
    ) -> Dict[str, Any]:
        """What would make it pass (``sealsim advise``, docs/model.md §16): the sensitivity
        of the verdict to each design variable and the smallest changes (alone and in pairs)
        that meet ``life`` (a time with its unit, ``"10y"``, or seconds), each verified by a
        full run. Returns the ``--json`` document as a dict (SI): ``base``, ``proposals`` (each
        with its ``changes`` as scenario keys and TOML values, ``passes``, ``life_s``,
        ``margin``, ``runs``), ``sensitivity``. Apply a proposal with
        ``scenario.replace({c["key"]: tomllib.loads("v = " + c["value"])["v"] ...})``.
        ``threads``: worker threads (default all cores; the same advice on any number);
        ``max_runs``: the bound on the life runs (default 200)."""
        text = self._inner._advise(life, threads, max_runs, _progress(progress, "life runs"))
        return json.loads(text)

    def run(self, fidelity: Optional[str] = None, progress: Any = None) -> RunResult:
        """The seal's life (``sealsim run``), at ``fidelity`` if given (``exact``,
        ``critical-junction``, ``effective-medium``, ``rule-of-thumb``, ``numerical``).
        ``progress``: True for a text bar, a tqdm bar or a callable ``(done, total)``, told
        of the numerical level's tabulated pressures (the other levels report nothing)."""
        history, summary = self._inner._run(fidelity, _progress(progress, "numerical level"))
        result = RunResult(self, history, json.loads(summary))
        # the command line's stderr: the input warnings, then the run's findings
        _warn(InputWarning, result.summary.get("input_warnings", []), stacklevel=2)
        _warn(ValidityWarning, result.warnings, stacklevel=2)
        return result

    def leak(
        self,
        contact_pressures: Optional[Sequence[Union[float, str]]] = None,
        fidelity: Optional[str] = None,
        progress: Any = None,
        *,
        pressure_differences: Optional[Sequence[Union[float, str]]] = None,
        pressures: Optional[Sequence[Union[float, str]]] = None,
    ) -> Any:
        """The leak of the seal (``sealsim leak``), at one of two kinds of pressure (Pa floats or
        strings with units, ``"2 bar"``):

        * ``pressure_differences``: the FLUID pressure difference ΔP across the seal ("at 50 and
          210 bar of oil"): one row per ΔP, the installed seal at its own squeeze evaluated with
          that ΔP (an O-ring: the energisation k_e ΔP, its profile's strips, lift-off by the
          fluid pressure), the first row of :meth:`run` with ``fluid.pressure_difference`` set
          to ΔP; columns ``pressure_difference_Pa``, ``extrudes`` (``yes``/``no`` at
          installation, blank without a gland), ``contact_pressure_Pa``, then as below
          (``sealsim leak --pressure-differences``).
        * ``contact_pressures`` (``pressures`` is its old name): the CONTACT pressure, a flat
          seal's nominal pressure P0 or an O-ring's peak contact pressure (``sealsim leak
          --contact-pressures``); for an O-ring a ``UserWarning`` says so. None (and no
          ``pressure_differences``): the scenario's own state.

        At nominal pressure P0 the critical junction ζc is where the contact area A(ζc)/A0 falls
        to the percolation threshold a_c = 0.4 (``[model] percolation_threshold``); its gap u_c
        = u1(ζc) gives Q̇ = (L_y/L_x) α u_c³ ΔP/(12η) (Persson & Yang 2008, eqs. 1–3;
        docs/model.md §3). The table has the columns of ``sealsim leak``'s CSV; its validity
        findings are ``.attrs["warnings"]`` of a DataFrame, the O-ring's note
        ``.attrs["note"]``. ``progress`` as for :meth:`run`."""
        if pressures is not None:
            if contact_pressures is not None:
                raise TypeError("leak: give contact_pressures or its old name pressures, not both")
            contact_pressures = pressures
        columns, findings, note = self._inner._leak(
            None if contact_pressures is None else list(contact_pressures),
            fidelity,
            _progress(progress, "numerical level"),
            None if pressure_differences is None else list(pressure_differences),
        )
        records = json.loads(findings)
        _warn(ValidityWarning, records, stacklevel=2)
        if note is not None and contact_pressures is not None:
            warnings.warn(note, UserWarning, stacklevel=2)
        table = _table(columns)
        if hasattr(table, "attrs"):
            table.attrs["warnings"] = records
            table.attrs["note"] = note
        return table

    def __repr__(self) -> str:
        return f"Scenario({self.name!r}, path={self.path!r})"


def compare(
    scenario: Scenario,
    compounds: Iterable[str],
    fidelity: Optional[str] = None,
    progress: Any = None,
    raw: bool = False,
) -> Any:
    """The scenario run with each compound (library ids such as ``"nbr-70"`` or material-file
    paths) in place of its own (``sealsim compare``): one row per compound with the columns of
    its CSV, ranked as the CLI ranks them: the compounds rated A or B for the run's medium
    first, by life, then the others with their ``rank_basis`` (``raw=True``: by life alone,
    as ``--all``). Each compound's findings are ``.attrs["warnings"]`` of a DataFrame and the
    headline (it names only a compound rated A/B) is ``.attrs["headline"]``. ``progress`` as
    for :meth:`Scenario.run`."""
    if not isinstance(scenario, Scenario):
        raise TypeError(f"compare: scenario must be a sealsim.Scenario, got {type(scenario).__name__}")
    columns, findings, headline = _sealsim._compare(
        scenario._inner,
        list(compounds),
        fidelity,
        _progress(progress, "numerical level"),
        raw,
    )
    table = _table(columns)
    if hasattr(table, "attrs"):
        table.attrs["warnings"] = json.loads(findings)
        table.attrs["headline"] = headline
    return table


def study(
    source: Union[PathLike, str], threads: Optional[int] = None, progress: Any = None
) -> StudyResult:
    """Runs a tolerance study (``sealsim study``): ``source`` is a study file's path or its
    TOML text (a text's ``base`` is relative to the working directory). ``threads``: None for
    all cores. ``progress``: True for a text bar on standard error, a tqdm bar
    (``progress=tqdm.tqdm()``), or a callable ``(cases_done, cases)``, called at most every
    50 ms and once at the end."""
    columns, summary = _sealsim._study(os.fspath(source), threads, _progress(progress, "cases"))
    return StudyResult(_table(columns), json.loads(summary))


class GlandDesign:
    """A gland designed by :func:`gland` (``sealsim gland``): ``summary`` is the command's
    ``--json`` (the table row and its source, the housing with its ISO 286 fits, the
    conditions and the stack-up with each quantity's limit and source), ``stack_up`` the
    stack-up as a table (one row per quantity: squeeze, stretch, od_compression, fill,
    clearance; nominal, assembly_min/max at 23 °C, service_min/max over the temperatures, the
    limit and whether it holds), ``toml`` the runnable scenario of ``-o``."""

    def __init__(self, summary: Dict[str, Any], toml: str):
        self.summary = summary
        self.toml = toml

    @property
    def stack_up(self) -> Any:
        """The stack-up, one row per quantity (fractions for squeeze, stretch, OD compression
        and fill; the clearance in the row's ``unit``): nominal, the worst case at 23 °C, the
        worst case over the service temperatures, the limit it is checked against and whether
        it holds."""
        rows = self.summary["stack_up"]
        names = [
            "quantity",
            "unit",
            "nominal",
            "assembly_min",
            "assembly_max",
            "service_min",
            "service_max",
            "limit",
            "ok",
        ]
        return _table({n: [r[n] for r in rows] for n in names})

    @property
    def backup_rings_needed(self) -> int:
        """Back-up rings the extrusion chart asks for at the pressure and the largest gap."""
        return int(self.summary["backup_rings_needed"])

    def scenario(self) -> "Scenario":
        """The designed gland in the service's o-ring template, ready to run."""
        return Scenario.from_toml(self.toml)

    def __repr__(self) -> str:
        s = self.summary
        return "GlandDesign({} {} gland, {} back-up ring(s))".format(
            s["size"], s["service"], s["backup_rings"]
        )


def gland(
    size: str,
    service: str,
    dynamic: bool = False,
    pressure: Optional[str] = None,
    backup_rings: int = 0,
    bore: Union[str, float, None] = None,
    rod: Union[str, float, None] = None,
    fit: str = "H8/f7",
    temperature: Optional[Sequence[Union[str, float]]] = None,
    pressure_difference: Union[str, float, None] = None,
    material: str = "nbr-70",
    housing: str = "steel",
) -> GlandDesign:
    """The recommended gland of an AS568 ring (``"AS568-214"``) for a ``service`` (``"face"``,
    ``"piston"``, ``"rod"``), as ``sealsim gland`` designs it: the handbook table's row, the
    ISO 286 ``fit`` of bore and piston (or housing and rod), and the tolerance stack-up over
    ``temperature=(min, max)`` (strings with units or kelvin). ``pressure``: a face gland's
    pressure side (``"inside"``/``"outside"``); ``bore``/``rod``: the piston gland's bore or
    the rod gland's rod (strings with units or metres; default the ring's nominal OD/ID);
    ``pressure_difference`` (a string with units or Pa) sets the back-up-ring advice and the
    scenario's pressure. Invalid input raises :class:`ScenarioError` with the command's
    message (an impossible fit names the nearest size)."""
    if temperature is not None:
        lo, hi = temperature
        temperature = (lo, hi)
    summary, toml = _sealsim._gland(
        size,
        service,
        dynamic,
        pressure,
        backup_rings,
        bore,
        rod,
        fit,
        temperature,
        pressure_difference,
        material,
        housing,
    )
    return GlandDesign(json.loads(summary), toml)


def materials() -> Any:
    """The material library: id, name, status, E0_Pa, E_inf_Pa, glass_transition_K,
    low_temperature_limit_K (NaN where a compound has none)."""
    return _table(_sealsim._materials())


class ContactResult:
    """The numerical level of :func:`contact`: boundary-element contact, percolation and
    Reynolds flow at each nominal pressure.

    Attributes:
        table: one row per pressure: ``nominal_pressure_Pa``, ``reduced_pressure`` (P0/E*),
            ``approach_m`` (the rigid-body approach δ = max h − s), ``area_fraction`` (A/A0, the
            fraction of pixels with a positive contact pressure),
            ``mean_gap_m`` (ū, the mean of the gap field), ``percolates`` (bool: the non-contact
            region connects the inlet to the outlet in some realisation), ``percolating_fraction``
            (of the realisations), ``conductance_m3_per_Pa_s`` (the Reynolds conductance σ_eff
            at ``viscosity``) and ``u_c_m`` (the effective gap (12 η σ_eff)^(1/3), NaN when
            sealed). With several realisations every column is the ensemble mean, as in
            ``sealsim leak``.
        fields: one dict per pressure: ``gap_m`` and ``pressure_Pa`` (the contact pressure) and
            ``heights_m`` (the surface the solver saw), float64 arrays of shape ``(n, n)`` for a
            height map — row ``iy``, column ``ix`` along the flow, as the map — and
            ``(realisations, n, n)`` for random realisations; and the per-realisation
            ``area_fraction``, ``mean_gap_m``, ``percolates``, ``conductance_m3_per_Pa_s`` and
            ``seed`` (None for a height map) as 1-D arrays, with ``approach_m`` (δ),
            ``mean_pressure_Pa`` and ``iterations`` (of the boundary elements, summed over the
            load search under displacement control).
        n: grid points per side; pixel_size: their spacing (m); realisations: surfaces per
            pressure; effective_modulus: E* (Pa); viscosity: η (Pa·s) of the conductance.
        boundary: ``"periodic"`` or ``"free"``; control: ``"pressure"`` or ``"displacement"``;
            tolerance: the boundary elements' tolerance; flow: None, or why the percolation and
            flow columns are missing (a free patch).
    """

    def __init__(self, raw: Mapping[str, Any]):
        self.n: int = raw["n"]
        self.pixel_size: float = raw["pixel_size"]
        self.realisations: int = raw["realisations"]
        self.effective_modulus: float = raw["effective_modulus"]
        self.viscosity: float = raw["viscosity"]
        self.boundary: str = raw["boundary"]
        self.control: str = raw["control"]
        self.tolerance: float = raw["tolerance"]
        self.flow: Optional[str] = raw["flow"]
        self.table: Any = _table(raw["table"])
        # a height map is one surface (2-D fields); random realisations stack (3-D), even one
        fields = raw["fields"]
        single = not fields or not fields[0]["seed"] or fields[0]["seed"][0] is None
        shape = (self.n, self.n) if single else (self.realisations, self.n, self.n)
        self.fields: List[Dict[str, Any]] = []
        for f in fields:
            entry: Dict[str, Any] = {}
            for name in ("heights_m", "gap_m", "pressure_Pa"):
                entry[name] = numpy.frombuffer(f[name], dtype=numpy.float64).reshape(shape).copy()
            for name in ("area_fraction", "mean_gap_m", "approach_m", "mean_pressure_Pa", "conductance_m3_per_Pa_s"):
                if name in f:
                    entry[name] = numpy.array(f[name], dtype=numpy.float64)
            if "percolates" in f:
                entry["percolates"] = numpy.array(f["percolates"], dtype=bool)
            entry["iterations"] = numpy.array(f["iterations"], dtype=numpy.int64)
            entry["seed"] = list(f["seed"])
            self.fields.append(entry)

    def __repr__(self) -> str:
        return (
            f"ContactResult({len(self.fields)} pressures, {self.realisations} realisation(s) of "
            f"{self.n}² pixels of {self.pixel_size:.4g} m, {self.boundary})"
        )


def contact(
    pressures: Union[Sequence[Union[float, str]], float, str, None] = None,
    scenario: Optional[Scenario] = None,
    *,
    displacement: Union[Sequence[Union[float, str]], float, str, None] = None,
    boundary: str = "periodic",
    tolerance: Optional[float] = None,
    height_map: Any = None,
    pixel_size: Union[float, str, None] = None,
    height_unit: Optional[str] = None,
    youngs_modulus: Optional[float] = None,
    poisson_ratio: float = 0.5,
    rms_roughness: Optional[float] = None,
    hurst_exponent: Optional[float] = None,
    q0: Optional[float] = None,
    q1: Optional[float] = None,
    fidelity: Optional[str] = None,
    viscosity: Optional[float] = None,
) -> Any:
    """The contact problem on its own (docs/model.md §2, §3.5) at each nominal pressure (Pa
    floats or strings with units).

    The rubber is ``scenario``'s (its relaxed E* and ``[model]`` settings) or an elastic
    half-space (``youngs_modulus`` Pa, ``poisson_ratio``). The surface is ``height_map`` (a 2-D
    array of heights, row ``iy``, column ``ix`` along the flow, in m or in ``height_unit``
    (``"um"``), with ``pixel_size`` in m or a string with its unit, ``"0.5 um"``, read by the
    scenario files' parser; a non-square map runs on its centred even square, as a
    scenario's), else ``scenario``'s, else a self-affine spectrum (``rms_roughness`` m,
    ``hurst_exponent``, ``q0``, ``q1`` 1/m). Heights implausible for their pixel (rms slope
    above 10 at the pixel, or rms of 1 mm or more: docs/model.md §2.4) raise an :class:`InputWarning` (W044, a ``UserWarning``)
    naming the likely unit slip ("heights look like µm read as m").
    Keywords that would be ignored (a modulus or spectrum beside a scenario, a spectrum beside
    a height map) raise :class:`ScenarioError`.

    ``fidelity``: None (the numerical level for a height map or a scenario at that level, else
    Persson's theory by quadrature, ``exact``), ``"numerical"``, or an analytic level
    (``exact``, ``critical-junction``, ``effective-medium``, ``rule-of-thumb``).

    Analytic levels return a table: ``nominal_pressure_Pa``, ``reduced_pressure`` P0/E*, the
    relative contact area ``area_fraction`` A/A0 at full magnification (q1), the mean gap
    ``mean_gap_m`` ū(ζ = 1) of the interface (both Persson's theory at every analytic level:
    ``sealsim leak``'s columns of the same names), and the level's critical junction
    ``zeta_c``, ``u_c_m``, ``lambda_c_m`` (NaN where sealed). A height map at an analytic level
    uses its spectrum estimate, as a scenario does.

    The numerical level returns a :class:`ContactResult` (its ``table`` and the ``fields``):
    the solver, settings, threads and tolerances of ``sealsim leak --fidelity numerical`` and of
    the life run (a scenario's ``[numerical]``, else the defaults), so a height map gives the
    CLI's numbers bit for bit. ``viscosity`` (Pa·s) scales only ``conductance_m3_per_Pa_s``:
    default the scenario's fluid's, else 1e-3 Pa·s (water near 20 °C). The table adds
    ``approach_m``, the rigid-body approach δ = max h − s (the overlap of the undeformed
    surfaces: Hertz's indentation for a single sphere; for a periodic cell max h − (ū + ⟨h⟩)).

    At the numerical level only (an analytic level refuses them):

    * ``displacement``: rigid-body approaches δ (m, floats or strings with a unit, ``"1 um"``)
      instead of ``pressures`` — give exactly one of the two. The mean pressure each needs is
      the table's ``nominal_pressure_Pa`` (the ensemble mean; each realisation's in the fields'
      ``mean_pressure_Pa``). δ ≤ 0 (the body at or above the highest point) gives no contact and
      zero pressure. A periodic cell's δ must stay below max h − ⟨h⟩ (full contact):
      :class:`ScenarioError` at or beyond it. Found by a secant search on the load-controlled
      solver, to the same ``tolerance`` (|δ − target| ≤ tolerance × rms height).
    * ``boundary``: ``"periodic"`` (default: the map is one cell of a periodic surface, the
      numerical level of ``sealsim leak``) or ``"free"`` (an isolated patch on an infinite
      half-space, unloaded outside it: Love's pixel kernel, zero-padded FFT — single asperities,
      indenters, measured patches that are not periodic). A free patch has no percolation and
      no flow columns (the Reynolds cell is periodic); the result's ``flow`` says so.
    * ``tolerance``: the boundary elements' convergence threshold in (0, 1) (default 1e-8): the
      relative pressure change per iteration and the rms gap misfit on the contact set relative
      to the rms height. A looser value takes fewer iterations (the fields' ``iterations``)."""
    spectrum = {"rms_roughness": rms_roughness, "hurst_exponent": hurst_exponent, "q0": q0, "q1": q1}
    given = [k for k, v in spectrum.items() if v is not None]
    if scenario is not None:
        rubber = ["youngs_modulus"] * (youngs_modulus is not None)
        rubber += ["poisson_ratio"] * (poisson_ratio != 0.5)
        if rubber or given:
            raise ScenarioError(
                f"contact: {', '.join(rubber + given)} would be ignored: the rubber and the surface "
                "are the scenario's; give either a scenario or the elastic half-space and its surface"
            )
    if height_map is not None and given:
        raise ScenarioError(
            f"contact: {', '.join(given)} would be ignored: the surface is the height map; give "
            "either a height_map or a spectrum"
        )
    shape = None
    heights = None
    if height_map is not None:
        array = numpy.asarray(height_map)
        if array.ndim != 2:
            raise ScenarioError(
                f"contact: height_map must be a 2-D array of heights (m), got {array.ndim} dimension(s)"
            )
        if not numpy.issubdtype(array.dtype, numpy.number) or numpy.iscomplexobj(array):
            raise ScenarioError(f"contact: height_map must hold real numbers, got {array.dtype}")
        # the size refused before the heights are copied (a map above 8192² pixels, D6)
        _sealsim._height_map_shape(array.shape)
        array = numpy.ascontiguousarray(array, dtype=numpy.float64)
        shape = array.shape
        heights = array.tobytes()
    if scenario is not None and not isinstance(scenario, Scenario):
        raise TypeError(f"contact: scenario must be a sealsim.Scenario, got {type(scenario).__name__}")
    def listed(values: Any) -> Optional[List[Any]]:
        # one value or a sequence of them
        if values is None:
            return None
        if isinstance(values, (str, bytes, int, float)):
            return [values]
        return list(values)

    raw = _sealsim._contact(
        listed(pressures),
        None if scenario is None else scenario._inner,
        youngs_modulus,
        poisson_ratio,
        rms_roughness,
        hurst_exponent,
        q0,
        q1,
        heights,
        shape,
        pixel_size,
        fidelity,
        viscosity,
        height_unit,
        listed(displacement),
        tolerance,
        boundary,
    )
    if raw.get("height_warning"):
        _warn_slip(raw["height_warning"], stacklevel=2)
    if raw["level"] == "numerical":
        return ContactResult(raw)
    return _table(raw["table"])


def _is_panic(error: BaseException) -> bool:
    """Whether ``error`` is pyo3's ``PanicException`` (a Rust panic that reached Python outside
    the extension's own ``catch_unwind``: a ``BaseException`` that ``except Exception`` misses)."""
    kind = type(error)
    return kind.__name__ == "PanicException" and kind.__module__ == "pyo3_runtime"


def _documented_errors(name: str, fn: Any) -> Any:
    """``fn`` raising only the documented exception types: an integer out of a native type's
    range (``threads=-1``, ``10**400`` as a float) raises ``ValueError`` with Python's words,
    not ``OverflowError`` (an ``ArithmeticError`` that ``except ValueError`` misses); a Rust
    panic the extension did not catch itself raises :class:`InternalError`, not pyo3's
    ``PanicException``."""
    import functools

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return fn(*args, **kwargs)
        except OverflowError as e:
            raise ValueError(f"{name}: a number out of range: {e}") from e
        except BaseException as e:  # noqa: BLE001 — only a panic is replaced, the rest re-raised
            if _is_panic(e):
                raise InternalError(f"{name}: sealsim panicked: {e}") from e
            raise

    return wrapper


for _name in ("compare", "study", "gland", "materials", "contact", "fit_prony", "surface", "quantity"):
    globals()[_name] = _documented_errors(_name, globals()[_name])
for _name in ("advise", "run", "leak", "replace"):
    setattr(Scenario, _name, _documented_errors(f"Scenario.{_name}", getattr(Scenario, _name)))
for _cls, _name in ((RunResult, "plot"), (FitResult, "relaxation"), (FitResult, "write"),
                    (GlandDesign, "scenario")):
    _full = f"{_cls.__name__}.{_name}"
    setattr(_cls, _name, _documented_errors(_full, getattr(_cls, _name)))
del _cls, _full
for _name in ("from_file", "from_toml"):
    setattr(
        Scenario,
        _name,
        classmethod(_documented_errors(f"Scenario.{_name}", getattr(Scenario, _name).__func__)),
    )
del _name
