"""The Python examples of the guide (docs/src/python.md), of python/README.md and of the README run, and print
the headline's time to failure equal to the CLI's JSON."""

import contextlib
import io
import re

import pytest

from conftest import REPO, read_json

PAGES = ["docs/src/python.md", "python/README.md", "README.md"]


@pytest.mark.parametrize("page", PAGES)
def test_the_python_example_prints_the_clis_time_to_failure(page, cli, tmp_path):
    text = (REPO / page).read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, page
    cli("run", "scenarios/oring-nbr-water-80c.toml", "--summary", tmp_path / "s.json")
    want = read_json(tmp_path / "s.json")["time_to_failure_s"]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(blocks[0], page, "exec"), {})
    lines = out.getvalue().splitlines()
    assert lines[0].startswith("FAILS after 281 days"), lines[0]
    assert repr(want) in lines, (want, lines)
