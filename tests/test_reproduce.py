"""`toolkit reproduce --quick` for every scenario, checked against the contract of DESIGN.md."""

import json
from types import SimpleNamespace

import numpy as np
import pytest

from toolkit import cli, scenarios
from toolkit.experiments import paper_numbers, queries, tables
from toolkit.experiments import reproduce as experiments
from toolkit.experiments.config import BASELINES, RunConfig
from toolkit.experiments.stages import Stages
from toolkit.geometry.collision import FCLChecker, exact_checker
from toolkit.learning import presets
from toolkit.planning.options import PaperParams
from toolkit.planning.paper_prm import PRM
from toolkit.planning.sampling import PAPER_SAMPLERS

RATE_KEYS = ("success_rate", "path_valid_rate")
TIME_KEYS = ("sampling_s", "total_s")


def check_contract(results: dict, name: str) -> None:
    assert results["scenario"] == name and results["preset"] == "paper" and results["quick"] is True
    assert results["seed"] == 0
    for key in ("seen_acc", "unseen_acc"):
        assert 0.0 <= results["cae"][key] <= 1.0
    for split in ("seen", "unseen", "unseen_uniform"):
        for key in ("acc", "tpr", "tnr", "always_valid"):
            assert 0.0 <= results["mlp"][split][key] <= 1.0
    assert results["mlp"]["unseen"]["always_valid"] == 0.5  # balanced
    assert set(results["planning"]) == set(PAPER_SAMPLERS)
    assert results["baseline"] == "paper"  # the paper preset's Table 3: Algorithm 1 without prediction
    for sampler, modes in results["planning"].items():
        assert set(modes) == {"without", "with", "baseline"}
        for mode, summary in modes.items():
            for key in RATE_KEYS:
                assert 0.0 <= summary[key] <= 1.0, (sampler, mode, key)
            for key in TIME_KEYS:
                assert summary[key] > 0.0, (sampler, mode, key)
            assert summary["path_valid_rate"] == 1.0, f"{sampler} {mode}: a returned path failed the exact re-check"
    # the exact planner solves these short quick queries
    assert np.mean([results["planning"][s]["without"]["success_rate"] for s in PAPER_SAMPLERS]) > 0.5
    throughput = results["throughput"]
    assert throughput["exact_cfg_per_s"] > 0 and throughput["learned_cfg_per_s"] > 0 and throughput["fcl_cfg_per_s"] > 0


def check_files(out, name: str) -> None:
    tables = (out / "tables.md").read_text()
    for heading in ("Table 1", "Table 2", "Table 3", "Times behind Table 3", "with / without prediction, medians"):
        assert heading in tables
    # the published numbers stand next to ours
    assert f"/ {100 * paper_numbers.MLP[name]['unseen']['acc']:.0f}%" in tables
    for figure in ("cae_reconstruction.png", "planning_times.png", "mlp_threshold.png"):
        assert (out / figure).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(scenarios.SCENARIOS))
def test_quick_reproduction_meets_the_contract(name, tmp_path):
    out = tmp_path / name
    assert cli.main(["reproduce", "--scenario", name, "--quick", "--out", str(out)]) == 0
    results = json.loads((out / "results.json").read_text())
    check_contract(results, name)
    check_files(out, name)
    if name == "2ds":  # a finished run is not redone: every stage comes from the cache
        config = RunConfig.create(name, quick=True, progress=False)
        again = experiments.reproduce(config, out)
        assert again["recomputed"] == []
        assert again["stage_seconds"] == results["stage_seconds"]  # the times of the first run, kept
        summary = tables.summary_markdown([results, results])  # `--scenario all`: a row per scenario
        table1 = summary.split("## Table 1")[1].split("## Table 2")[0]
        assert table1.count("| 2ds | **") == 2
        assert again["planning"] == results["planning"]
        # a lost stage file is computed again, and only that stage
        (out / "cache" / "learning.json").unlink()
        redone = experiments.reproduce(config, out)
        assert redone["recomputed"] == ["learning"] and redone["mlp"] == results["mlp"]


def test_an_output_folder_of_other_settings_is_refused(tmp_path):
    Stages(tmp_path, {"scenario": "2ds", "seed": 0}, progress=False)
    with pytest.raises(ValueError, match="other settings"):
        Stages(tmp_path, {"scenario": "2ds", "seed": 1}, progress=False)


