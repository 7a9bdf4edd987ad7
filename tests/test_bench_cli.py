"""`toolkit bench` (issues 2, 25): prints one JSON object with the checkers' throughput (DESIGN.md contract).

Speed targets are measured by the command, never asserted here (no timed unit tests).
"""

import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from toolkit import cli, scenarios
from toolkit.experiments import bench, queries, versus_ompl
from toolkit.learning import checkpoints, presets
from toolkit.planning import sampling
from toolkit.planning.options import LazyParams, PaperParams
from toolkit.planning.planner import REFINEMENT

THROUGHPUT_KEYS = {
    "exact_cfg_per_s",
    "fcl_cfg_per_s",
    "learned_cfg_per_s",
    "ratio",
    "exact_over_fcl",
    "exact_small_call_cost",
}


def test_bench_prints_one_json_object(capsys):
    assert cli.main(["bench", "--scenario", "2ds", "--json"]) == 0
    out = capsys.readouterr().out
    result = json.loads(out)  # the whole output is one JSON object
    assert isinstance(result, dict)
    assert result["scenario"] == "2ds"
    assert set(result) == {"scenario", "edges"} | THROUGHPUT_KEYS
    assert isinstance(result["exact_cfg_per_s"], float) and result["exact_cfg_per_s"] > 0
    assert result["fcl_cfg_per_s"] > 0 and result["learned_cfg_per_s"] > 0  # the contract's other keys
    assert result["ratio"] == pytest.approx(result["learned_cfg_per_s"] / result["exact_cfg_per_s"])
    assert result["exact_over_fcl"] == pytest.approx(result["exact_cfg_per_s"] / result["fcl_cfg_per_s"])
    fine, coarse = result["edges"]["finer"], result["edges"]["resolution"]
    assert fine["resolution"] == pytest.approx(coarse["resolution"] / REFINEMENT) and fine["segments"] > 100
    assert 0 < fine["valid"] <= 1
    assert fine["certify_edges_checked"] < fine["check_edges_checked"] / 5  # clearances vouch for most stretches
    assert fine["check_edges_s"] > 0 and fine["certify_edges_s"] > 0


def test_throughput_times_the_compiled_checker_beside_fcl_in_3d():
    """The default exact checker (compiled) and the python-fcl reference, both timed, on a 3D scenario."""
    scenario = scenarios.get("3dc7")
    result = bench.throughput(scenario, bench.untrained_models(scenario, presets.get("paper")), batch=300, repeats=1)
    assert set(result) == THROUGHPUT_KEYS
    assert all(result[key] > 0 for key in THROUGHPUT_KEYS - {"exact_small_call_cost"})
    assert result["exact_over_fcl"] == pytest.approx(result["exact_cfg_per_s"] / result["fcl_cfg_per_s"])
    assert set(result["exact_small_call_cost"]) == {"16", "32", "64"}
    assert all(cost > 0 for cost in result["exact_small_call_cost"].values())


def test_bench_and_the_small_call_script_measure_small_calls_with_one_function(monkeypatch, capsys):
    """``toolkit bench``'s ``exact_small_call_cost`` and ``docs/scripts/small_call_cost.py`` print
    :func:`bench.small_call_cost`, so the two cannot measure small calls two ways; its figures are consistent."""
    import runpy

    scenario = scenarios.get("3dc7")
    cost = bench.small_call_cost(scenario, batch=40, repeats=1)  # a call of each size at least
    assert set(cost["ratios"]) == set(cost["call_ns"]) == {"16", "32", "64"}
    assert cost["ratios"]["16"] == pytest.approx(cost["call_ns"]["16"] / cost["batch_ns"])
    assert cost["fixed_16_ns"] == pytest.approx(16 * (cost["call_ns"]["16"] - cost["batch_ns"]))
    assert cost["batch_ns"] > 0 and cost["empty_ns"] > 0
    calls = []
    canned = dict(cost, ratios={"16": 2.5, "32": 1.5, "64": 1.25})
    monkeypatch.setattr(bench, "small_call_cost", lambda *args, **kwargs: calls.append(kwargs) or canned)
    result = bench.throughput(scenario, bench.untrained_models(scenario, presets.get("paper")), batch=300, repeats=1)
    assert result["exact_small_call_cost"] == canned["ratios"]
    monkeypatch.setattr("sys.argv", ["small_call_cost.py", "3dc7", "3"])
    runpy.run_path("docs/scripts/small_call_cost.py", run_name="__main__")
    assert "16: 2.50x  32: 1.50x  64: 1.25x" in capsys.readouterr().out
    assert calls[1]["repeats"] == 3


