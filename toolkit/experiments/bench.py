"""Benchmarks: configurations checked per second, exact and learned; exact edge checks, plain and certified;
PRM time with and without prediction.

Figures are medians over repeats, and ratios come from one run, since these
machines are noisy; :func:`throughput` times the two checkers in turns, so that
both see the same machine however its load changes. ``toolkit bench --scenario S
--json`` prints the throughput and the edge checks; with ``--checkpoint DIR`` it
also plans a few of the paper's queries with each sampler, with and without that
model, and prints the time ratios. ``toolkit bench --vs-ompl --scenario S --queries N``
plans N queries with our planners and OMPL's, on the same exact checker
(:func:`versus_ompl`), and prints a markdown table.
"""

from __future__ import annotations

import dataclasses
import time
from typing import Callable

import numpy as np
import torch

from toolkit.geometry.collision import exact_checker
from toolkit.learning import presets
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.models import build_predictor
from toolkit.learning.training import TrainedModels
from toolkit.planning import queries
from toolkit.planning.local_planner import (
    certify_edges,
    check_edges,
    default_resolution,
)
from toolkit.planning.prm import PRMOptions
from toolkit.scenarios import Scenario


def median_seconds(fn, repeats: int = 5) -> float:
    """Seconds of ``fn()``, the median over ``repeats`` timed calls (one warm-up call first)."""
    fn()
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def median_rate(fn, n_items: int, repeats: int = 5) -> float:
    """Items per second of ``fn()``, the median over ``repeats`` timed calls (one warm-up call first)."""
    return in_turns({"": (fn, n_items)}, repeats)[""]


def in_turns(calls: dict[str, tuple[Callable[[], object], int]], repeats: int = 5) -> dict[str, float]:
    """Items per second of each ``name: (fn, n_items)``, the medians of ``repeats`` rounds in which every
    ``fn`` is timed once, in turns (after one warm-up call each).

    Timed one after the other, two measurements see different machines when the load
    changes: on 2 cores beside two busy processes (and other work), 3DC-7's learned /
    exact ratio came out 20.9 in one run and 5.2 in another, 3DO's 27.4 and 151; timed
    in turns, both see the same machine.
    """
    for fn, _ in calls.values():
        fn()
    seconds: dict[str, list[float]] = {name: [] for name in calls}
    for _ in range(repeats):
        for name, (fn, _) in calls.items():
            start = time.perf_counter()
            fn()
            seconds[name].append(time.perf_counter() - start)
    return {name: n / float(np.median(seconds[name])) for name, (_, n) in calls.items()}


def throughput(scenario: Scenario, preset: str = "paper", batch: int | None = None, seed: int = 0, repeats: int = 5,
               models: TrainedModels | None = None) -> dict[str, float]:
    """``{"exact_cfg_per_s", "learned_cfg_per_s", "ratio"}``: both checkers timed in turns (:func:`in_turns`),
    at ``batch`` configurations a call (default: 20,000 exact, 10,000 learned)."""
    batches = {"batch": batch} if batch else {}
    rates = in_turns({"exact": _exact_call(scenario, seed=seed, **batches),
                      "learned": _learned_call(scenario, preset, seed=seed, models=models, **batches)}, repeats)
    return {"exact_cfg_per_s": rates["exact"], "learned_cfg_per_s": rates["learned"],
            "ratio": rates["learned"] / rates["exact"]}


def exact_throughput(scenario: Scenario, batch: int = 20_000, seed: int = 0, repeats: int = 5) -> float:
    """Configurations per second of the exact checker on uniform samples in one workspace."""
    return median_rate(*_exact_call(scenario, batch, seed), repeats)


def learned_throughput(scenario: Scenario, preset: str = "paper", batch: int = 10_000, seed: int = 0,
                       repeats: int = 5, models: TrainedModels | None = None) -> float:
    """Predictions per second of a :class:`~toolkit.learned.LearnedChecker` at ``batch``, the workspace encoded once.

    The networks are ``models`` or, by default, untrained ones of the preset's sizes: their speed
    does not depend on the weights.
    """
    return median_rate(*_learned_call(scenario, preset, batch, seed, models), repeats)


