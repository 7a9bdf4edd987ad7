"""Our planners against OMPL's, on the same queries and the same exact checker (``toolkit bench --vs-ompl``).

The paper measures prediction against its own exact PRM (§V, Table 3; Algorithm 1).
A gain over a slow baseline says little, so this race asks the question an OMPL user
would: is our exact planner, with or without prediction, faster than OMPL's PRM and
RRTConnect (Şucan, Moll, Kavraki 2012) on the same problem? A race takes four steps,
one function each:

1. :func:`race_queries` — the first ``n`` queries of the paper's set for a seed;
2. :func:`contenders` — the planners, each a :data:`Planner` callable: ours (the best
   exact planner, RRT-Connect, the paper's baseline, and with prediction) and OMPL's,
   through the adapter :mod:`toolkit.planning.ompl`;
3. :func:`race` — each planner solves each query from scratch, the planners in turns
   query by query (who goes first rotates, so that all see the same machine load),
   torch and BLAS on one thread; :func:`timed_solve` times one solve and re-checks
   its path;
4. :func:`summarize` — per planner: success, validity, times and checks.

:func:`versus_ompl` runs the four for one seed; :func:`versus_ompl_markdown` prints its table.
:func:`race_seeds` runs it for several seeds and records the machine's load around each
(:func:`race_seeds_markdown`): ``toolkit bench --vs-ompl``.

What keeps the race fair:

- One checker: every planner asks a fresh default exact checker (``exact_checker``: compiled for box
  worlds) per query; ours in batches, OMPL's one state per call (OMPL asks about one state at a time).
- One edge resolution: OMPL's state space measures distance as ``robot.motion_bound``
  and its validity-checking resolution is ``resolution / space.getMaximumExtent()``,
  so no robot point moves farther than the scenario's resolution between two checks,
  as in our local planner (OMPL then checks at least as many points a motion:
  :mod:`toolkit.planning.ompl`).
- One verdict: every returned path is re-checked by a fresh exact checker at 10x
  finer resolution (ours verify that themselves; OMPL's only check at the resolution).
- One clock: the wall time of the whole call, the model's workspace encoding included
  for prediction; a query a planner does not solve counts the time it took. Beside it the
  process's CPU time, which a busy machine inflates less (it leaves out the time the race
  waited for a core).
- The strongest peer: OMPL asks about one state per Python call, and most of its time goes
  there. Beside each OMPL planner the table has the same planner *with its checks batched*:
  its wall time minus the time spent inside its validity callbacks, plus one batched call of
  our checker on the configurations they asked about (:func:`at_batched_rate`) — what it
  would take if OMPL could ask as we do.
- The machine's load: a busy machine slows a Python call per state more than a batched
  call, which flatters us. :func:`race_seeds` records the 1-minute load average before,
  during (the highest, read before each query) and after each race; a race whose load stayed
  at or below ``IDLE_LOAD`` ran on an idle machine (its own thread is a load of 1).

Results and what they say: ``docs/planner_race.md``, "Our planners against OMPL's".
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from toolkit.experiments import queries
from toolkit.experiments.problems import build, make_planner, scenario_resolution
from toolkit.experiments.queries import Query
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.training import TrainedModels
from toolkit.planning import prm
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.planner import REFINEMENT
from toolkit.planning.planner import Planner as Solver
from toolkit.scenarios import Scenario

IDLE_LOAD = 1.5  # a race whose 1-minute load average stayed at or below this ran on an idle machine


@dataclass
class Solved:
    """A planner's answer to one query: ``success``, ``path (P, dof)`` (None: none); for OMPL, ``callback_s``, the
    seconds spent in its Python validity callbacks, and ``asked (C, dof)``, the configurations they asked about."""

    success: bool
    path: np.ndarray | None
    callback_s: float = 0.0
    asked: np.ndarray | None = None


# planner(query, exact, n) -> Solved: solves query number n, exact deciding validity
Planner = Callable[[Query, CollisionChecker, int], Solved]


def race_queries(scenario: Scenario, n_queries: int, seed: int) -> list[Query]:
    """The first ``n_queries`` of ``queries.make_queries(scenario, seed)``: as many workspaces as they fill."""
    if int(n_queries) != n_queries or n_queries < 1:
        raise ValueError(f"n_queries must be a positive integer, got {n_queries!r}")
    per = scenario.queries_per_workspace
    return queries.make_queries(scenario, seed=seed, n_workspaces=-(-n_queries // per), per_workspace=per)[:n_queries]


def our_planner(
    solver: Solver, scenario: Scenario, *, sampler: str, seed: int, models: TrainedModels | None = None
) -> Planner:
    """Our planner ``solver`` (its name and parameters) on queries of ``scenario`` with ``sampler``; with ``models``,
    a learned checker of the query's workspace decides the samples (built inside the call, so its workspace
    encoding counts in the time). Query ``n`` draws from ``rng = default_rng([seed, n])``."""

    def solve(query: Query, exact: CollisionChecker, n: int):
        checker = LearnedChecker(query.workspace, models) if models is not None else None
        task = build(scenario, query, sampler=sampler, planner=solver, checker=checker, exact=exact)
        result = task.solve(np.random.default_rng([seed, n]))
        return Solved(result.success, result.path)

    return solve


def ompl_planner(name: str, resolution: float, seconds: float) -> Planner:
    """OMPL's planner ``name`` (a class of ``ompl.geometric``) at our edge ``resolution``, ``seconds`` a query."""
    # toolkit.planning.ompl needs the optional extra: imported here, so that only a race needs it
    from toolkit.planning import ompl as toolkit_ompl

    def solve(query: Query, exact: CollisionChecker, n: int):
        result = toolkit_ompl.solve(
            exact, query.start, query.goal, planner=name, resolution=resolution, seconds=seconds
        )
        return Solved(result.success, result.path, result.callback_s, result.asked)

    return solve


