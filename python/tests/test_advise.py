"""``Scenario.advise`` (``sealsim advise``): the same advice as the CLI's ``--json``, and every
passing proposal, applied with ``Scenario.replace``, meets the target."""

import json
import tomllib

import sealsim

# The new user's AS568-214 NBR piston ring at 210 bar and 80 °C, one back-up ring: FAILS after
# 407 days by retained_force (tests/cli/advise.rs has the same ring).
PISTON = """name = "AS568-214 NBR piston, VG46 210 bar 80 C, 1 backup"
[material]
library = "nbr-70"
[surface]
ra = "0.4 um"
[groove_surface]
ra = "1.6 um"
[fluid]
library = "iso-vg-46"
pressure_difference = "210 bar"
[seal]
kind = "o-ring"
gland = "piston"
size = "AS568-214"
bore_diameter = "31.75 mm"
groove_depth = "2.91 mm"
groove_depth_tolerance = "0.09 mm"
groove_width = "5.6 mm"
diametral_clearance = "0.06 mm"
backup_rings = 1
[environment]
temperature = "80 C"
[failure]
max_leaked_volume = "1 L"
min_retained_force = 0.1
[simulation]
duration = "10 year"
"""

TEN_YEARS = 10 * 365.25 * 86400


def test_advise_equals_the_cli_and_its_proposals_pass(cli, tmp_path):
    path = tmp_path / "piston.toml"
    path.write_text(PISTON)
    scenario = sealsim.Scenario.from_file(path)
    advice = scenario.advise(life="10y", threads=2, max_runs=40)
    out = tmp_path / "a.json"
    cli("advise", path, "--life", "10y", "--threads", "1", "--max-runs", "40", "--json", out)
    assert advice == json.loads(out.read_text())
    assert advice["base"]["passes"] is False
    passing = [p for p in advice["proposals"] if p["passes"]]
    assert passing
    for p in passing:
        values = {c["key"]: tomllib.loads("v = " + c["value"])["v"] for c in p["changes"]}
        result = scenario.replace(values).run()
        assert result.summary["verdict"] == "survives", p
        assert result.summary["time_to_failure_s"] is None
        assert result.summary["duration_s"] >= TEN_YEARS