def test_an_interrupted_stage_leaves_no_file_a_later_run_trusts(tmp_path):
    stages = Stages(tmp_path, {"scenario": "2ds"}, progress=False)

    def crash():
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        stages.json("planning_BS_without", crash)
    assert not (stages.cache / "planning_BS_without.json").exists()
    assert stages.json("planning_BS_without", lambda: {"total_s": 1.0}) == {"total_s": 1.0}
    assert stages.json("planning_BS_without", lambda: {"total_s": 2.0}) == {"total_s": 1.0}  # cached


def test_table_2_shows_both_unseen_tests_beside_always_valid():
    scores = {"acc": 0.8, "tpr": 0.9, "tnr": 0.7}
    run = {
        "scenario": "2ds",
        "threshold": 0.5,
        "mlp": {
            "seen": scores,
            "unseen": dict(scores, always_valid=0.5),
            "unseen_uniform": {"acc": 0.86, "tpr": 0.95, "tnr": 0.4, "always_valid": 0.84},
        },
    }
    table2 = tables.paper_tables([_with_planning(run)])
    row = next(line for line in table2 if line.startswith("| 2ds | **80%** / 92%"))
    assert row == (
        "| 2ds | **80%** / 92% | **90%** / 96% | **70%** / 88% | **86%** / 88% | **95%** / 90% | **40%** / 85% "
        "| 84% | **80%** | **90%** | **70%** | 50% |"
    )


def test_table_1_says_when_the_cae_was_not_trained():
    scores = {"acc": 1, "tpr": 1, "tnr": 1, "always_valid": 0.5}
    run = _with_planning(
        {"scenario": "2ds", "threshold": 0.5, "mlp": {"seen": scores, "unseen": scores, "unseen_uniform": scores}}
    )
    lines = tables.paper_tables([dict(run, cae={"trained": False})])  # a checkpoint from toolkit train, no --cae
    assert "| 2ds | not trained | not trained | n/a |" in lines


_MLP = {s: {"acc": 1, "tpr": 1, "tnr": 1, "always_valid": 0.5} for s in ("seen", "unseen", "unseen_uniform")}
_COSTS = {
    "stage_seconds": {"data": 1.0, "models": 2.0},
    "throughput": {"exact_cfg_per_s": 4.0, "fcl_cfg_per_s": 2.0, "learned_cfg_per_s": 1.0, "ratio": 0.25},
}


def _summary(total: float = 1.0) -> dict:
    """A planning summary: every time 1 s but the mean total, ``total``."""
    times = {f"{key}{stat}": 1.0 for key in ("sampling_s", "total_s") for stat in ("", "_std", "_median")}
    return {"success_rate": 1.0, "path_valid_rate": 1.0, **times, "total_s": total}


def _with_planning(run: dict) -> dict:
    """A results dict with the keys paper_tables needs besides Table 2's."""
    summary = _summary()
    return dict(
        run,
        cae={"seen_acc": 1.0, "unseen_acc": 0.9, "seen_all_free": 0.8, "unseen_all_free": 0.8},
        planning={s: dict.fromkeys(tables.MODES, summary) for s in PAPER_SAMPLERS},
        improvement={k: dict.fromkeys(PAPER_SAMPLERS, 0.0) for k in ("sampling", "total")},
    )


def test_improvement_is_the_papers_table_3_measure():
    planning = {s: {"without": {"total_s": 2.0}, "with": {"total_s": 1.5}} for s in PAPER_SAMPLERS}
    assert experiments.improvement(planning, "total_s") == dict.fromkeys(PAPER_SAMPLERS, 0.25)