def contenders(
    scenario: Scenario,
    *,
    seed: int,
    models: TrainedModels | None,
    sampler: str,
    ompl_planners: tuple[str, ...],
    ompl_seconds: float,
    paper_baseline: bool,
) -> dict[str, Planner]:
    """The planners of a race, by the name its table gives them, ours first.

    Ours: the best exact planner (the lazy PRM), RRT-Connect, the paper's baseline (Algorithm 1,
    ``paper``; unless ``paper_baseline`` is False) and, with ``models``, the planner paired with
    the model's preset with prediction (:mod:`toolkit.experiments.planners`, as
    ``bench.planning_ratios`` plans). OMPL's: each of ``ompl_planners``.
    """
    resolution = scenario_resolution(scenario)
    ours = {
        "ours, best exact": our_planner(make_planner(scenario, prm.DEFAULT), scenario, sampler=sampler, seed=seed),
        "ours, RRT-Connect": our_planner(make_planner(scenario, "rrt-connect"), scenario, sampler=sampler, seed=seed),
    }
    if paper_baseline:
        paper = make_planner(scenario, "paper")  # Algorithm 1
        ours["ours, paper's baseline"] = our_planner(paper, scenario, sampler=sampler, seed=seed)
    if models is not None:
        predicting = make_planner(scenario, preset=models.preset)
        ours[f"ours, with prediction ({models.preset.name})"] = our_planner(
            predicting, scenario, sampler=sampler, seed=seed, models=models
        )
    return {**ours, **{f"OMPL {name}": ompl_planner(name, resolution, ompl_seconds) for name in ompl_planners}}


def timed_solve(planner: Planner, query: Query, n: int, *, robot: BoxRobot, resolution: float) -> dict:
    """One solve from scratch: ``{"seconds", "cpu_s", "success", "valid", "checks"}``, and for a planner whose
    callbacks were timed (OMPL's) :func:`at_batched_rate`'s figures.

    ``cpu_s``: the process's CPU time; ``valid``: the path passes a fresh exact checker at
    ``resolution / REFINEMENT``; ``checks``: configurations the planner's exact checker was asked about,
    clearance bounds included.
    """
    exact = exact_checker(query.workspace, robot)
    began, cpu = time.perf_counter(), time.process_time()
    solved = planner(query, exact, n)
    seconds, cpu_s = time.perf_counter() - began, time.process_time() - cpu
    fresh = exact_checker(query.workspace, robot)  # one the planner never asked
    valid = solved.success and path_is_valid(fresh, solved.path, resolution / REFINEMENT)
    run = {
        "seconds": seconds,
        "cpu_s": cpu_s,
        "success": bool(solved.success),
        "valid": valid,
        "checks": exact.n_checked + exact.n_bounded,
    }
    if solved.asked is not None:
        run.update(at_batched_rate(exact, solved, seconds, cpu_s))
    return run