def test_with_and_without_prediction_plan_with_one_planner_whatever_the_models_recipe(monkeypatch):
    """`bench --checkpoint`: both modes run one planner (the lazy PRM unless --planner names another) with the same
    parameters and the default exact checker; only the checker that decides samples differs; an --option reaches
    the planner, and one it does not read is refused."""
    seen = {}

    def fake_run(scenario, query_set, sampler, factories, *, planner, seed):
        seen.update(factories, planner=planner)
        return {
            mode: (
                [],
                {
                    "sampling_s": 1.0,
                    "total_s": 2.0,
                    "sampling_s_median": 1.0,
                    "total_s_median": 2.0,
                    "success_rate": 1.0,
                    "rounds": 1.0,
                    "repairs": 0.0,
                },
            )
            for mode in factories
        }

    monkeypatch.setattr(queries, "run_interleaved", fake_run)
    models = SimpleNamespace(preset=presets.get("paper"))  # a paper model: still the lazy PRM, both ways
    overrides = {"max_rounds": 3, "screen_spacing": 4.0}  # the second: the lazy PRM's alone
    row = bench.planning_ratios(
        scenarios.get("2ds"), models, n_workspaces=1, per_workspace=1, samplers=("BS",), overrides=overrides
    )
    assert row["BS"]["total_ratio"] == 1.0 and row["BS"]["planner"] == "lazy"
    assert seen["without"] is None and callable(seen["with"])  # the modes differ in the checker alone
    assert seen["planner"].name == "lazy" and seen["planner"].params == LazyParams(n_samples=200, **overrides)
    one_planner = {"scenario": scenarios.get("2ds"), "models": models, "samplers": ("BS",)}
    row = bench.planning_ratios(**one_planner, planner="paper", overrides={"max_rounds": 3})  # --planner paper
    assert row["BS"]["planner"] == "paper" and seen["planner"].params == PaperParams(n_samples=200, max_rounds=3)
    with pytest.raises(ValueError, match=r"unknown planner option\(s\) \['screen_spacing'\]; PaperParams has"):
        bench.planning_ratios(**one_planner, planner="paper", overrides={"screen_spacing": 4.0})


