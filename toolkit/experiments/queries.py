"""Planning queries as in the paper (§IV-A) and running a sampler over them, with or without prediction.

2DS and 3DO: 10 workspaces x 10 start/goal pairs; 3DC: 100 workspaces x 1 pair
(``scenario.query_workspaces x scenario.queries_per_workspace``). Workspaces come
from the ``'query'`` stream of :meth:`toolkit.scenarios.Scenario.workspaces`; starts and goals are
uniform configurations the exact checker accepts, drawn from a generator derived
from ``(seed, workspace index)``, and at least a quarter of the region's diagonal
apart (base positions), so every query means travelling.

:func:`planner_options` gives a query's planner settings (the paper's |S|, the scenario's
resolution, and the planner the experiments pair with a model's recipe,
:mod:`~toolkit.experiments.planners`); :func:`default_options` does it for a learned checker.
``run_queries`` solves each query from scratch (a fresh roadmap, as in the paper),
with torch and numpy's BLAS on one thread (:func:`one_thread`), and summarizes: mean
and std of ``sampling_s`` and ``total_s`` (and their medians and quartiles), ``success_rate``, and
``path_valid_rate``, the fraction of returned paths that a fresh exact checker
accepts at 10x finer resolution than the local planner's. ``run_interleaved`` does
the same in several modes (without and with prediction) taking turns query by
query, so that the ratio of their times is measured under the same conditions; a
:class:`Mode` names what differs between them: the checker that decides samples,
the exact checker, the planner's settings.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from toolkit.experiments import planners
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.learning.learned import LearnedChecker
from toolkit.learning.presets import Preset
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.prm import PlanResult, PRMOptions, plan
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.scenarios import STREAMS, Scenario
from toolkit.util import threads

PAIR_STREAM = 1  # appended to the workspace's seed words: the start/goal pairs of query workspace i


@dataclass(frozen=True)
class Mode:
    """One way to plan a query set, for :func:`run_interleaved`: which checker decides samples (``checker(workspace)``;
    None: the exact one), which exact checker checks edges and paths (``exact(workspace, robot)``; default: the
    fastest, :func:`~toolkit.geometry.collision.exact_checker`), with which planner settings (None: the run's)."""

    checker: Callable[[Workspace], CollisionChecker] | None = None
    exact: Callable[[Workspace, BoxRobot], CollisionChecker] = exact_checker
    options: PRMOptions | None = None


@dataclass(frozen=True)
class Query:
    """One start/goal pair in workspace number ``workspace_index`` of the query stream."""

    workspace_index: int
    workspace: Workspace
    start: np.ndarray  # (dof,)
    goal: np.ndarray  # (dof,)


def query_pairs(
    scenario: Scenario, ws: Workspace, count: int, rng: np.random.Generator, *, min_separation: float = 0.25
) -> list[tuple[np.ndarray, np.ndarray]]:
    """``count`` (start, goal) pairs valid under the exact checker, base positions ``min_separation`` x diagonal
    apart."""
    robot, checker = scenario.robot, exact_checker(ws, scenario.robot)
    far = min_separation * float(np.linalg.norm(ws.upper - ws.lower))
    pairs: list[tuple[np.ndarray, np.ndarray]] = []
    for _ in range(1000):
        Q = robot.sample(rng, 256)  # (256, dof)
        Q = Q[checker.are_valid(Q)]
        for start, goal in zip(Q[0::2], Q[1::2]):
            if len(pairs) < count and np.linalg.norm(goal[: robot.dim] - start[: robot.dim]) >= far:
                pairs.append((start, goal))
        if len(pairs) == count:
            return pairs
    raise RuntimeError(f"could not find {count} valid, separated start/goal pairs in this workspace")


def default_options(scenario: Scenario, learned: CollisionChecker | None = None, **overrides) -> PRMOptions:
    """The planner settings of a query in ``scenario``: without a ``learned`` checker, the best exact planner (the lazy
    PRM) with the paper's |S| and the scenario's resolution; with a :class:`LearnedChecker`, the planner its model's
    preset is paired with (:mod:`toolkit.experiments.planners`: Algorithm 1 for ``paper``); with a predictor of your
    own, the lazy PRM. ``overrides``: fields of those options."""
    preset = learned.models.preset if isinstance(learned, LearnedChecker) else None
    return planner_options(scenario, preset, predicted=learned is not None, **overrides)


def planner_options(
    scenario: Scenario,
    preset: Preset | None = None,
    *,
    predicted: bool = False,
    options_class: type[PRMOptions] | None = None,
    **overrides,
) -> PRMOptions:
    """Options of the planner paired with ``preset`` (:mod:`~toolkit.experiments.planners`; None: the lazy PRM) or of
    ``options_class`` (``PRMOptions``: Algorithm 1): the paper's |S| and the scenario's resolution, the pairing's
    settings with the model when ``predicted``, then ``overrides`` (one the planner does not read is an error)."""
    paired = planners.Pairing() if preset is None else planners.pairing(preset)
    options_class = options_class or paired.options
    known = {f.name for f in fields(options_class)}
    settings: dict[str, Any] = {"n_samples": scenario.plan_samples, "resolution": scenario.plan_resolution}
    settings.update({name: value for name, value in paired.with_model.items() if predicted and name in known})
    if unknown := sorted(set(overrides) - known):
        raise ValueError(f"unknown planner option(s) {unknown}; {options_class.__name__} has {sorted(known)}")
    return options_class(**{**settings, **overrides})


def make_queries(
    scenario: Scenario, *, seed: int = 0, n_workspaces: int | None = None, per_workspace: int | None = None
) -> list[Query]:
    """The paper's query set (counts default to the scenario's), reproducible from ``seed``."""
    n_workspaces = scenario.query_workspaces if n_workspaces is None else n_workspaces
    per_workspace = scenario.queries_per_workspace if per_workspace is None else per_workspace
    queries = []
    for i, ws in enumerate(scenario.workspaces("query", n_workspaces, seed)):
        rng = np.random.default_rng([int(seed), STREAMS["query"], i, PAIR_STREAM])
        queries += [Query(i, ws, start, goal) for start, goal in query_pairs(scenario, ws, per_workspace, rng)]
    return queries


def solve_query(
    scenario: Scenario,
    query: Query,
    sampler: str,
    *,
    checker: CollisionChecker | None = None,
    options: PRMOptions | None = None,
    seed=0,
    exact: CollisionChecker | None = None,
) -> PlanResult:
    """One query with ``sampler``; ``checker`` decides samples (None: the exact checker); ``options`` by default
    :func:`default_options` of the scenario and the checker; ``exact``
    checks edges and paths (None: :func:`~toolkit.geometry.collision.exact_checker`)."""
    options = options or default_options(scenario, checker)
    return plan(
        exact or exact_checker(query.workspace, scenario.robot),
        query.start,
        query.goal,
        sampler=sampler,
        checker=checker,
        options=options,
        rng=np.random.default_rng(seed),
    )


def run_queries(
    scenario: Scenario,
    queries: list[Query],
    sampler: str,
    checker_factory: Callable[[Workspace], CollisionChecker] | None = None,
    *,
    options: PRMOptions | None = None,
    seed: int = 0,
) -> tuple[list[dict], dict]:
    """Solve every query with ``sampler``; ``checker_factory(workspace)`` gives the learned checker (None: exact).

    The factory runs once per workspace (it encodes the workspace: Algorithm 1,
    line 1); its time is shared among that workspace's queries and counted in their
    ``total_s``. ``options`` None: :func:`default_options` for each query's checker.
    Torch and numpy's BLAS run on one thread meanwhile (:func:`one_thread`). Returns
    per-query records and the summary.
    """
    return run_interleaved(scenario, queries, sampler, {"run": checker_factory}, options=options, seed=seed)["run"]


def run_interleaved(
    scenario: Scenario,
    queries: list[Query],
    sampler: str,
    factories: Mapping[str, Callable[[Workspace], CollisionChecker] | Mode | None],
    *,
    options: PRMOptions | None = None,
    seed: int = 0,
) -> dict[str, tuple[list[dict], dict]]:
    """:func:`run_queries` once per entry of ``factories`` (a name: a checker factory, None for exact, or a
    :class:`Mode`, whose own options replace ``options``), the entries taking turns query by query (who goes
    first rotates), each query with the same seed in every entry.

    So all entries see the machine alike: a shared machine changes speed for minutes
    at a time, which moves the ratio of two runs made one
    after the other, not that of runs made in turns. Per name: records and summary.
    """
    with one_thread():
        records = _solve_all(scenario, queries, sampler, factories, options=options, seed=seed)
    return {name: (runs, summarize(runs)) for name, runs in records.items()}


def one_thread():
    """Torch and numpy's BLAS on one thread inside (the previous counts restored after): how queries are timed,
    whatever ``TOOLKIT_THREADS`` says, so that times from different runs compare (:mod:`toolkit.util.threads`).

    The exact checker's own work runs on one thread; the learned checker's calls are
    small (a few hundred to a few ten thousand configurations), where intra-op threads
    cost more than they give and, when the other core is busy, stall (measured in
    ``docs/benchmarks.md``, "On a busy machine").
    """
    return threads.limited(1)


def _solve_all(
    scenario: Scenario,
    queries: list[Query],
    sampler: str,
    factories: Mapping[str, Callable[[Workspace], CollisionChecker] | Mode | None],
    *,
    options: PRMOptions | None,
    seed: int,
) -> dict[str, list[dict]]:
    """The per-query records of :func:`run_interleaved`, per name.

    Before anything is timed, each mode solves the first query once, untimed: the first call of a compiled
    kernel in a process compiles it or loads it from numba's cache (seconds on a fresh machine: 5.16 s against
    a median query of 7.5 ms once moved Table 3's mean by +59 to +77 %, issue 51), and torch sets up its first
    call. That solve is discarded; the timed loop starts warm.
    """
    modes = {name: entry if isinstance(entry, Mode) else Mode(entry) for name, entry in factories.items()}
    names = list(modes)
    records: dict[str, list[dict]] = {name: [] for name in names}
    checkers: dict[str, dict] = {name: {} for name in names}  # per name: workspace index -> checker
    share = np.bincount([q.workspace_index for q in queries])  # queries per workspace
    for mode in modes.values():  # the untimed warm-up
        if queries:
            warm = mode.checker(queries[0].workspace) if mode.checker is not None else None
            _solve_and_verify(scenario, queries[0], sampler, mode, warm, options=options, seed=[int(seed), 0])
    for n, query in enumerate(queries):
        turn = n % len(names)
        for name in names[turn:] + names[:turn]:
            encode_s, mode, built = 0.0, modes[name], checkers[name]
            if mode.checker is not None and query.workspace_index not in built:
                began = time.perf_counter()
                built[query.workspace_index] = mode.checker(query.workspace)
                encode_s = (time.perf_counter() - began) / share[query.workspace_index]
            record = _solve_and_verify(
                scenario, query, sampler, mode, built.get(query.workspace_index), options=options, seed=[int(seed), n]
            )
            records[name].append(dict(record, encode_s=encode_s, total_s=record["total_s"] + encode_s))
    return records


def _solve_and_verify(
    scenario: Scenario,
    query: Query,
    sampler: str,
    mode: Mode,
    checker: CollisionChecker | None,
    *,
    options: PRMOptions | None,
    seed: list[int],
) -> dict:
    """One query solved in ``mode`` with ``checker`` deciding samples: the planner's stats, ``success``, and
    ``path_valid`` (the path accepted by a fresh exact checker at a tenth of the planner's resolution)."""
    result = solve_query(
        scenario,
        query,
        sampler,
        checker=checker,
        options=mode.options or options,
        seed=seed,
        exact=mode.exact(query.workspace, scenario.robot),
    )
    fine = result.stats["resolution"] / 10
    valid = result.success and path_is_valid(exact_checker(query.workspace, scenario.robot), result.path, fine)
    return dict(result.stats, workspace=query.workspace_index, success=result.success, path_valid=bool(valid))


TIMES = ("sampling_s", "connection_s", "query_s", "encode_s", "total_s")  # a query's times, in seconds
STAGES = ("sampling_s", "connection_s", "query_s")  # the parts of total_s the planner times (the rest: set-up)


def summarize(records: list[dict]) -> dict:
    """Means and stds over queries of the times and counts, medians and quartiles (``_q1``, ``_q3``) of the times,
    each query's total, each stage's mean share of a query's total (``_share``); success and path-validity rates
    in [0, 1]."""

    def values(key):
        return np.array([r[key] for r in records], dtype=float)

    summary: dict[str, float] = {"n_queries": len(records)}
    for key in (
        "sampling_s",
        "connection_s",
        "query_s",
        "total_s",
        "encode_s",
        "exact_checks",
        "predicted_checks",
        "rounds",
        "repairs",
    ):
        summary[key] = float(values(key).mean()) if records else 0.0
        summary[key + "_std"] = float(values(key).std()) if records else 0.0
    for key in TIMES:  # robust to the odd slow query on a noisy machine: median and quartiles
        q1, median, q3 = np.percentile(values(key), (25, 50, 75)) if records else (0.0, 0.0, 0.0)
        summary.update({key + "_median": float(median), key + "_q1": float(q1), key + "_q3": float(q3)})
    summary["total_s_per_query"] = values("total_s").tolist()  # in the order of the queries: names an outlier
    for key in STAGES:  # where a typical query's time goes: each stage's share of a query's total, averaged
        summary[key + "_share"] = float(np.mean(values(key) / np.maximum(values("total_s"), 1e-12))) if records else 0.0
    solved = [r for r in records if r["success"]]
    summary["success_rate"] = len(solved) / len(records) if records else 0.0
    summary["path_valid_rate"] = float(np.mean([r["path_valid"] for r in solved])) if solved else 1.0
    return summary


def compare_prediction(
    scenario: Scenario,
    queries: list[Query],
    checker_factory: Callable[[Workspace], CollisionChecker] | Mode,
    *,
    samplers=PAPER_SAMPLERS,
    options: PRMOptions | None = None,
    seed: int = 0,
) -> dict:
    """Per sampler: ``{"without": summary, "with": summary, "sampling_ratio", "total_ratio"}`` (with / without),
    the two modes in turns (:func:`run_interleaved`); "without" plans with ``options``, "with" with
    ``checker_factory`` (a :class:`Mode` brings its own options)."""
    table = {}
    for sampler in samplers:
        modes = {"without": None, "with": checker_factory}
        runs = run_interleaved(scenario, queries, sampler, modes, options=options, seed=seed)
        without, with_ = runs["without"][1], runs["with"][1]
        table[sampler] = {
            "without": without,
            "with": with_,
            "sampling_ratio": with_["sampling_s"] / max(without["sampling_s"], 1e-12),
            "total_ratio": with_["total_s"] / max(without["total_s"], 1e-12),
        }
    return table
