"""The example notebook (python/examples/o-ring-life.ipynb) runs top to bottom in under a
minute (nbclient with an ipykernel; tests/python/run.sh installs both)."""

import time

import pytest

from conftest import REPO

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")


def test_the_example_notebook_runs():
    path = REPO / "python/examples/o-ring-life.ipynb"
    nb = nbformat.read(path, as_version=4)
    # outputs are not committed
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code")
    start = time.perf_counter()
    nbclient.NotebookClient(
        nb, timeout=60, kernel_name="python3", resources={"metadata": {"path": str(path.parent)}}
    ).execute()
    assert time.perf_counter() - start < 60
    text = "\n".join(
        o.get("text", "") + str(o.get("data", {}).get("text/plain", ""))
        for c in nb.cells
        if c.cell_type == "code"
        for o in c.outputs
    )
    assert "FAILS after 281 days" in text
    assert "groove depth 2.55 mm: squeeze 27.2%" in text
    assert "fkm-75" in text