def test_bench_at_a_sampler_sized_batch(capsys):
    assert cli.main(["bench", "--scenario", "2ds", "--batch", "200", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["learned_cfg_per_s"] > 0
    with pytest.raises(SystemExit):
        cli.main(["bench", "--scenario", "2ds", "--batch", "0"])
    assert "argument --batch: must be 1..1000000, got 0" in capsys.readouterr().err


@pytest.mark.parametrize(
    "command",
    [
        [sys.executable, "-m", "toolkit"],
        [str(Path(sys.executable).with_name("toolkit"))],  # the console script installed beside this Python
    ],
)
def test_bench_from_the_command_line(command):
    if not Path(command[0]).exists():
        pytest.skip("console script not installed beside this interpreter")
    done = subprocess.run(
        command + ["bench", "--scenario", "2ds", "--json"], capture_output=True, text=True, timeout=120
    )
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["exact_cfg_per_s"] > 0


def test_bench_with_a_checkpoint_times_prm_with_and_without_it(capsys, checkpoint_2ds):
    assert (
        cli.main(
            [
                "bench",
                "--scenario",
                "2ds",
                "--checkpoint",
                str(checkpoint_2ds),
                "--workspaces",
                "1",
                "--pairs",
                "2",
                "--json",
            ]
        )
        == 0
    )
    result = json.loads(capsys.readouterr().out)
    assert set(result["planning"]) == {"BS", "OB", "G", "BT"}
    for row in result["planning"].values():
        assert row["sampling_ratio"] > 0 and row["total_ratio"] > 0
        assert 0.0 <= row["success_with"] <= 1.0 and 0.0 <= row["success_without"] <= 1.0


def test_bench_plans_with_chosen_samplers_and_planner_options(capsys, checkpoint_2ds):
    args = [
        "bench",
        "--scenario",
        "2ds",
        "--checkpoint",
        str(checkpoint_2ds),
        "--workspaces",
        "1",
        "--pairs",
        "2",
        "--samplers",
        "BT",
        "--json",
    ]
    assert cli.main(args + ["--option", "max_rounds=1", "--option", "auxiliary=exact"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["planning_options"] == {"max_rounds": 1, "auxiliary": "exact"}
    row = result["planning"]["BT"]
    assert set(result["planning"]) == {"BT"}
    assert set(row) >= {"sampling_ratio_median", "total_ratio_median", "rounds_with", "repairs_without"}
    assert row["rounds_with"] == row["rounds_without"] == 1  # the option reached both modes (the default: 20)
    assert cli.main(args + ["--option", "max_rounds=1", "--planner", "paper"]) == 0  # both modes Algorithm 1
    assert json.loads(capsys.readouterr().out)["planning_options"] == {"max_rounds": 1, "planner": "paper"}


def test_bench_names_a_bad_planner_option_or_sampler(capsys, checkpoint_2ds):
    args = ["bench", "--scenario", "2ds", "--checkpoint", str(checkpoint_2ds), "--workspaces", "1", "--pairs", "1"]
    assert cli.main(args + ["--option", "rebrige=0"]) == 2
    assert "unknown planner option(s) ['rebrige']" in capsys.readouterr().err
    assert cli.main(args + ["--option", "rebridge=-1"]) == 2
    assert "LazyParams.rebridge must be a non-negative integer" in capsys.readouterr().err
    for bad, message in (
        ("--option=rebridge", "expected NAME=VALUE"),
        ("--samplers=BS,RRT", "unknown sampler(s) ['RRT']"),
    ):
        with pytest.raises(SystemExit):
            cli.main(args + [bad])
        assert message in capsys.readouterr().err


def test_bench_refuses_a_checkpoint_of_another_scenario(capsys, checkpoint_2ds):
    assert cli.main(["bench", "--scenario", "3dc7", "--checkpoint", str(checkpoint_2ds), "--json"]) == 2
    assert "trained for scenario '2ds', not '3dc7'" in capsys.readouterr().err


def test_bench_refuses_an_unknown_scenario(capsys):
    with pytest.raises(SystemExit) as exit_info:
        cli.main(["bench", "--scenario", "4dx", "--json"])
    assert exit_info.value.code == 2
    assert "invalid choice: '4dx'" in capsys.readouterr().err


def test_the_two_checkers_are_timed_in_turns(monkeypatch):
    """``in_turns``: every round times each call once, in turns; each rate is items over its median time.

    A fake clock that each call moves on by its own duration stands in for the machine."""
    clock, order = [0.0], []

    def call(name, seconds):
        def fn():
            order.append(name)
            clock[0] += seconds

        return fn

    monkeypatch.setattr(bench.time, "perf_counter", lambda: clock[0])
    rates = bench.in_turns(
        {"exact": (call("exact", 2.0), 20_000), "learned": (call("learned", 0.01), 10_000)}, repeats=3
    )
    assert order == ["exact", "learned"] * 4  # a warm-up call each, then three rounds
    assert rates == {"exact": pytest.approx(10_000), "learned": pytest.approx(1_000_000)}


def test_bench_vs_ompl_prints_the_load_and_a_markdown_table_per_seed(capsys):
    pytest.importorskip("ompl")
    command = ["bench", "--vs-ompl", "--scenario", "2ds", "--queries", "2", "--seeds", "9000", "--ompl-seconds", "5"]
    assert cli.main(command) == 0
    lines = capsys.readouterr().out.splitlines()
    assert re.fullmatch(
        r"Seed 9000: 1-minute load average [\d.]+ before, [\d.]+ at most, [\d.]+ after, on \d+ cores: "
        r"(idle|loaded \(above 1\.5\))\.",
        lines[0],
    )
    assert lines[2].startswith("| 2ds (2 queries) | solved | valid at 10x finer | median s | CPU median s")
    assert lines[2].endswith("| median / OMPL RRTConnect's | median / OMPL RRTConnect, checks batched's |")
    rows = {line.split("|")[1].strip(): line for line in lines[4:] if line.startswith("|")}
    assert list(rows) == [
        "ours, best exact",
        "ours, RRT-Connect",
        "ours, paper's baseline",
        "OMPL PRM",
        "OMPL PRM, checks batched",
        "OMPL RRTConnect",
        "OMPL RRTConnect, checks batched",
    ]
    for name in ("ours, best exact", "ours, RRT-Connect", "ours, paper's baseline"):  # all solved, valid 10x finer
        assert rows[name].split("|")[2:4] == [" 100% ", " 100% "]
    assert rows["OMPL PRM"].split("|")[9].strip() == "1.00 (1.00)"  # the ratios' first reference
    assert re.search(
        r"^OMPL RRTConnect: a configuration took [\d.]+ us in its Python callbacks", "\n".join(lines), re.M
    )


def test_versus_ompl_races_the_chosen_planners_only():
    pytest.importorskip("ompl")
    scenario = scenarios.get("2ds")
    table = versus_ompl.versus_ompl(
        scenario, n_queries=2, seed=9000, ompl_seconds=5, ompl_planners=("RRTConnect",), paper_baseline=False
    )
    assert list(table) == [
        "ours, best exact",
        "ours, RRT-Connect",
        "OMPL RRTConnect",
        "OMPL RRTConnect, checks batched",
    ]
    assert table["ours, best exact"]["success_rate"] == 1.0 and table["ours, best exact"]["valid_rate"] == 1.0
    assert all(len(row["seconds"]) == 2 for row in table.values())
    raw, batched = table["OMPL RRTConnect"], table["OMPL RRTConnect, checks batched"]
    assert batched["median_s"] < raw["median_s"] and batched["checks_median"] == raw["checks_median"]
    assert raw["callback_us"] > raw["batch_us"] > 0  # one Python call a state costs more than a batched check
    lines = versus_ompl.versus_ompl_markdown(scenario, table).splitlines()
    assert lines[0].endswith("| median / OMPL RRTConnect's | median / OMPL RRTConnect, checks batched's |")
    assert lines[5].startswith("| OMPL RRTConnect, checks batched |") and lines[5].endswith("| 1.00 (1.00) |")
    with pytest.raises(ValueError, match=r"no planner\(s\) \['NoSuchPlanner'\]"):
        versus_ompl.versus_ompl(scenario, n_queries=1, ompl_planners=("NoSuchPlanner",))
    with pytest.raises(ValueError, match="n_queries must be a positive integer, got 0"):
        versus_ompl.versus_ompl(scenario, n_queries=0)


def test_at_batched_rate_swaps_the_callbacks_time_for_one_batched_call(monkeypatch):
    """A solve of 1.0 s wall and 0.8 s CPU, 0.6 s of it in callbacks that asked about 50 configurations: a fake clock
    makes the batched call take 0.01 s (0.008 s CPU); the checker is asked about exactly those 50."""
    from toolkit.geometry.collision import exact_checker

    scenario = scenarios.get("3dc7")
    q = versus_ompl.race_queries(scenario, 1, 7300)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    asked = scenario.robot.sample(np.random.default_rng(0), 50)
    wall, cpu = iter([5.0, 5.01]), iter([2.0, 2.008])
    monkeypatch.setattr(versus_ompl.time, "perf_counter", lambda: next(wall))
    monkeypatch.setattr(versus_ompl.time, "process_time", lambda: next(cpu))
    figures = versus_ompl.at_batched_rate(exact, versus_ompl.Solved(True, None, 0.6, asked), 1.0, 0.8)
    assert exact.n_checked == 50
    assert figures == pytest.approx(
        {"callbacks": 50, "callback_s": 0.6, "batch_s": 0.01, "batched_s": 0.41, "batched_cpu_s": 0.8 * 0.4 + 0.008}
    )


def test_race_seeds_records_the_load_around_each_run(monkeypatch):
    """Loads read in order: before seed 1, before its two queries, after it, and likewise for seed 2."""
    readings = iter([0.2, 0.4, 1.2, 1.1, 3.0, 3.5, 2.0, 2.5, 2.5])
    monkeypatch.setattr(versus_ompl.os, "getloadavg", lambda: (next(readings), 0.0, 0.0))

    def fake(scenario, *, n_queries, seed, loads, **options):
        loads.extend(os.getloadavg()[0] for _ in range(n_queries))  # as race does, before each query
        return {"OMPL RRTConnect": versus_ompl._row([_run(seed / 1e4)] * n_queries, "seconds", "cpu_s")}

    monkeypatch.setattr(versus_ompl, "versus_ompl", fake)
    scenario = scenarios.get("2ds")
    result = versus_ompl.race_seeds(scenario, n_queries=2, seeds=(7300, 9300))
    assert [run["seed"] for run in result["runs"]] == [7300, 9300]
    assert [run["load"] for run in result["runs"]] == [
        {"before": 0.2, "highest": 1.2, "after": 1.1},  # the highest of before, the queries' and after
        {"before": 3.0, "highest": 3.5, "after": 2.5},
    ]
    assert [run["idle"] for run in result["runs"]] == [True, False]
    text = versus_ompl.race_seeds_markdown(scenario, result)
    assert "Seed 7300: 1-minute load average 0.20 before, 1.20 at most, 1.10 after" in text
    assert text.count("| OMPL RRTConnect | 100% |") == 2 and "loaded (above 1.5)." in text


def _run(seconds: float) -> dict:
    return {"seconds": seconds, "cpu_s": seconds, "success": True, "valid": True, "checks": 10}


def test_a_race_takes_the_first_queries_of_the_paper_set():
    scenario = scenarios.get("2ds")
    first = versus_ompl.race_queries(scenario, 3, 9000)
    paper_set = queries.make_queries(scenario, seed=9000)
    assert len(first) == 3
    for ours, theirs in zip(first, paper_set[:3]):
        np.testing.assert_array_equal(ours.start, theirs.start)
        np.testing.assert_array_equal(ours.goal, theirs.goal)


def test_a_race_rotates_who_goes_first_and_times_every_solve(monkeypatch):
    """Three planners over three queries: each query's first planner is the next one; a fake clock moves on by
    each planner's own duration, and the table reports those durations."""
    clock, order = [0.0], []

    def fake(name, seconds, success):
        def solve(query, exact, n):
            order.append((n, name))
            clock[0] += seconds
            return versus_ompl.Solved(success, None if not success else np.stack([query.start, query.start]))

        return solve

    monkeypatch.setattr(versus_ompl.time, "perf_counter", lambda: clock[0])
    scenario = scenarios.get("2ds")
    racing = {"a": fake("a", 1.0, True), "b": fake("b", 2.0, False), "c": fake("c", 4.0, True)}
    loads = []
    solves = versus_ompl.race(scenario, versus_ompl.race_queries(scenario, 3, 9000), racing, loads)
    assert len(loads) == 3  # the load before each query
    warm_up = [(0, "a"), (0, "b"), (0, "c")]  # each planner's untimed first solve, then the timed rounds
    assert order == warm_up + [(0, "a"), (0, "b"), (0, "c"), (1, "b"), (1, "c"), (1, "a"), (2, "c"), (2, "a"), (2, "b")]
    table = versus_ompl.summarize(solves)
    assert table["a"]["seconds"] == [1.0, 1.0, 1.0] and table["c"]["median_s"] == 4.0
    assert table["b"]["success_rate"] == 0.0 and table["b"]["valid_rate"] == 1.0  # nothing found, nothing invalid
    assert table["a"]["success_rate"] == 1.0 and table["a"]["valid_rate"] == 1.0  # a path of the start, twice
    assert table["a"]["checks_median"] == 0.0  # the fake planners ask the checker nothing


def test_summarize_counts_failures_times_and_validity_of_found_paths_only():
    runs = [
        {"seconds": s, "cpu_s": s / 2, "success": ok, "valid": valid, "checks": c}
        for s, ok, valid, c in (
            (1.0, True, True, 10),
            (2.0, True, False, 20),
            (3.0, False, False, 30),
            (10.0, True, True, 40),
        )
    ]
    row = versus_ompl.summarize({"p": runs})["p"]
    assert row["queries"] == 4 and row["success_rate"] == 0.75
    assert row["valid_rate"] == pytest.approx(2 / 3)  # of the three paths found
    assert row["median_s"] == 2.5 and row["mean_s"] == 4.0 and row["checks_median"] == 25.0
    assert row["cpu_median_s"] == 1.25
    assert row["p90_s"] == pytest.approx(float(np.percentile([1.0, 2.0, 3.0, 10.0], 90)))


def test_planning_ratios_plans_a_registered_sampler_and_names_an_unknown_one(monkeypatch, checkpoint_2ds):
    monkeypatch.setattr(sampling, "SAMPLERS", dict(sampling.SAMPLERS))

    class Uniform(sampling.UniformSampler):
        """BS under another name."""

    sampling.register_sampler("MINE", Uniform)
    models = checkpoints.load_models(checkpoint_2ds, "2ds")
    scenario = scenarios.get("2ds")
    result = bench.planning_ratios(
        scenario, models, n_workspaces=1, per_workspace=1, samplers=("MINE",), overrides={"max_rounds": 1}
    )
    assert set(result) == {"MINE"}
    assert result["MINE"]["rounds_with"] == result["MINE"]["rounds_without"] == 1
    with pytest.raises(ValueError, match=r"unknown sampler\(s\) \['RRT'\]; choose from BS, OB, G, BT, MINE$"):
        bench.planning_ratios(scenario, models, n_workspaces=1, per_workspace=1, samplers=("BS", "RRT"))


def test_untrained_models_have_the_presets_sizes_and_answer_alike_for_a_seed():
    scenario = scenarios.get("2ds")
    one, two = (bench.untrained_models(scenario, presets.get("strong"), seed=3) for _ in range(2))
    assert one.preset.name == "strong" and not one.predictor.training
    for a, b in zip(one.predictor.state_dict().values(), two.predictor.state_dict().values()):
        assert a.shape == b.shape and bool((a == b).all())


def test_edge_check_segments_join_valid_configurations_a_short_step_apart():
    from toolkit.geometry.collision import exact_checker

    scenario = scenarios.get("2ds")
    exact = exact_checker(scenario.workspaces("query", 1, 0)[0], scenario.robot)
    Q0, Q1 = bench.short_valid_segments(exact, 50, np.random.default_rng(0))
    assert Q0.shape == Q1.shape == (50, scenario.robot.dof)
    assert exact.are_valid(Q0).all() and exact.are_valid(Q1).all()
    steps = np.abs(Q1 - Q0) / (scenario.robot.upper - scenario.robot.lower)  # (50, dof), as fractions of the bounds
    assert 0.005 < np.median(steps) < 0.05  # normal steps of 0.03 x the bounds: median |step| about 0.02


def test_bench_vs_ompl_says_how_to_install_ompl(monkeypatch, capsys):
    import toolkit.planning

    monkeypatch.setitem(sys.modules, "ompl", None)  # as if not installed: importing it raises ImportError
    monkeypatch.delitem(sys.modules, "toolkit.planning.ompl", raising=False)
    monkeypatch.delattr(toolkit.planning, "ompl", raising=False)
    assert cli.main(["bench", "--vs-ompl", "--scenario", "2ds", "--queries", "1"]) == 2
    assert "pip install 'sample-collision-toolkit[ompl]'" in capsys.readouterr().err


def test_bench_needs_a_scenario_but_with_crossover(capsys):
    assert cli.main(["bench", "--json"]) == 2
    assert "--scenario is needed (but with --crossover)" in capsys.readouterr().err


def test_cpu_clock_times_what_a_call_computed_not_what_it_waited():
    """Within ``bench.cpu_clock`` a call that sleeps costs next to nothing; outside it, the wall clock is back."""
    nap = (lambda: time.sleep(0.05), 1)  # one item in 0.05 s of wall time: 20 a second
    with bench.cpu_clock():
        assert bench.in_turns({"nap": nap}, repeats=1)["nap"] > 200
    assert bench.in_turns({"nap": nap}, repeats=1)["nap"] < 21


def test_bench_vs_ompl_names_a_bad_seed(capsys):
    with pytest.raises(SystemExit) as exit_:
        cli.main(["bench", "--vs-ompl", "--scenario", "2ds", "--seeds", "7300,x"])
    assert exit_.value.code == 2
    assert "argument --seeds: must be a whole number, 0..4294967295; got 'x'" in capsys.readouterr().err
