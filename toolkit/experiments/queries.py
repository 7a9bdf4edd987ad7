"""Running a planner over a query set, with or without prediction, in turns (§IV-A, Table 3).

The query sets are :mod:`~toolkit.experiments.query_sets` (``make_queries``, also importable from
here); each query is built by :func:`toolkit.experiments.problems.build`; the records are
summarized by :mod:`~toolkit.experiments.summaries`. ``run_queries`` solves each query from
scratch (a fresh roadmap, as in the paper), with torch and numpy's BLAS on one thread
(:func:`one_thread`); ``path_valid`` is whether a fresh exact checker accepts the returned path at
the problem's finer resolution. ``run_interleaved`` does the same in several modes (without and
with prediction) taking turns query by query, so that the ratio of their times is measured under
the same conditions; a :class:`Mode` names what differs between them: the checker that decides
samples, the exact checker, the planner (with its parameters). Modes without a planner of their
own all run the run's ``planner``: "with / without prediction" then differs in the checker only.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from toolkit.experiments.problems import build, make_planner
from toolkit.experiments.query_sets import Query, make_queries, query_pairs
from toolkit.experiments.summaries import summarize
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.planner import Planner, PlanResult
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.scenarios import Scenario
from toolkit.util import threads

__all__ = [  # make_queries, query_pairs, Query and summarize are imported by old callers from here too
    "Mode",
    "Query",
    "compare_prediction",
    "make_queries",
    "one_thread",
    "query_pairs",
    "run_interleaved",
    "run_queries",
    "solve_query",
    "summarize",
]


@dataclass(frozen=True)
class Mode:
    """One way to plan a query set, for :func:`run_interleaved`: which checker decides samples (``checker(workspace)``;
    None: the exact one), which exact checker checks edges and paths (``exact(workspace, robot)``; default: the
    fastest, :func:`~toolkit.geometry.collision.exact_checker`), with which planner (None: the run's)."""

    checker: Callable[[Workspace], CollisionChecker] | None = None
    exact: Callable[[Workspace, BoxRobot], CollisionChecker] = exact_checker
    planner: Planner | None = None


def solve_query(
    scenario: Scenario,
    query: Query,
    sampler: str,
    *,
    checker: CollisionChecker | None = None,
    planner: str | Planner | None = None,
    seed=0,
    exact: CollisionChecker | None = None,
) -> PlanResult:
    """One query with ``sampler`` and ``planner`` (a name or one made; None: ``toolkit.planning.prm.DEFAULT``);
    ``checker`` decides samples (None: the exact checker); ``exact`` checks edges and paths (None:
    :func:`~toolkit.geometry.collision.exact_checker`)."""
    task = build(scenario, query, sampler=sampler, planner=planner, checker=checker, exact=exact)
    return task.solve(np.random.default_rng(seed))


def run_queries(
    scenario: Scenario,
    queries: list[Query],
    sampler: str,
    checker_factory: Callable[[Workspace], CollisionChecker] | None = None,
    *,
    planner: Planner | None = None,
    seed: int = 0,
) -> tuple[list[dict], dict]:
    """Solve every query with ``sampler`` and ``planner`` (None: the default, with the scenario's |S|);
    ``checker_factory(workspace)`` gives the learned checker (None: exact).

    The factory runs once per workspace (it encodes the workspace: Algorithm 1,
    line 1); its time is shared among that workspace's queries and counted in their
    ``total_s``. Torch and numpy's BLAS run on one thread meanwhile (:func:`one_thread`).
    Returns per-query records and the summary.
    """
    return run_interleaved(scenario, queries, sampler, {"run": checker_factory}, planner=planner, seed=seed)["run"]


def run_interleaved(
    scenario: Scenario,
    queries: list[Query],
    sampler: str,
    factories: Mapping[str, Callable[[Workspace], CollisionChecker] | Mode | None],
    *,
    planner: Planner | None = None,
    seed: int = 0,
) -> dict[str, tuple[list[dict], dict]]:
    """:func:`run_queries` once per entry of ``factories`` (a name: a checker factory, None for exact, or a
    :class:`Mode`, whose own planner replaces ``planner``), the entries taking turns query by query (who goes
    first rotates), each query with the same seed in every entry.

    So all entries see the machine alike: a shared machine changes speed for minutes
    at a time, which moves the ratio of two runs made one
    after the other, not that of runs made in turns. Per name: records and summary.
    """
    planner = planner or make_planner(scenario)
    modes = {name: entry if isinstance(entry, Mode) else Mode(entry) for name, entry in factories.items()}
    modes = {name: mode if mode.planner else Mode(mode.checker, mode.exact, planner) for name, mode in modes.items()}
    with one_thread():
        records = _solve_all(scenario, queries, sampler, modes, seed=seed)
    return {name: (runs, summarize(runs)) for name, runs in records.items()}


def one_thread():
    """Torch and numpy's BLAS on one thread inside (the previous counts restored after): how queries are timed,
    whatever ``TOOLKIT_THREADS`` says, so that times from different runs compare (:mod:`toolkit.util.threads`).

    The exact checker's own work runs on one thread; the learned checker's calls are
    small (a few hundred to a few ten thousand configurations), where intra-op threads
    cost more than they give and, when the other core is busy, stall (measured in
    ``tutorials/instructors.md``, "On a busy machine").
    """
    return threads.limited(1)


def _solve_all(
    scenario: Scenario, queries: list[Query], sampler: str, modes: Mapping[str, Mode], *, seed: int
) -> dict[str, list[dict]]:
    """The per-query records of :func:`run_interleaved`, per name.

    Before anything is timed, each mode solves the first query once, untimed: the first call of a compiled
    kernel in a process compiles it or loads it from numba's cache (seconds on a fresh machine: 5.16 s against
    a median query of 7.5 ms once moved Table 3's mean by +59 to +77 %, issue 51), and torch sets up its first
    call. That solve is discarded; the timed loop starts warm.
    """
    names = list(modes)
    records: dict[str, list[dict]] = {name: [] for name in names}
    checkers: dict[str, dict] = {name: {} for name in names}  # per name: workspace index -> checker
    share = np.bincount([q.workspace_index for q in queries])  # queries per workspace
    for mode in modes.values():  # the untimed warm-up
        if queries:
            warm = mode.checker(queries[0].workspace) if mode.checker is not None else None
            _solve_and_verify(scenario, queries[0], sampler, mode, warm, seed=[int(seed), 0])
    for n, query in enumerate(queries):
        turn = n % len(names)
        for name in names[turn:] + names[:turn]:
            encode_s, mode, built = 0.0, modes[name], checkers[name]
            if mode.checker is not None and query.workspace_index not in built:
                began = time.perf_counter()
                built[query.workspace_index] = mode.checker(query.workspace)
                encode_s = (time.perf_counter() - began) / share[query.workspace_index]
            record = _solve_and_verify(
                scenario, query, sampler, mode, built.get(query.workspace_index), seed=[int(seed), n]
            )
            records[name].append(dict(record, encode_s=encode_s, total_s=record["total_s"] + encode_s))
    return records


def _solve_and_verify(
    scenario: Scenario, query: Query, sampler: str, mode: Mode, checker: CollisionChecker | None, *, seed: list[int]
) -> dict:
    """One query solved in ``mode`` with ``checker`` deciding samples: the planner's stats, its name, ``success``,
    and ``path_valid`` (the path accepted by a fresh exact checker at the problem's finer resolution)."""
    task = build(scenario, query, sampler=sampler, planner=mode.planner, checker=checker, exact=mode.exact)
    result = task.solve(np.random.default_rng(seed))
    fresh = exact_checker(query.workspace, scenario.robot)
    valid = result.success and path_is_valid(fresh, result.path, task.problem.fine_resolution)
    return dict(
        result.stats, planner=result.planner, workspace=query.workspace_index, success=result.success, path_valid=valid
    )


def compare_prediction(
    scenario: Scenario,
    queries: list[Query],
    checker_factory: Callable[[Workspace], CollisionChecker] | Mode,
    *,
    samplers=PAPER_SAMPLERS,
    planner: Planner | None = None,
    seed: int = 0,
) -> dict:
    """Per sampler: ``{"without": summary, "with": summary, "sampling_ratio", "total_ratio"}`` (with / without),
    the two modes in turns (:func:`run_interleaved`), both with ``planner`` (None: the default) unless
    ``checker_factory`` is a :class:`Mode` with a planner of its own."""
    table = {}
    for sampler in samplers:
        modes = {"without": None, "with": checker_factory}
        runs = run_interleaved(scenario, queries, sampler, modes, planner=planner, seed=seed)
        without, with_ = runs["without"][1], runs["with"][1]
        table[sampler] = {
            "without": without,
            "with": with_,
            "sampling_ratio": with_["sampling_s"] / max(without["sampling_s"], 1e-12),
            "total_ratio": with_["total_s"] / max(without["total_s"], 1e-12),
        }
    return table
