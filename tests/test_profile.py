"""`toolkit bench --profile` (issue 36): a query's time by stage. Times are measured, never asserted."""

import json

import numpy as np
import pytest

from toolkit import cli, scenarios
from toolkit.experiments import profile
from toolkit.geometry.compiled import CompiledChecker
from toolkit.planning.paper_prm import PRM
from toolkit.planning.roadmap import Roadmap


def test_profile_splits_each_query_into_stages_that_sum_to_its_time():
    result = profile.profile(scenarios.get("3dc7"), n_queries=2, seed=9100)
    assert len(result["queries"]) == 2
    for record in result["queries"]:
        stages = record["stages_ms"]
        assert record["success"]
        assert sum(stages.values()) == pytest.approx(record["total_ms"])  # exclusive stages cover the call
        assert stages["sampling"] > 0 and stages["verification"] > 0 and stages["neighbours"] > 0
        assert stages[profile.AROUND] >= -1e-6
        assert 0 < record["checker_ms"]["verification"] <= stages["verification"]  # the checker's part of a stage
        assert record["setup_ms"] > 0
    summary = result["summary"]
    assert list(summary["stages"]) == ["set-up", *profile.STAGES, profile.AROUND]
    assert sum(row["share"] for row in summary["stages"].values()) == pytest.approx(1.0)
    assert summary["setup_over_query"] == pytest.approx(summary["setup_ms"] / summary["query_ms"])


def test_profiling_leaves_the_timed_methods_as_they_were():
    before = (vars(PRM)["sample_round"], vars(Roadmap)["shortest_path"], vars(CompiledChecker)["validity"])
    clock = profile.StageClock()
    with clock.patched(CompiledChecker):
        assert vars(Roadmap)["shortest_path"] is not before[1]
        robot = scenarios.get("3dc7").robot
        roadmap = Roadmap(robot)
        roadmap.add_nodes(np.zeros((2, robot.dof)), verified=True)
        assert roadmap.shortest_path(0, 1) is None
    assert clock.seconds["search"] > 0 and clock.seconds["roadmap"] > 0
    assert (vars(PRM)["sample_round"], vars(Roadmap)["shortest_path"], vars(CompiledChecker)["validity"]) == before
    assert "validity" not in vars(Roadmap) and "decide" not in vars(profile.QueryRoadmap)


def test_bench_profile_prints_json_or_a_table(capsys):
    assert cli.main(["bench", "--profile", "--scenario", "3dc7", "--queries", "1", "--seed", "9100", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["scenario"] == "3dc7" and len(result["queries"]) == 1
    assert cli.main(["bench", "--profile", "--scenario", "3dc7", "--queries", "1", "--seed", "9100"]) == 0
    table = capsys.readouterr().out
    assert "| set-up |" in table and "| verification |" in table and "x a query" in table