@pytest.mark.parametrize("preset, screened", [("paper", False), ("strong", True)])
def test_planning_with_prediction_follows_the_presets_edge_rule(preset, screened, monkeypatch, tmp_path):
    """``paper``: Algorithm 1 as published (edges checked exactly, later rounds exact); ``strong``: learned edge
    screening, later rounds confirmed predictions and exact in turn. Without prediction: the best exact planner
    (lazy) with the default exact checker; the paper preset's Table 3 baseline, Algorithm 1, in the same turns."""
    calls = []

    def fake_run(scenario, query_set, sampler, modes, seed=0):
        with_, without = modes["with"], modes["without"]
        assert with_.planner.params.auxiliary == ("confirmed" if screened else "exact")
        assert with_.checker is not None and without.checker is None
        assert without.planner.name == "lazy" and without.exact is exact_checker
        assert with_.planner.name == {"paper": "paper", "strong": "lazy"}[preset] and with_.exact is exact_checker
        baseline = {"paper": ["baseline"], "strong": []}[preset]
        assert list(modes) == ["without", "with", *baseline]  # in turns, one run
        if baseline:  # Table 3: the same planner as "with", Algorithm 1, with the compiled checker
            assert modes["baseline"].planner.name == "paper" and modes["baseline"].checker is None
            assert modes["baseline"].planner.params == with_.planner.params
            assert modes["baseline"].exact is exact_checker
        calls.append((sampler, getattr(with_.planner.params, "screen_edges", False)))
        return {mode: ([], {"sampling_s": 1.0, "total_s": 1.0}) for mode in modes}

    monkeypatch.setattr(experiments.queries, "run_interleaved", fake_run)
    models = SimpleNamespace(preset=presets.get(preset))  # the planning stage plans with the models it is given
    stages = Stages(tmp_path, {"scenario": "2ds"}, progress=False)
    config = RunConfig.create("2ds", preset, quick=True, workers=1, progress=False)
    planning = experiments.planning_stage(stages, config, models)
    assert sorted(s for s, _ in calls) == sorted(PAPER_SAMPLERS)
    assert {screen for _, screen in calls} == {screened}
    assert set(planning) == set(PAPER_SAMPLERS)
    assert set(planning["BS"]) == {"without", "with"} | ({"baseline"} if preset == "paper" else set())


@pytest.mark.parametrize(
    "preset, chosen, baseline, exact",
    [
        ("paper", None, "paper", exact_checker),
        ("strong", None, "best", None),
        ("strong", "paper-fcl", "paper-fcl", FCLChecker),
        ("strong", "paper-fcl-alike", "paper-fcl-alike", FCLChecker),
        ("paper", "best", "best", None),
    ],
)
def test_table_3s_baseline_is_the_recipes_planner_unless_chosen(preset, chosen, baseline, exact):
    config = RunConfig.create("2ds", preset, quick=True, progress=False, baseline=chosen)
    assert config.baseline == baseline and config.settings()["baseline"] == baseline
    modes = experiments.planning_modes(config, SimpleNamespace(preset=config.preset))
    assert modes["without"].planner.name == "lazy"  # always the best exact planner
    assert ("baseline" in modes) == (exact is not None)
    if exact is not None:
        assert modes["baseline"].exact is exact and modes["baseline"].planner.name == "paper"
    # prediction's own exact checks: python-fcl only where the baseline asks for one checker on both sides
    assert modes["with"].exact is (FCLChecker if baseline == "paper-fcl-alike" else exact_checker)
    with pytest.raises(ValueError, match="unknown baseline 'eager'; choose one of best, paper, paper-fcl,"):
        RunConfig.create("2ds", preset, baseline="eager")


def test_reproduce_offers_the_baselines(capsys, tmp_path):
    with pytest.raises(SystemExit):
        cli.main(["reproduce", "--scenario", "2ds", "--baseline", "eager", "--out", str(tmp_path)])
    assert "argument --baseline: invalid choice: 'eager'" in capsys.readouterr().err


def test_each_table_says_what_without_prediction_is():
    run = _with_planning({"scenario": "2ds", "threshold": 0.5, "mlp": _MLP, "baseline": "paper-fcl"})
    run["planning"] = {s: dict(run["planning"][s], baseline=_summary(total=4.0)) for s in PAPER_SAMPLERS}
    text = tables.tables_markdown(dict(run, preset="paper", quick=True, seed=0, **_COSTS))
    table3 = text.split("## Table 3")[1].split("## Times behind")[0]
    assert f"*Without prediction*: {BASELINES['paper-fcl']}." in table3
    times = text.split("## Times behind Table 3")[1].split("## Time with / without")[0]
    assert f"*Without prediction*: {BASELINES['paper-fcl']}." in times
    row = next(line for line in times.splitlines() if line.startswith("| 2ds | BS |")).split("|")
    assert row[5].startswith(" **4 ± 1** / ") and row[6].startswith(" **1 ± 1** / ")  # total: baseline, with
    medians = text.split("## Time with / without prediction, medians")[1].split("## Checker")[0]
    assert f"*Without prediction*: {BASELINES['best']}." in medians  # the strongest, unless the run names a planner:
    assert f"*Without prediction*: {BASELINES['paper']}." in "\n".join(
        tables.median_ratios([dict(run, planner="paper")])
    )
    assert "| 2ds | 1.00 | 1.00 | 1.00 | 1.00 | 1.00 | 1.00 | 1.00 | 1.00 |" in medians
    assert experiments.improvement(run["planning"], "total_s") == dict.fromkeys(PAPER_SAMPLERS, 0.75)
    assert "| exact cfg/s | FCL cfg/s | learned cfg/s |" in text and "| 2ds | 4 | 2 | 1 | 0.25 |" in text


