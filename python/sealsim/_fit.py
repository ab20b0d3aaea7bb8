"""Lab data and surfaces: ``fit_prony`` (``sealsim fit-prony``) and ``surface``
(``sealsim surface``), through the library's workflows.

Columns and arrays are handed to the command line's own parsers as CSV text written with
shortest round-trip floats (``repr``), so every value crosses exactly and a bad value gets the
command line's message (:class:`ScenarioError`, a ``ValueError``).
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence, Union

import numpy

from . import _sealsim

PathLike = Union[str, "os.PathLike[str]"]

_PATHS = (str, os.PathLike)


def _cell(value: Any) -> str:
    """A CSV cell: a number as its shortest round-trip text, anything else as text."""
    if isinstance(value, (bool, numpy.bool_)):
        return str(value)
    if isinstance(value, (int, float, numpy.integer, numpy.floating)):
        return repr(float(value))
    return str(value)


def _columns_csv(data: Any, units: Optional[Mapping[str, str]]) -> str:
    """Columns (a DataFrame or a mapping of name -> values) as a fit data file: the header
    row, the units row (``units`` or SI: s, Pa, N, 1, K, Hz, rad/s by the column's name), then
    one row per point."""
    if not (hasattr(data, "columns") or isinstance(data, Mapping)):
        raise TypeError(
            "fit_prony: data must be a data file's path, a DataFrame or a dict of column name "
            f"-> values, got {type(data).__name__}"
        )
    names = [str(n) for n in (data.columns if hasattr(data, "columns") else data.keys())]
    given = dict(units or {})
    unit_row = [given.get(n) or _sealsim._fit_column_unit(n) or "?" for n in names]
    columns = [list(data[n]) for n in names]
    lengths = {len(c) for c in columns}
    if len(lengths) > 1:
        raise ValueError(f"fit_prony: the columns have different lengths {sorted(lengths)}")
    rows = [",".join(_cell(c[i]) for c in columns) for i in range(lengths.pop() if lengths else 0)]
    return "\n".join([",".join(names), ",".join(unit_row), *rows]) + "\n"


class FitResult:
    """A Prony series fitted to lab data (``sealsim fit-prony``).

    Attributes:
        material_toml: the material file's text, byte for byte what ``fit-prony -o`` writes.
        terms: the Prony terms in SI, columns ``tau_s`` and ``E_i_Pa`` (a table).
        E_inf: the long-term modulus E∞ [Pa]; ``E0`` the instantaneous E∞ + Σ E_i [Pa].
        summary: the lines ``fit-prony`` prints on standard error (fit quality, how forces
            became moduli, what ``like`` copied, notes and warnings).
        warnings: the summary's ``warning:`` lines.
        name, source: the material's name and the data as named in the provenance.
        points, rms_relative_residual, max_relative_residual: the fit's data and residuals;
        window: the time window (s) the data cover.
    """

    def __init__(self, raw: Dict[str, Any]):
        from . import _table

        self.material_toml: str = raw["material_toml"]
        self.summary: List[str] = raw["summary"].splitlines()
        self.warnings: List[str] = [l for l in self.summary if l.startswith("warning:")]
        self.name: str = raw["name"]
        self.source: str = raw["source"]
        self._tau = numpy.array(raw["tau_s"], dtype=float)
        self._e = numpy.array(raw["E_i_Pa"], dtype=float)
        self.terms = _table({"tau_s": raw["tau_s"], "E_i_Pa": raw["E_i_Pa"]})
        self.E_inf: float = raw["E_inf_Pa"]
        self.E0: float = raw["E0_Pa"]
        self.points: int = raw["points"]
        self.rms_relative_residual: float = raw["rms_relative_residual"]
        self.max_relative_residual: float = raw["max_relative_residual"]
        self.window = tuple(raw["window_s"])

    def relaxation(self, t: Any) -> Any:
        """E(t) = E∞ + Σ E_i exp(−t/τ_i) [Pa] at times ``t`` [s] (at the data's temperature,
        or in reduced time for a master curve). A negative or NaN time raises ``ValueError``
        (the relaxation starts at the load; exp(−t/τ) of t = −1e308 s was infinite)."""
        t = numpy.asarray(t, dtype=float)
        bad = numpy.isnan(t) | (t < 0)
        if numpy.any(bad):
            first = t[bad].flat[0]
            raise ValueError(f"relaxation: times must be at least 0 s, got {first}")
        return self.E_inf + (self._e * numpy.exp(-t[..., None] / self._tau)).sum(axis=-1)

    def write(self, path: PathLike) -> None:
        """Writes the material file (what ``fit-prony -o PATH`` writes)."""
        with open(path, "w", encoding="utf-8", newline="") as f:
            f.write(self.material_toml)

    def __repr__(self) -> str:
        return (
            f"FitResult({self.name!r}: {len(self._tau)} terms, E0 {self.E0:.4g} Pa, "
            f"E_inf {self.E_inf:.4g} Pa)"
        )


def fit_prony(
    data: Any,
    kind: str,
    *,
    terms_per_decade: float = 3.0,
    regularisation: str = "gcv",
    honour: str = "both",
    name: Optional[str] = None,
    temperature: Union[float, str, None] = None,
    like: Optional[str] = None,
    test_piece: Optional[str] = None,
    squeeze: Union[float, str, None] = None,
    cross_section: Union[float, str, None] = None,
    mean_diameter: Union[float, str, None] = None,
    diameter: Union[float, str, None] = None,
    height: Union[float, str, None] = None,
    initial_force: Union[float, str, None] = None,
    reference_modulus: Union[float, str, None] = None,
    shift: Optional[str] = None,
    reference_temperature: Union[float, str, None] = None,
    units: Optional[Mapping[str, str]] = None,
    source: Optional[str] = None,
) -> FitResult:
    """A Prony series fitted to relaxation, CSR or DMA data (``sealsim fit-prony``).

    ``data``: a data file's path, or columns (a DataFrame or a dict of name -> values) with
    the file's column names (``t, E_relax``; ``t, force``; ``t, retained``; ``f, E_stor,
    E_loss``; optional ``T``/``temperature``), in SI unless ``units`` maps a column to its
    unit (``{"t": "h", "force": "N"}``). ``kind``: ``relaxation`` or ``dma``. The options are
    the command's flags (``--test-piece ring`` is ``test_piece="ring"``; ``--honour storage`` is
    ``honour="storage"``); quantities are SI
    floats (m, N, Pa, K; squeeze as a fraction) or strings with units (``"3.53 mm"``,
    ``"25 %"``, ``"70 C"``). ``source``: the name of the data in the provenance and messages
    (default: the path, or ``<data>`` for columns); the default ``name`` is its stem.
    """
    options = dict(
        terms_per_decade=float(terms_per_decade),
        regularisation=regularisation,
        honour=honour,
        name=name,
        temperature=temperature,
        like=like,
        test_piece=test_piece,
        squeeze=squeeze,
        cross_section=cross_section,
        mean_diameter=mean_diameter,
        diameter=diameter,
        height=height,
        initial_force=initial_force,
        reference_modulus=reference_modulus,
        shift=shift,
        reference_temperature=reference_temperature,
        source=source,
    )
    if isinstance(data, _PATHS):
        raw = _sealsim._fit_prony(kind, path=os.fspath(data), **options)
    else:
        raw = _sealsim._fit_prony(kind, text=_columns_csv(data, units), **options)
    return FitResult(raw)


class SurfaceResult(dict):
    """The summary of a roughness source: a dict equal to ``sealsim surface --json`` (``ra_m``,
    ``rq_m``, ``rz_m``, ``h_rms_m``, ``rms_slope``, ``hurst_exponent``, ``q0_per_m``, ...,
    ``warnings``), with the spectrum the chart of ``--plot`` draws: ``spectrum`` (columns
    ``q_per_m``, ``C_m4``) and ``law`` (the fitted or given power law, same columns)."""

    spectrum: Any
    law: Any


def _points(points: Sequence[Sequence[float]]) -> Any:
    from . import _table

    return _table({"q_per_m": [p[0] for p in points], "C_m4": [p[1] for p in points]})


def _trace_csv(x: Any, z: Any, z_unit: str = "m") -> str:
    x = numpy.asarray(x, dtype=float).ravel()
    z = numpy.asarray(z, dtype=float).ravel()
    if x.shape != z.shape:
        raise ValueError(f"surface: a trace's x and z differ in length ({x.size}, {z.size})")
    rows = [f"{repr(float(a))},{repr(float(b))}" for a, b in zip(x, z)]
    return "\n".join(["x,z", f"m,{z_unit}", *rows]) + "\n"


def _is_trace(item: Any) -> bool:
    if isinstance(item, Mapping) or hasattr(item, "columns"):
        return "x" in item and "z" in item
    return isinstance(item, tuple) and len(item) == 2


def surface(
    source: Any,
    *,
    pixel_size: Union[float, str, None] = None,
    height_unit: Optional[str] = None,
    cutoff: Union[float, str, None] = None,
    short_cutoff: Union[float, str, None] = None,
    tip_radius: Union[float, str, None] = None,
    name: Union[str, Sequence[str], None] = None,
) -> SurfaceResult:
    """What a roughness source gives the contact (``sealsim surface --json``).

    ``source``: a path (scenario ``.toml``, trace CSV, PSD CSV, ``.gsf`` height map, or a CSV
    height grid with ``pixel_size``) or a list of trace paths (averaged); a 2-D numpy array of
    heights [m] (rows along x) with ``pixel_size`` [m]; a trace ``(x, z)`` [m] (or a dict /
    DataFrame with columns ``x`` and ``z``), or a list of them. Lengths are SI floats or strings
    with units (``"0.8 mm"``, by the scenario files' parser); ``height_unit`` (``"um"``) is the
    unit of the heights of a grid or a trace's ``z`` (default m; a trace's ``x`` is in m).
    Heights implausible for their spacing (rms slope above 10 at the spacing, or rms of 1 mm or
    more: docs/model.md §2.4) raise an ``InputWarning`` (W044, a ``UserWarning``) with the likely
    unit slip. ``name``: the
    source's name in the summary (a list for several traces; default ``<heights>``,
    ``trace 1``, ...).
    """
    options = dict(
        cutoff=cutoff,
        short_cutoff=short_cutoff,
        tip_radius=tip_radius,
        pixel_size=pixel_size,
        height_unit=height_unit,
    )
    if isinstance(source, _PATHS):
        raw = _sealsim._surface(sources=[os.fspath(source)], **options)
    elif (
        isinstance(source, (list, tuple))
        and source
        and all(isinstance(s, _PATHS) for s in source)
    ):
        raw = _sealsim._surface(sources=[os.fspath(s) for s in source], **options)
    elif isinstance(source, numpy.ndarray) and source.ndim == 2:
        grid = numpy.asarray(source, dtype=float)
        text = "\n".join(",".join(repr(float(v)) for v in row) for row in grid) + "\n"
        raw = _sealsim._surface(grid=text, name=name, **options)
    else:
        items = [source] if _is_trace(source) else source
        if not isinstance(items, (list, tuple)) or not items or not all(map(_is_trace, items)):
            raise ValueError(
                "surface: give a path, a list of paths, a 2-D array of heights or traces (x, z)"
            )
        names = [name] if isinstance(name, str) else list(name or [])
        names += [f"trace {k + 1}" for k in range(len(names), len(items))]
        traces = []
        for label, t in zip(names, items):
            x, z = (t["x"], t["z"]) if not isinstance(t, tuple) else t
            traces.append((label, _trace_csv(x, z, (height_unit or "m").strip())))
        raw = _sealsim._surface(traces=traces, **options)
    text, spectrum, law = raw
    result = SurfaceResult(json.loads(text))
    # heights implausible for their spacing (a unit slip, docs/model.md §2.4) warn at once
    for w in result.get("warnings", []):
        if "heights look" in w or "heights implausible" in w:
            from . import _warn_slip

            _warn_slip(w, stacklevel=2)
    result.spectrum = _points(spectrum)
    result.law = _points(law)
    return result