def _exact_call(scenario: Scenario, batch: int = 20_000, seed: int = 0) -> tuple[Callable[[], object], int]:
    """The exact checker asked about ``batch`` uniform samples in a query workspace, and ``batch``."""
    ws = scenario.workspaces("query", 1, seed)[0]
    checker = exact_checker(ws, scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return (lambda: checker.are_valid(Q)), batch


def _learned_call(scenario: Scenario, preset: str = "paper", batch: int = 10_000, seed: int = 0,
                  models: TrainedModels | None = None) -> tuple[Callable[[], object], int]:
    """A learned checker (``models``, or untrained networks of the preset's sizes) asked about ``batch``
    uniform samples in a query workspace, and ``batch``."""
    if models is None:
        recipe = presets.get(preset)
        torch.manual_seed(seed)
        predictor = build_predictor(scenario, recipe.encoding, recipe.mlp_hidden, recipe.dropout, recipe.latent_input).eval()
        models = TrainedModels(scenario, recipe, predictor, seed)
    ws = scenario.workspaces("query", 1, seed)[0]
    checker = LearnedChecker(ws, models)
    Q = scenario.robot.sample(np.random.default_rng(seed), batch)
    return (lambda: checker.are_valid(Q)), batch


def edge_checks(scenario: Scenario, n_segments: int = 300, seed: int = 0, repeats: int = 5) -> dict[str, dict]:
    """``check_edges`` against ``certify_edges`` (same answers) at the planner's resolution and 10x finer.

    On ``n_segments`` segments between valid configurations of a query workspace, 3 %
    of the bounds apart (normal steps: some valid, some grazing, some through a block;
    a path's edges look like these). Per resolution: median seconds of each, and the
    configurations each checked (``certify_edges`` also bounds clearances).
    """
    ws = scenario.workspaces("query", 1, seed)[0]
    exact, robot, rng = exact_checker(ws, scenario.robot), scenario.robot, np.random.default_rng(seed)
    Q0 = robot.sample(rng, 20 * n_segments)
    Q0 = Q0[exact.are_valid(Q0)]
    Q1 = np.clip(Q0 + rng.normal(0, 0.03, Q0.shape) * (robot.upper - robot.lower), robot.lower, robot.upper)
    keep = exact.are_valid(Q1)
    Q0, Q1 = Q0[keep][:n_segments], Q1[keep][:n_segments]  # (E, dof) each
    resolution = scenario.plan_resolution or default_resolution(robot)
    spacing = resolution * PRMOptions().certify_spacing
    result = {}
    for name, r in (("resolution", resolution), ("finer", resolution / 10)):
        exact.reset_count()
        valid = check_edges(exact, Q0, Q1, r)
        row = {"resolution": r, "segments": len(Q0), "valid": float(valid.mean()), "check_edges_checked": exact.n_checked}
        exact.reset_count()
        certify_edges(exact, Q0, Q1, r, spacing)
        row.update(certify_edges_checked=exact.n_checked, certify_edges_bounded=exact.n_bounded,
                   check_edges_s=median_seconds(lambda: check_edges(exact, Q0, Q1, r), repeats),
                   certify_edges_s=median_seconds(lambda: certify_edges(exact, Q0, Q1, r, spacing), repeats))
        row["speedup"] = row["check_edges_s"] / row["certify_edges_s"]
        result[name] = row
    return result


def planning_ratios(scenario: Scenario, models: TrainedModels, n_workspaces: int = 2, per_workspace: int = 2,
                    seed: int = 0, samplers=("BS", "OB", "G", "BT"), overrides: dict | None = None) -> dict[str, dict]:
    """Per sampler, PRM on the first queries of the paper's set, with ``models`` and without, in turns:
    ``{"sampling_ratio", "total_ratio"}`` (with / without, mean times), the same of the medians, both
    success rates and the sampling rounds and repairs a query each mode needed (means).

    ``overrides`` (PRMOptions fields) apply to both modes, over the scenario's settings and the
    preset's: the same queries with one option changed measure what that option does.
    """
    fields = {f.name for f in dataclasses.fields(PRMOptions)}
    if unknown := sorted(set(overrides or {}) - fields):
        raise ValueError(f"unknown planner option(s) {unknown}; PRMOptions has {sorted(fields)}")
    options = queries.default_options(scenario, None, **{**models.preset.planner_options(), **(overrides or {})})
    per_workspace = min(per_workspace, scenario.queries_per_workspace)
    query_set = queries.make_queries(scenario, seed, n_workspaces, per_workspace)
    table = queries.compare_prediction(scenario, query_set, lambda ws: LearnedChecker(ws, models), samplers,
                                       options, seed)
    return {sampler: {"sampling_ratio": row["sampling_ratio"], "total_ratio": row["total_ratio"],
                      "sampling_ratio_median": row["with"]["sampling_s_median"] / row["without"]["sampling_s_median"],
                      "total_ratio_median": row["with"]["total_s_median"] / row["without"]["total_s_median"],
                      "success_without": row["without"]["success_rate"], "success_with": row["with"]["success_rate"],
                      **{f"{key}_{mode}": row[mode][key] for key in ("rounds", "repairs") for mode in ("without", "with")}}
            for sampler, row in table.items()}


def versus_ompl(scenario: Scenario, n_queries: int = 10, seed: int = 9000, models: TrainedModels | None = None,
                ompl_seconds: float = 30.0, sampler: str = "BS", ompl_planners: tuple[str, ...] = ("PRM", "RRTConnect"),
                paper_baseline: bool = True) -> dict[str, dict]:
    """Our planners against OMPL's PRM and RRTConnect on the same queries and the same exact checker.

    The first ``n_queries`` of ``queries.make_queries(scenario, seed)``; each planner
    solves each query from scratch, the planners in turns query by query (who goes
    first rotates), torch and BLAS on one thread. Ours: the best exact planner
    (``queries.default_options``), the paper's baseline (``prm.PAPER_BASELINE``; unless
    ``paper_baseline`` is False) and, with ``models``, the best exact planner with
    prediction (the model's preset's options, the workspace's encoding counted in its
    time). OMPL's: each of ``ompl_planners`` (classes of ``ompl.geometric``, default PRM
    and RRTConnect) through :mod:`toolkit.planning.ompl`, the same exact checker answering one
    state per call, with ``ompl_seconds`` per query. Edge resolution matched: OMPL's
    state space measures distance as ``robot.motion_bound``, and its validity-checking
    resolution is ``resolution / space.getMaximumExtent()``, so that no robot point
    moves farther than the scenario's resolution between two checks, as in our local
    planner (OMPL checks at least as many points a motion: :mod:`toolkit.planning.ompl`). Every
    returned path is then checked by
    a fresh exact checker at 10x finer resolution (ours verify that themselves; OMPL's
    only check at the resolution). Time is the wall time of the whole call.

    Per planner: ``success_rate`` (an exact solution within the time), ``valid_rate``
    (paths valid at 10x finer, of those found), ``median_s``, ``mean_s``, ``p90_s`` over
    all queries (a failure counts its time), ``checks_median`` (configurations the exact
    checker was asked about, clearance bounds included: one call each for OMPL), and
    ``seconds`` (per query).
    """
    from toolkit.planning import ompl as toolkit_ompl
    from toolkit.planning.local_planner import path_is_valid
    from toolkit.planning.prm import PAPER_BASELINE, plan

    if unknown := [name for name in ompl_planners if not hasattr(toolkit_ompl.og, name)]:
        raise ValueError(f"ompl.geometric has no planner(s) {unknown}")
    toolkit_ompl.quiet(seed)
    per = scenario.queries_per_workspace
    query_set = queries.make_queries(scenario, seed, -(-n_queries // per), per)[:n_queries]
    resolution = scenario.plan_resolution or default_resolution(scenario.robot)
    best = queries.default_options(scenario)

    def ours(options, learned: bool):
        def run(query, exact, n):
            checker = LearnedChecker(query.workspace, models) if learned else None
            result = plan(exact, query.start, query.goal, sampler=sampler, checker=checker,
                          options=options or queries.default_options(scenario, checker), rng=np.random.default_rng([seed, n]))
            return result.success, result.path
        return run

    def theirs(planner):
        def run(query, exact, n):
            result = toolkit_ompl.solve(exact, query.start, query.goal, planner=planner, resolution=resolution,
                                        seconds=ompl_seconds)
            return result.success, result.path
        return run

    planners = {"ours, best exact": ours(best, False)}
    if paper_baseline:
        planners["ours, paper's baseline"] = ours(dataclasses.replace(best, **PAPER_BASELINE), False)
    if models is not None:
        planners[f"ours, with prediction ({models.preset.name})"] = ours(None, True)
    planners.update({f"OMPL {name}": theirs(name) for name in ompl_planners})
    rows = {name: {"seconds": [], "success": [], "valid": [], "checks": []} for name in planners}
    names = list(planners)
    with queries.one_thread():
        for n, query in enumerate(query_set):
            for name in names[n % len(names):] + names[:n % len(names)]:
                exact = exact_checker(query.workspace, scenario.robot)
                began = time.perf_counter()
                success, path = planners[name](query, exact, n)
                row = rows[name]
                row["seconds"].append(time.perf_counter() - began)
                row["checks"].append(exact.n_checked + exact.n_bounded)
                row["success"].append(bool(success))
                fresh = exact_checker(query.workspace, scenario.robot)
                row["valid"].append(bool(success and path_is_valid(fresh, path, resolution / 10)))
    table = {}
    for name, row in rows.items():
        seconds, solved = np.array(row["seconds"]), np.array(row["success"])
        table[name] = {"queries": len(seconds), "success_rate": float(solved.mean()),
                       "valid_rate": float(np.mean(np.array(row["valid"])[solved])) if solved.any() else 1.0,
                       "median_s": float(np.median(seconds)), "mean_s": float(seconds.mean()),
                       "p90_s": float(np.percentile(seconds, 90)), "checks_median": float(np.median(row["checks"])),
                       "seconds": row["seconds"]}
    return table


def versus_ompl_markdown(scenario: Scenario, table: dict[str, dict]) -> str:
    """:func:`versus_ompl`'s table in markdown, with each planner's median over OMPL PRM's (over the first OMPL
    planner's when PRM did not run)."""
    reference = "OMPL PRM" if "OMPL PRM" in table else next((n for n in table if n.startswith("OMPL ")), None)
    if reference is None:
        raise ValueError(f"the table holds no OMPL planner to compare with: {list(table)}")
    prm_median = table[reference]["median_s"]
    lines = [f"| {scenario.name} ({table[reference]['queries']} queries) | solved | valid at 10x finer | "
             f"median s | mean s | p90 s | configurations checked, median | median / {reference}'s |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name, row in table.items():
        lines.append(f"| {name} | {row['success_rate']:.0%} | {row['valid_rate']:.0%} | {row['median_s']:.3f} | "
                     f"{row['mean_s']:.3f} | {row['p90_s']:.3f} | {row['checks_median']:,.0f} | "
                     f"{row['median_s'] / prm_median:.2f} |")
    return "\n".join(lines)
