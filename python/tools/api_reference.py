"""Writes the Python package's API reference (docs/src/reference/python-api.md) from the
installed package's signatures and docstrings: one source, so the page cannot drift from the
code (python/tests/test_api_reference.py checks the committed page equals this output).

Usage: python python/tools/api_reference.py > docs/src/reference/python-api.md
(it imports the installed package; it lives in tools/ so that the source folder python/sealsim,
which has no compiled extension, does not shadow it on sys.path)
"""

from __future__ import annotations

import inspect
import re
import sys

import sealsim

HEADER = """# Python API

Generated from the package's signatures and docstrings by `python/tools/api_reference.py` (a test
checks this page equals its output: edit the docstrings, then rerun it). Every number is an SI
float; a *table* is a pandas DataFrame when pandas is importable, else a dict of numpy arrays,
with the column names of the command line's CSV files ([CSV columns](columns.md)). Install and a
first run: [Python](../python.md).
"""


def annotation(a) -> str:
    """An annotation as written (they are strings under ``from __future__ import
    annotations``)."""
    return a if isinstance(a, str) else inspect.formatannotation(a)


def signature(obj) -> str:
    """``(name: type = default, *, ...) -> type``, the annotations unquoted."""
    try:
        sig = inspect.signature(obj)
    except (TypeError, ValueError):
        return "(...)"
    parts = []
    star = False
    for p in sig.parameters.values():
        if p.kind == p.KEYWORD_ONLY and not star:
            parts.append("*")
            star = True
        text = p.name
        if p.kind == p.VAR_POSITIONAL:
            text, star = "*" + text, True
        elif p.kind == p.VAR_KEYWORD:
            text = "**" + text
        if p.annotation is not p.empty:
            text += f": {annotation(p.annotation)}"
        if p.default is not p.empty:
            text += f" = {p.default!r}" if p.annotation is not p.empty else f"={p.default!r}"
        parts.append(text)
    out = "(" + ", ".join(parts) + ")"
    if sig.return_annotation is not sig.empty:
        out += f" -> {annotation(sig.return_annotation)}"
    return out


def doc(obj) -> str:
    """The docstring, with Sphinx roles (``:meth:`x```) as plain code."""
    text = inspect.getdoc(obj) or "(undocumented)"
    return re.sub(r":(?:meth|class|func|attr):`~?([^`]+)`", r"``\1``", text.strip())


def block(name: str, obj) -> list[str]:
    return [f"```python\n{name}{signature(obj)}\n```", "", doc(obj), ""]


def members(cls) -> list[tuple[str, object]]:
    out = []
    for name, value in cls.__dict__.items():
        if name.startswith("_"):
            continue
        if isinstance(value, (classmethod, staticmethod)):
            value = getattr(cls, name)  # bound: no ``cls`` in the signature
        out.append((name, value))
    return out


def main() -> None:
    lines = [HEADER]
    names = [n for n in sealsim.__all__ if n != "__version__"]
    classes = [n for n in names if inspect.isclass(getattr(sealsim, n))]
    functions = [n for n in names if n not in classes]
    lines.append("## Functions\n")
    for name in functions:
        lines.append(f"### `sealsim.{name}`\n")
        lines += block(f"sealsim.{name}", getattr(sealsim, name))
    lines.append("## Classes\n")
    for name in classes:
        cls = getattr(sealsim, name)
        lines.append(f"### `sealsim.{name}`\n")
        lines += [doc(cls), ""]
        if issubclass(cls, BaseException):
            lines.append(f"A subclass of `{cls.__mro__[1].__name__}`.\n")
            continue
        for member, value in members(cls):
            if isinstance(value, property):
                lines += [f"#### `{name}.{member}` (property)", "", doc(value), ""]
            elif callable(value):
                lines.append(f"#### `{name}.{member}`\n")
                lines += block(f"{name}.{member}", value)
    sys.stdout.write("\n".join(lines).rstrip() + "\n")


if __name__ == "__main__":
    main()
