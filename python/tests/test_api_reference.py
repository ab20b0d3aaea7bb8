"""The guide's Python API page is the package's signatures and docstrings, as
python/tools/api_reference.py writes them."""

import subprocess
import sys

import sealsim
from conftest import REPO

PAGE = REPO / "docs/src/reference/python-api.md"


def test_the_committed_api_page_is_generated_from_the_package():
    done = subprocess.run(
        [sys.executable, str(REPO / "python/tools/api_reference.py")], capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    assert PAGE.read_text() == done.stdout, (
        "docs/src/reference/python-api.md is stale: run "
        "`python python/tools/api_reference.py > docs/src/reference/python-api.md`"
    )


def test_the_api_page_documents_every_public_name():
    text = PAGE.read_text()
    for name in sealsim.__all__:
        if name != "__version__":
            assert f"`sealsim.{name}`" in text, name
    assert "(undocumented)" not in text
