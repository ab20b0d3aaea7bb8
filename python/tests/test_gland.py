"""``sealsim.gland``: the command's design through the library, the same numbers as
``sealsim gland --json``, a scenario that runs, and the command's refusals."""

import json
import math

import pytest

import sealsim


def test_gland_is_the_commands_json_and_its_scenario_runs(cli, tmp_path):
    designed = sealsim.gland(
        "AS568-214",
        "piston",
        bore="31.75 mm",
        temperature=("-20 C", "80 C"),
        pressure_difference="210 bar",
        backup_rings=1,
    )
    out = cli(
        "gland", "AS568-214", "--service", "piston", "--bore", "31.75 mm",
        "--temperature", "-20 C,80 C", "--pressure-difference", "210 bar",
        "--backup-rings", "1", "--json",
    )
    assert designed.summary == json.loads(out.stdout)
    # the table the engineer reads: squeeze of a piston gland in the handbook's static range
    table = designed.stack_up
    squeeze = list(table["quantity"]).index("squeeze")
    assert 0.10 < float(table["nominal"][squeeze]) < 0.30
    assert float(table["service_min"][squeeze]) <= float(table["nominal"][squeeze])
    assert float(table["nominal"][squeeze]) <= float(table["service_max"][squeeze])
    # the written scenario is the CLI's -o file, byte for byte, and it runs
    cli("gland", "AS568-214", "--service", "piston", "--bore", "31.75 mm",
        "--temperature", "-20 C,80 C", "--pressure-difference", "210 bar",
        "--backup-rings", "1", "-o", tmp_path / "piston.toml")
    assert designed.toml == (tmp_path / "piston.toml").read_text()
    scenario = designed.scenario()
    assert "210 bar" in scenario.text
    result = scenario.run()
    assert math.isfinite(result.summary["leaked_volume_m3"])


def test_gland_quantities_as_si_floats_are_the_strings():
    a = sealsim.gland("AS568-214", "piston", bore="0.03175 m", temperature=("253.15 K", "353.15 K"))
    b = sealsim.gland("AS568-214", "piston", bore=0.03175, temperature=(253.15, 353.15))
    assert a.summary == b.summary


@pytest.mark.parametrize(
    "kwargs, words",
    [
        (dict(service="piston", bore="25.4 mm"), "AS568-"),  # a -214 in a 25.4 mm bore
        (dict(service="sideways"), "service"),
        (dict(service="face", dynamic=True), "dynamic"),
        (dict(service="rod", bore="31.75 mm"), "bore"),
        (dict(service="piston", fit="H8/z9"), "fit"),
        (dict(service="piston", material="nbr-99"), "material"),
    ],
)
def test_gland_refusals_name_the_input(kwargs, words):
    with pytest.raises(ValueError) as raised:
        sealsim.gland("AS568-214", **kwargs)
    assert words in str(raised.value)
