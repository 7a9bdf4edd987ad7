"""Our planners against OMPL's, on the same queries and the same exact checker (``toolkit bench --vs-ompl``).

The paper measures prediction against its own exact PRM (§V, Table 3; Algorithm 1).
A gain over a slow baseline says little, so this race asks the question an OMPL user
would: is our exact planner, with or without prediction, faster than OMPL's PRM and
RRTConnect (Şucan, Moll, Kavraki 2012) on the same problem? A race takes four steps,
one function each:

1. :func:`race_queries` — the first ``n`` queries of the paper's set for a seed;
2. :func:`contenders` — the planners, each a :data:`Planner` callable: ours (the best
   exact planner, the paper's baseline, and with prediction) and OMPL's, through the
   adapter :mod:`toolkit.planning.ompl`;
3. :func:`race` — each planner solves each query from scratch, the planners in turns
   query by query (who goes first rotates, so that all see the same machine load),
   torch and BLAS on one thread; :func:`timed_solve` times one solve and re-checks
   its path;
4. :func:`summarize` — per planner: success, validity, times and checks.

:func:`versus_ompl` runs the four; :func:`versus_ompl_markdown` prints its table.

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
  for prediction; a query a planner does not solve counts the time it took.

Results and what they say: ``docs/benchmarks.md``, "Against OMPL (issue 18)".
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from toolkit.experiments import queries
from toolkit.experiments.problems import build, make_planner
from toolkit.experiments.queries import Query
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.training import TrainedModels
from toolkit.planning import prm
from toolkit.planning.local_planner import default_resolution, path_is_valid
from toolkit.planning.planner import Planner as Solver
from toolkit.scenarios import Scenario

# planner(query, exact, n) -> (success, path (P, dof) or None): solves query number n, exact deciding validity
Planner = Callable[[Query, CollisionChecker, int], tuple[bool, np.ndarray | None]]


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
        return result.success, result.path

    return solve


def ompl_planner(name: str, resolution: float, seconds: float) -> Planner:
    """OMPL's planner ``name`` (a class of ``ompl.geometric``) at our edge ``resolution``, ``seconds`` a query."""
    # toolkit.planning.ompl needs the optional extra: imported here, so that only a race needs it
    from toolkit.planning import ompl as toolkit_ompl

    def solve(query: Query, exact: CollisionChecker, n: int):
        result = toolkit_ompl.solve(
            exact, query.start, query.goal, planner=name, resolution=resolution, seconds=seconds
        )
        return result.success, result.path

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

    Ours: the best exact planner (the lazy PRM), the paper's baseline (Algorithm 1, ``PRMOptions``;
    unless ``paper_baseline`` is False) and, with ``models``, the planner paired with the model's
    preset with prediction (:mod:`toolkit.experiments.planners`, as ``bench.planning_ratios``
    plans). OMPL's: each of ``ompl_planners``.
    """
    best = make_planner(scenario, prm.DEFAULT)
    ours = {"ours, best exact": our_planner(best, scenario, sampler=sampler, seed=seed)}
    if paper_baseline:
        paper = make_planner(scenario, "paper")  # Algorithm 1
        ours["ours, paper's baseline"] = our_planner(paper, scenario, sampler=sampler, seed=seed)
    if models is not None:
        predicting = make_planner(scenario, preset=models.preset)
        ours[f"ours, with prediction ({models.preset.name})"] = our_planner(
            predicting, scenario, sampler=sampler, seed=seed, models=models
        )
    resolution = scenario.plan_resolution or default_resolution(scenario.robot)
    return {**ours, **{f"OMPL {name}": ompl_planner(name, resolution, ompl_seconds) for name in ompl_planners}}


def timed_solve(planner: Planner, query: Query, n: int, *, robot: BoxRobot, resolution: float) -> dict:
    """One solve from scratch: ``{"seconds", "success", "valid", "checks"}``.

    ``valid``: the path passes a fresh exact checker at ``resolution / 10``; ``checks``:
    configurations the planner's exact checker was asked about, clearance bounds included.
    """
    exact = exact_checker(query.workspace, robot)
    began = time.perf_counter()
    success, path = planner(query, exact, n)
    seconds = time.perf_counter() - began
    valid = bool(success) and path_is_valid(exact_checker(query.workspace, robot), path, resolution / 10)
    return {"seconds": seconds, "success": bool(success), "valid": valid, "checks": exact.n_checked + exact.n_bounded}


def race(scenario: Scenario, query_set: list[Query], racing: dict[str, Planner]) -> dict[str, list[dict]]:
    """Per planner, its :func:`timed_solve` of every query; the planners in turns query by query, the first of
    query ``n`` the ``n``-th (mod their count), on one thread (``queries.one_thread``).

    Each planner first solves the first query once, untimed, so that no timing includes a compiled
    kernel's first call (numba compiling or loading it: seconds) or torch's set-up.
    """
    resolution = scenario.plan_resolution or default_resolution(scenario.robot)
    solves: dict[str, list[dict]] = {name: [] for name in racing}
    names = list(racing)
    with queries.one_thread():
        for name in names if query_set else []:  # the untimed warm-up
            timed_solve(racing[name], query_set[0], 0, robot=scenario.robot, resolution=resolution)
        for n, query in enumerate(query_set):
            for name in names[n % len(names) :] + names[: n % len(names)]:
                solves[name].append(timed_solve(racing[name], query, n, robot=scenario.robot, resolution=resolution))
    return solves


def summarize(solves: dict[str, list[dict]]) -> dict[str, dict]:
    """Per planner: ``queries``, ``success_rate``, ``valid_rate`` (of the paths found; 1.0 when none was),
    ``median_s``, ``mean_s``, ``p90_s`` over all queries (a failure counts its time), ``checks_median``, and
    ``seconds`` (per query)."""
    table = {}
    for name, runs in solves.items():
        seconds = np.array([run["seconds"] for run in runs])  # (Q,)
        solved = np.array([run["success"] for run in runs])  # (Q,)
        valid = np.array([run["valid"] for run in runs])  # (Q,)
        table[name] = {
            "queries": len(runs),
            "success_rate": float(solved.mean()),
            "valid_rate": float(valid[solved].mean()) if solved.any() else 1.0,
            "median_s": float(np.median(seconds)),
            "mean_s": float(seconds.mean()),
            "p90_s": float(np.percentile(seconds, 90)),
            "checks_median": float(np.median([run["checks"] for run in runs])),
            "seconds": seconds.tolist(),
        }
    return table


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
) -> dict[str, dict]:
    """Our planners (:func:`contenders`) against OMPL's ``ompl_planners`` on the first ``n_queries`` of the paper's
    query set for ``seed``, raced in turns (:func:`race`): :func:`summarize`'s table.

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
    return summarize(race(scenario, query_set, racing))


def versus_ompl_markdown(scenario: Scenario, table: dict[str, dict]) -> str:
    """:func:`versus_ompl`'s table in markdown, with each planner's median over OMPL PRM's (over the first OMPL
    planner's when PRM did not run)."""
    reference = "OMPL PRM" if "OMPL PRM" in table else next((n for n in table if n.startswith("OMPL ")), None)
    if reference is None:
        raise ValueError(f"the table holds no OMPL planner to compare with: {list(table)}")
    reference_median = table[reference]["median_s"]
    header = (
        f"| {scenario.name} ({table[reference]['queries']} queries) | solved | valid at 10x finer | "
        f"median s | mean s | p90 s | configurations checked, median | median / {reference}'s |"
    )
    lines = [header, "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name, row in table.items():
        lines.append(
            f"| {name} | {row['success_rate']:.0%} | {row['valid_rate']:.0%} | {row['median_s']:.3f} | "
            f"{row['mean_s']:.3f} | {row['p90_s']:.3f} | {row['checks_median']:,.0f} | "
            f"{row['median_s'] / reference_median:.2f} |"
        )
    return "\n".join(lines)
