"""Validity findings and input warnings reach the Python user through the ``warnings`` module
(issue 42): ``ValidityWarning`` / ``InputWarning`` (both ``SealsimWarning``, a ``UserWarning``)
carrying the code that ``sealsim explain`` expands, filterable by code."""

import warnings

import pytest

import sealsim


def _run(repo, name="scenarios/oring-nbr-water-80c.toml"):
    return sealsim.Scenario.from_file(str(repo / name)).run()


def test_the_headline_run_issues_its_validity_and_input_warnings_with_codes(repo, cli_path):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = _run(repo)
    ours = [w for w in caught if issubclass(w.category, sealsim.SealsimWarning)]
    validity = [w.message for w in ours if issubclass(w.category, sealsim.ValidityWarning)]
    inputs = [w.message for w in ours if issubclass(w.category, sealsim.InputWarning)]
    # the same codes as the run's records (the CLI prints these three on stderr)
    assert sorted(w.code for w in validity) == sorted(r["code"] for r in result.warnings)
    assert {"W001", "W015"} <= {w.code for w in validity}
    assert [w.code for w in inputs] == ["W038"]
    w001 = next(w for w in validity if w.code == "W001")
    assert str(w001).startswith("W001 pressure_ratio: ΔP/P0 = 1 is above 0.5")
    assert w001.record["id"] == "pressure_ratio" and w001.record["value"] == 1.0
    assert isinstance(w001, UserWarning)
    # a note (how the callout was read) is not a warning
    assert all(not w.message.code.startswith("N") for w in ours)
    # every code is one `sealsim explain` knows
    import subprocess

    for code in {w.message.code for w in ours}:
        out = subprocess.run([cli_path, "explain", code], capture_output=True, text=True)
        assert out.returncode == 0 and out.stdout.startswith(code)


def test_a_code_is_silenced_by_its_message_prefix_and_a_kind_by_its_category(repo):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.filterwarnings("ignore", message="W001")
        _run(repo)
    codes = [w.message.code for w in caught if issubclass(w.category, sealsim.SealsimWarning)]
    assert "W001" not in codes and "W015" in codes
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.filterwarnings("ignore", category=sealsim.ValidityWarning)
        _run(repo)
    codes = [w.message.code for w in caught if issubclass(w.category, sealsim.SealsimWarning)]
    assert codes == ["W038"]


def test_warnings_as_errors_stop_at_the_first_one(repo):
    with warnings.catch_warnings():
        warnings.simplefilter("error", sealsim.SealsimWarning)
        with pytest.raises(sealsim.InputWarning) as raised:
            _run(repo)
    assert raised.value.code == "W038"
