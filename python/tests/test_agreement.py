"""The Python results equal the command line's, bit for bit, for every shipped scenario."""

import pathlib

import pytest

import sealsim
from conftest import REPO, assert_table_equals_csv, read_json

# every shipped scenario that `sealsim run` accepts: figure sets (`[[group]]`) and studies are
# other commands' files
SCENARIOS = sorted(
    str(p.relative_to(REPO))
    for p in (REPO / "scenarios").glob("*.toml")
    if "[[group]]" not in p.read_text() and not p.name.endswith(".study.toml")
)


def test_every_shipped_scenario_is_covered():
    # guards the glob: the scenarios of the README's table are all here
    assert len(SCENARIOS) >= 19
    assert "scenarios/oring-nbr-water-80c.toml" in SCENARIOS
    assert "scenarios/persson-yang-2008-figures.toml" not in SCENARIOS


@pytest.mark.parametrize("path", SCENARIOS)
def test_history_and_summary_equal_the_cli(path, cli, tmp_path):
    cli("run", path, "-o", tmp_path / "history.csv", "--summary", tmp_path / "summary.json")
    result = sealsim.Scenario.from_file(path).run()
    assert_table_equals_csv(result.history, tmp_path / "history.csv")
    assert result.summary == read_json(tmp_path / "summary.json")


def test_headline_time_to_failure_equals_the_cli_json(cli, tmp_path):
    path = "scenarios/oring-nbr-water-80c.toml"
    cli("run", path, "--summary", tmp_path / "s.json")
    want = read_json(tmp_path / "s.json")["time_to_failure_s"]
    result = sealsim.Scenario.from_file(path).run()
    assert want is not None and result.time_to_failure == want
    assert result.failure_mode == "retained_force"
    # the README's sentence
    assert result.verdict == "fails"
    assert result.verdict_text.startswith("FAILS after 281 days")


def test_leak_equals_the_cli(cli, tmp_path):
    path = "scenarios/persson-yang-2008.toml"
    cli("leak", path, "--pressures", "0.1MPa,0.2MPa,1MPa", "-o", tmp_path / "leak.csv")
    table = sealsim.Scenario.from_file(path).leak(pressures=[1e5, "0.2 MPa", 1e6])
    assert_table_equals_csv(table, tmp_path / "leak.csv")
    # a seal with motion: the motion columns too
    path = "scenarios/wiper-blade-water.toml"
    cli("leak", path, "-o", tmp_path / "wiper.csv")
    assert_table_equals_csv(sealsim.Scenario.from_file(path).leak(), tmp_path / "wiper.csv")


def test_compare_equals_the_cli(cli, tmp_path):
    path = "scenarios/oring-nbr-water-80c.toml"
    cli("compare", path, "--materials", "nbr-70,fkm-75", "-o", tmp_path / "compare.csv")
    table = sealsim.compare(sealsim.Scenario.from_file(path), ["nbr-70", "fkm-75"])
    assert_table_equals_csv(table, tmp_path / "compare.csv")
    assert list(table["material"]) == ["nbr-70", "fkm-75"]


def test_study_equals_the_cli(cli, tmp_path):
    base = REPO / "scenarios/oring-nbr-water-80c.toml"
    study = tmp_path / "small.study.toml"
    study.write_text(
        f'name = "small"\nbase = "{base}"\ndesign = "latin-hypercube"\nsamples = 12\nseed = 3\n'
        '[vary]\n"environment.temperature" = { distribution = "normal", mean = "80 C", std = "3 K" }\n'
    )
    cli("study", study, "-o", tmp_path / "cases.csv", "--summary", tmp_path / "summary.json")
    result = sealsim.study(str(study))
    assert_table_equals_csv(result.cases, tmp_path / "cases.csv")
    assert result.summary == read_json(tmp_path / "summary.json")
    assert result.summary["cases"] == 12
    # B-lives and the Weibull fit as the summary gives them
    assert set(result.b_lives) >= {"b10", "b50"}
    assert result.b_lives["b10"]["estimate"] == result.summary["b10_s"]
    assert result.weibull == result.summary["weibull"]
    # the same study from its text (base relative to the working directory)
    again = sealsim.study(study.read_text(), threads=1)
    assert list(again.cases["life_s"]) == list(result.cases["life_s"])