def at_batched_rate(exact: CollisionChecker, solved: Solved, seconds: float, cpu_s: float) -> dict:
    """A solve's time with its validity callbacks at our batched rate: ``batched_s``, its ``seconds`` minus
    ``callback_s`` plus one call of ``exact`` on the configurations they ``asked`` (``batch_s``), and
    ``batched_cpu_s``, its ``cpu_s`` less the callbacks' share of it (``callback_s / seconds``) plus that
    call's CPU time; with ``callbacks`` (their number), ``callback_s`` and ``batch_s``."""
    asked = np.zeros((0, exact.robot.dof)) if solved.asked is None else solved.asked  # (C, dof)
    began, cpu = time.perf_counter(), time.process_time()
    exact.are_valid(asked)
    batch_s, batch_cpu_s = time.perf_counter() - began, time.process_time() - cpu
    share = solved.callback_s / seconds if seconds > 0 else 0.0
    return {
        "callbacks": len(asked),
        "callback_s": solved.callback_s,
        "batch_s": batch_s,
        "batched_s": seconds - solved.callback_s + batch_s,
        "batched_cpu_s": cpu_s * (1 - share) + batch_cpu_s,
    }


def race(
    scenario: Scenario, query_set: list[Query], racing: dict[str, Planner], loads: list | None = None
) -> dict[str, list[dict]]:
    """Per planner, its :func:`timed_solve` of every query; the planners in turns query by query, the first of
    query ``n`` the ``n``-th (mod their count), on one thread (``queries.one_thread``); ``loads`` receives the
    1-minute load average before each query.

    Each planner first solves the first query once, untimed, so that no timing includes a compiled
    kernel's first call (numba compiling or loading it: seconds) or torch's set-up.
    """
    resolution = scenario_resolution(scenario)
    solves: dict[str, list[dict]] = {name: [] for name in racing}
    names = list(racing)
    with queries.one_thread():
        for name in names if query_set else []:  # the untimed warm-up
            timed_solve(racing[name], query_set[0], 0, robot=scenario.robot, resolution=resolution)
        for n, query in enumerate(query_set):
            if loads is not None:
                loads.append(os.getloadavg()[0])
            for name in names[n % len(names) :] + names[: n % len(names)]:
                solves[name].append(timed_solve(racing[name], query, n, robot=scenario.robot, resolution=resolution))
    return solves


def summarize(solves: dict[str, list[dict]]) -> dict[str, dict]:
    """Per planner: ``queries``, ``success_rate``, ``valid_rate`` (of the paths found; 1.0 when none was),
    ``median_s``, ``mean_s``, ``p90_s`` over all queries (a failure counts its time), ``cpu_median_s``,
    ``checks_median``, and ``seconds`` (per query). A planner whose callbacks were timed (OMPL's) also gets
    ``callback_us`` and ``batch_us`` (a configuration's median cost in its callbacks and in one batched call), and
    a row of its own, ``"<name>, checks batched"``, of its times at our batched rate (:func:`at_batched_rate`)."""
    table = {}
    for name, runs in solves.items():
        table[name] = _row(runs, "seconds", "cpu_s")
        if runs and "batched_s" in runs[0]:
            per_check = {  # (Q,) each: microseconds a configuration
                key: [1e6 * run[key] / max(run["callbacks"], 1) for run in runs] for key in ("callback_s", "batch_s")
            }
            table[name].update(
                callback_us=float(np.median(per_check["callback_s"])), batch_us=float(np.median(per_check["batch_s"]))
            )
            table[f"{name}, checks batched"] = _row(runs, "batched_s", "batched_cpu_s")
    return table


def _row(runs: list[dict], seconds_key: str, cpu_key: str) -> dict:
    seconds = np.array([run[seconds_key] for run in runs])  # (Q,)
    solved = np.array([run["success"] for run in runs])  # (Q,)
    valid = np.array([run["valid"] for run in runs])  # (Q,)
    return {
        "queries": len(runs),
        "success_rate": float(solved.mean()),
        "valid_rate": float(valid[solved].mean()) if solved.any() else 1.0,
        "median_s": float(np.median(seconds)),
        "mean_s": float(seconds.mean()),
        "p90_s": float(np.percentile(seconds, 90)),
        "cpu_median_s": float(np.median([run[cpu_key] for run in runs])),
        "checks_median": float(np.median([run["checks"] for run in runs])),
        "seconds": seconds.tolist(),
    }


