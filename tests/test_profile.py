"""`toolkit bench --profile` (issue 36): a query's time by stage. Times are measured, never asserted."""

import json

import numpy as np
import pytest

from toolkit import cli, scenarios
from toolkit.experiments import profile
from toolkit.experiments.query_sets import make_queries
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.compiled import CompiledChecker
from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.paper_prm import PRM
from toolkit.planning.planner import Problem
from toolkit.planning.query_roadmap import QueryRoadmap
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
    assert list(summary["stages"]) == ["set-up", *profile.PROFILE_STAGES, profile.AROUND]
    assert sum(row["share"] for row in summary["stages"].values()) == pytest.approx(1.0)
    assert summary["setup_over_query"] == pytest.approx(summary["setup_ms"] / summary["query_ms"])


def test_profiling_changes_no_library_class():
    """The clock times subclasses and instances of its own: the planner, query and roadmap classes and the checker's
    class are as they were, during and after."""
    classes = (LazyPRM, PRM, QueryRoadmap, Roadmap, CompiledChecker)
    before = [dict(vars(cls)) for cls in classes]
    clock = profile.StageClock()
    timed = clock.timed_planner(LazyPRM(k=12))
    assert isinstance(timed, LazyPRM) and type(timed) is not LazyPRM and timed.params == LazyPRM(k=12).params
    scenario = scenarios.get("3dc7")
    query = make_queries(scenario, seed=9100, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(query.workspace, scenario.robot)
    clock.time_checker(exact)
    result = timed.solve(Problem.create(exact, query.start, query.goal), np.random.default_rng(0))
    assert result.success and result.planner == "lazy"
    assert clock.seconds["search"] > 0 and clock.seconds["roadmap"] > 0 and sum(clock.checker.values()) > 0
    assert [dict(vars(cls)) for cls in classes] == before
    assert type(exact).validity is CompiledChecker.validity and "validity" in vars(exact)  # only this instance


def test_bench_profile_prints_json_or_a_table(capsys):
    assert cli.main(["bench", "--profile", "--scenario", "3dc7", "--queries", "1", "--seed", "9100", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["scenario"] == "3dc7" and len(result["queries"]) == 1
    assert cli.main(["bench", "--profile", "--scenario", "3dc7", "--queries", "1", "--seed", "9100"]) == 0
    table = capsys.readouterr().out
    assert "| set-up |" in table and "| verification |" in table and "x a query" in table
