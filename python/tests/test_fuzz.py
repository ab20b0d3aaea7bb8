"""Fuzz of the public API (issue 42, item 11): random types and values — None, text, huge and
negative integers, NaN, inf, lists, dicts, bytes, arrays — for every public function,
constructor and method of ``sealsim``, with a fixed seed. Documented failures only: bad input
raises ``ScenarioError``, ``TypeError`` or ``ValueError`` (``ScenarioError`` is a
``ValueError``), a missing file ``FileNotFoundError``/``OSError``; never ``AttributeError``,
``InternalError``, ``KeyError`` or a panic. (``fit_prony(2**70, ...)`` once raised
``AttributeError``; ``contact(youngs_modulus=5e-324)`` returned an infinite column.)

Every call carries at least one fuzzed argument, so nearly all are refused in milliseconds;
the rest are bounded by the fast shipped scenario they run on."""

import inspect
import math
import pathlib
import random

import numpy
import pytest

import sealsim

REPO = pathlib.Path(__file__).resolve().parents[2]
FAST = REPO / "scenarios" / "gasket-nbr-dirty-oil.toml"
SEED = 20261129
CALLS = 600

DOCUMENTED = (sealsim.ScenarioError, TypeError, ValueError, OSError)


def values(rng, depth=0):
    """A random argument: the types and extremes a careless or hostile caller passes."""
    pool = [
        None, "", "abc", "1 bar", "nan MPa", "1e400 Pa", "-5 C", "\x00", "x" * 10_000,
        0, -1, 1, 3, 2**70, -(2**70), 10**400, 0.0, -0.0, 1e-320, 5e-324, 1e308, -1e308,
        math.nan, math.inf, -math.inf, True, b"bytes", bytearray(b"\xff"), object(),
        numpy.int64(3), numpy.float32(2.5), numpy.nan, numpy.array([1.0, math.nan]),
        numpy.zeros((0, 0)), numpy.ones((9, 9)) * 1e300, numpy.full((16, 16), 0.39),
        complex(1, 1), str(FAST), pathlib.Path("/nonexistent/x.toml"), str(REPO),
    ]
    if depth < 2:
        pool += [
            [values(rng, depth + 1) for _ in range(rng.randrange(0, 3))],
            {rng.choice(["k", "", "a.b.c", "seal.squeeze", "t"]): values(rng, depth + 1)},
            (values(rng, depth + 1), values(rng, depth + 1)),
        ]
    return rng.choice(pool)


def targets():
    """Every public callable: (name, function)."""
    scenario = sealsim.Scenario.from_file(FAST)
    out = []
    for name in sealsim.__all__:
        obj = getattr(sealsim, name)
        if name in ("ScenarioError", "InternalError", "__version__") or inspect.isclass(obj) and issubclass(obj, BaseException):
            continue
        if inspect.isclass(obj):
            if name == "Scenario":
                out += [
                    ("Scenario.from_file", sealsim.Scenario.from_file),
                    ("Scenario.from_toml", sealsim.Scenario.from_toml),
                    ("Scenario.replace", scenario.replace),
                    ("Scenario.run", scenario.run),
                    ("Scenario.leak", scenario.leak),
                    ("Scenario.advise", scenario.advise),
                ]
            # result classes (RunResult, FitResult, ...) are built by sealsim from its own
            # output; their constructors are no entry point

        elif callable(obj):
            out.append((name, obj))
    return out


def parameters(fn):
    try:
        return [
            p for p in inspect.signature(fn).parameters.values()
            if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
        ]
    except (TypeError, ValueError):
        return []


def test_public_api_raises_only_documented_exceptions():
    rng = random.Random(SEED)
    funcs = targets()
    assert len(funcs) >= 14, [n for n, _ in funcs]
    seen = {}
    unexpected = []
    for i in range(CALLS):
        name, fn = funcs[i % len(funcs)]
        params = parameters(fn)
        kwargs = {}
        args = []
        if params:
            # fuzz one to three parameters; a required one left out is itself a case
            chosen = rng.sample(params, min(len(params), rng.randrange(1, 4)))
            for p in params:
                if p in chosen:
                    value = values(rng)
                elif p.default is inspect.Parameter.empty:
                    value = values(rng)
                else:
                    continue
                if p.kind is p.POSITIONAL_ONLY:
                    args.append(value)
                else:
                    kwargs[p.name] = value
        else:
            args = [values(rng) for _ in range(rng.randrange(0, 3))]
        # never a progress callback or a plot target that is a live object
        kwargs.pop("progress", None)
        kwargs.pop("ax", None)
        try:
            result = fn(*args, **kwargs)
        except DOCUMENTED as e:
            seen[type(e).__name__] = seen.get(type(e).__name__, 0) + 1
            continue
        except BaseException as e:  # noqa: BLE001 — the point of the test
            unexpected.append(f"{name}(*{args!r:.200}, **{kwargs!r:.300}) raised {type(e).__name__}: {e!s:.300}")
            continue
        seen["returned"] = seen.get("returned", 0) + 1
        check_finite(name, result, unexpected)
    print(f"python fuzz: {CALLS} calls over {len(funcs)} entry points: {seen}")
    assert not unexpected, "\n".join(unexpected)


def check_finite(name, result, unexpected):
    """A returned table or result holds no NaN/inf where the call was accepted (the contact
    table once held an infinite reduced pressure)."""
    if isinstance(result, sealsim.ContactResult):
        table = result.table
        columns = table.columns if hasattr(table, "columns") else table.keys()
        for column in ("nominal_pressure_Pa", "reduced_pressure"):
            if column in columns:
                data = numpy.asarray(table[column], dtype=float)
                if not numpy.all(numpy.isfinite(data)):
                    unexpected.append(f"{name}: non-finite {column}: {data}")


@pytest.mark.parametrize("data", [2**70, numpy.int64(3), math.nan, 3, 2.5, None, b"t,E"])
def test_fit_prony_refuses_data_that_is_not_a_table_with_a_type_error(data):
    with pytest.raises(TypeError, match="fit_prony: data must be"):
        sealsim.fit_prony(data, "relaxation")


@pytest.mark.parametrize("modulus", [5e-324, 1e300, 10.0])
def test_contact_refuses_a_modulus_outside_the_scenario_keys_range(modulus):
    with pytest.raises(sealsim.ScenarioError, match="youngs_modulus must lie in 1e3"):
        sealsim.contact(
            [2e5], youngs_modulus=modulus, rms_roughness=1e-6, hurst_exponent=0.8,
            q0=1e4, q1=1e9,
        )


def test_contact_refuses_a_height_map_in_micrometres_passed_as_metres():
    heights = numpy.random.default_rng(1).normal(0.0, 0.4, (32, 32))  # µm values, taken as m
    with pytest.raises(sealsim.ScenarioError, match="height_map\\[.*height unit"):
        sealsim.contact([2e5], height_map=heights, pixel_size=1e-6, youngs_modulus=1e7)