def versus_ompl(
    scenario: Scenario,
    *,
    n_queries: int = 10,
    seed: int = 9000,
    models: TrainedModels | None = None,
    ompl_seconds: float = 30.0,
    sampler: str = "BS",
    ompl_planners: tuple[str, ...] = ("PRM", "RRTConnect"),
    paper_baseline: bool = True,
    loads: list | None = None,
) -> dict[str, dict]:
    """Our planners (:func:`contenders`) against OMPL's ``ompl_planners`` on the first ``n_queries`` of the paper's
    query set for ``seed``, raced in turns (:func:`race`, which appends the load before each query to ``loads``):
    :func:`summarize`'s table.

    Raises ImportError (naming the extra to install) without OMPL, ValueError for a planner
    ``ompl.geometric`` lacks.
    """
    # toolkit.planning.ompl needs the optional extra: imported here, so that only a race needs it
    from toolkit.planning import ompl as toolkit_ompl

    if unknown := [name for name in ompl_planners if not hasattr(toolkit_ompl.og, name)]:
        raise ValueError(f"ompl.geometric has no planner(s) {unknown}")
    if not ompl_seconds > 0:
        raise ValueError(f"ompl_seconds must be positive, got {ompl_seconds!r}")
    query_set = race_queries(scenario, n_queries, seed)
    racing = contenders(
        scenario,
        seed=seed,
        models=models,
        sampler=sampler,
        ompl_planners=tuple(ompl_planners),
        ompl_seconds=ompl_seconds,
        paper_baseline=paper_baseline,
    )
    toolkit_ompl.quiet(seed)  # OMPL's own generators, seeded
    return summarize(race(scenario, query_set, racing, loads))


def race_seeds(scenario: Scenario, *, n_queries: int = 30, seeds=(7300, 9300), **options) -> dict:
    """:func:`versus_ompl` (with ``options``) for each of ``seeds``, each run with the machine's load around it:
    ``{"scenario", "cores", "runs": [{"seed", "load": {"before", "highest", "after"}, "idle", "planners"}]}``.

    The loads are 1-minute load averages (``os.getloadavg``): before the run, the highest read before a query, and
    after it; ``idle``: none above ``IDLE_LOAD``.
    """
    runs = []
    for seed in seeds:
        loads = [os.getloadavg()[0]]
        planners = versus_ompl(scenario, n_queries=n_queries, seed=seed, loads=loads, **options)
        after = os.getloadavg()[0]
        load = {"before": loads[0], "highest": max(loads + [after]), "after": after}
        runs.append({"seed": seed, "load": load, "idle": load["highest"] <= IDLE_LOAD, "planners": planners})
    return {"scenario": scenario.name, "cores": os.cpu_count(), "runs": runs}


def race_seeds_markdown(scenario: Scenario, result: dict) -> str:
    """:func:`race_seeds`'s runs: for each, a line with its seed and load, then its :func:`versus_ompl_markdown`
    table."""
    parts = []
    for run in result["runs"]:
        load = run["load"]
        parts.append(
            f"Seed {run['seed']}: 1-minute load average {load['before']:.2f} before, {load['highest']:.2f} at most, "
            f"{load['after']:.2f} after, on {result['cores']} cores: "
            + ("idle." if run["idle"] else f"loaded (above {IDLE_LOAD}).")
        )
        parts.append(versus_ompl_markdown(scenario, run["planners"]))
    return "\n\n".join(parts)


def versus_ompl_markdown(scenario: Scenario, table: dict[str, dict]) -> str:
    """:func:`versus_ompl`'s table in markdown, with each planner's median over each OMPL planner's (wall time, and
    in brackets CPU time)."""
    references = [name for name in table if name.startswith("OMPL ")]
    if not references:
        raise ValueError(f"the table holds no OMPL planner to compare with: {list(table)}")
    header = (
        f"| {scenario.name} ({table[references[0]]['queries']} queries) | solved | valid at {REFINEMENT}x finer | "
        "median s | CPU median s | mean s | p90 s | configurations checked, median | "
        + " | ".join(f"median / {name}'s" for name in references)
        + " |"
    )
    lines = [header, "| --- " * (8 + len(references)) + "|"]
    for name, row in table.items():
        ratios = [
            f"{row['median_s'] / table[ref]['median_s']:.2f} ({row['cpu_median_s'] / table[ref]['cpu_median_s']:.2f})"
            for ref in references
        ]
        lines.append(
            f"| {name} | {row['success_rate']:.0%} | {row['valid_rate']:.0%} | {row['median_s']:.4f} | "
            f"{row['cpu_median_s']:.4f} | {row['mean_s']:.4f} | {row['p90_s']:.4f} | {row['checks_median']:,.0f} | "
            + " | ".join(ratios)
            + " |"
        )
    for name, row in table.items():
        if "callback_us" in row:
            lines.append(
                f"\n{name}: a configuration took {row['callback_us']:.1f} us in its Python callbacks, "
                f"{row['batch_us']:.2f} us in one batched call (medians over the queries)."
            )
    return "\n".join(lines)