def test_each_querys_own_ratio_and_algorithm_1_timed_twice():
    """A run with --planner paper --baseline paper times one computation twice ("without" and the baseline): tables.md
    gives each query's own ratio (its median and middle half) and how far the two timings' ratios lie from 1."""

    def timed(per_query: list[float]) -> dict:
        return {
            **_summary(float(np.mean(per_query))),
            "total_s_median": float(np.median(per_query)),
            "total_s_per_query": per_query,
        }

    row = {
        "without": timed([1.0, 2.0, 4.0, 8.0]),
        "with": timed([2.0, 2.0, 4.0, 8.0]),
        "baseline": timed([1, 2, 4, 16]),
    }
    run = {"scenario": "3dc7", "baseline": "paper", "planner": "paper", "planning": {"BS": row}}
    assert tables.per_query(row) == "1.00 (1.00–1.25)"  # ratios 2, 1, 1, 1
    lines = tables.per_query_ratios([run])
    assert lines[lines.index("## Time with prediction / Table 3's baseline, each query's own ratio") - 2] == (
        "| 3dc7 | 1.00 (1.00–1.25) |"
    )
    assert lines[-1] == "| 3dc7 | 1.00 (0.88–1.25) |"  # against the baseline: ratios 2, 1, 1, 0.5
    best = dict(run, baseline="best", planning={"BS": {m: row[m] for m in ("without", "with")}})
    assert tables.per_query_ratios([best])[-1] == "| 3dc7 | 1.00 (1.00–1.25) |"  # no baseline planned: one table
    assert tables.timed_twice([run])[-1] == "| 3dc7 | BS | 1.53 | 1.00 | 1.00 (1.00–1.25) |"  # means 5.75 / 3.75
    assert tables.timed_twice([dict(run, planner=None)]) == []  # "without" is the lazy PRM: nothing timed twice


def test_stage_times_add_up_the_planned_samplers_stages_only():
    seconds = {"data": 1.0, "models": 2.0, "planning_MA": 50.0}  # a sampler this run did not plan
    seconds.update({f"planning_{s}": 3.0 for s in PAPER_SAMPLERS})
    run = {
        "scenario": "2ds",
        "stage_seconds": seconds,
        "planning": {s: {} for s in PAPER_SAMPLERS},
        "throughput": {"exact_cfg_per_s": 2.0, "learned_cfg_per_s": 1.0, "ratio": 0.5},
    }
    row = tables.run_costs([run])[-1]
    assert row.endswith("| 1 | 2 | 12 |")


def test_a_planning_mode_brings_its_own_exact_checker_and_options():
    """``queries.Mode``, what the baseline runs on: the paper-fcl baseline's FCL checker checks its edges, and its
    options (here one round of Algorithm 1) are its own while the other mode plans with the run's."""
    scenario = scenarios.get("2ds")
    query_set = queries.make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)
    made = []

    def fcl(ws, robot):
        made.append(FCLChecker(ws, robot))
        return made[-1]

    eager = PRM(PaperParams(n_samples=scenario.plan_samples, max_rounds=1))  # Algorithm 1, one round
    runs = queries.run_interleaved(
        scenario, query_set, "BS", {"best": None, "paper-fcl": queries.Mode(exact=fcl, planner=eager)}
    )
    (record,) = runs["paper-fcl"][0]
    assert record["planner"] == runs["paper-fcl"][1]["planner"] == "paper" and runs["best"][1]["planner"] == "lazy"
    assert len(made) == 2 and made[1].n_checked > 0 and record["rounds"] == 1  # the untimed warm-up's, the query's
    assert runs["best"][1]["success_rate"] == 1.0
