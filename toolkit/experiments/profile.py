"""Where a query's time goes: the best exact planner's time by stage (``toolkit bench --profile``).

A planner's speed is the sum of many small steps; to make one faster, first measure which.
:func:`profile` solves the first ``n`` queries of the paper's set (as ``toolkit bench --vs-ompl``
does: the lazy PRM, sampler BS, one thread, query ``n`` drawing from ``default_rng([seed, n])``),
each with a fresh exact checker, and times, per query, the methods of each stage
(:data:`PROFILE_STAGES`) while it runs, in subclasses of the planner, its query and its roadmap
made for the purpose (:meth:`StageClock.timed_planner`; no library class is changed):

- ``set-up``: building the exact checker for the query's workspace (``exact_checker``);
- ``sampling``: a round's samples, checked (``PRM.sample_round``);
- ``neighbours``: k-nearest and bridging candidates (``Roadmap.candidate_edges``, ``bridge_edges``);
- ``edge checks``: deciding candidate edges (the planner's ``decide``);
- ``search``: shortest paths and components (``Roadmap.shortest_path``, ``component``);
- ``verification``: confirming a candidate path exactly and repairing it (``QueryRoadmap.verified_path``);
- ``roadmap``: adding and removing nodes and edges (``Roadmap.add_nodes``, ``add_edges``, ...);
- ``python around``: the rest of the call (the planner's loop, counters, copies).

Stages are timed exclusively (a search inside verification counts as search), so they sum to
the query's time; the exact checker's own calls (``validity``, ``clearance_bounds``) are timed
too and reported as the part of each stage spent inside the checker. The timers cost about a
microsecond a call, a few hundred calls a query. Results: ``docs/benchmarks.md``, "Where a
query's time goes".
"""

from __future__ import annotations

import time

import numpy as np

from toolkit.experiments import queries, versus_ompl
from toolkit.experiments.problems import build, make_planner
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.planning import prm
from toolkit.planning.planner import Planner
from toolkit.planning.query_roadmap import QueryRoadmap
from toolkit.planning.roadmap import Roadmap
from toolkit.scenarios import Scenario

PLANNER_METHODS = {"sample_round": "sampling", "decide": "edge checks"}  # a roadmap planner's, by stage
QUERY_METHODS = {"verified_path": "verification"}  # QueryRoadmap's
ROADMAP_METHODS = {
    "candidate_edges": "neighbours",
    "bridge_edges": "neighbours",
    "shortest_path": "search",
    "component": "search",
    **dict.fromkeys(("add_nodes", "add_edges", "reject", "remove_edges", "remove_nodes"), "roadmap"),
}
PROFILE_STAGES = ("sampling", "neighbours", "edge checks", "search", "verification", "roadmap")  # in this order
CHECKER_METHODS = ("validity", "clearance_bounds")  # the exact checker's own work
AROUND = "python around"  # what no stage's methods cover


class StageClock:
    """Exclusive seconds per stage and seconds inside the checker per stage, for the planner and checker it times
    (:meth:`timed_planner`, :meth:`time_checker`): subclasses and instances of its own, no library class changed."""

    def __init__(self):
        self.seconds: dict[str, float] = {}
        self.checker: dict[str, float] = {}
        self._stack: list[list] = [[AROUND, 0.0]]  # [stage, seconds of nested stages] per open call

    def _timed(self, stage: str | None, method):
        """``method`` timed into ``stage`` (None: the checker's time, into the enclosing stage)."""

        def timed(*args, **kwargs):
            if stage is None:
                began = time.perf_counter()
                try:
                    return method(*args, **kwargs)
                finally:
                    outer = self._stack[-1][0]
                    self.checker[outer] = self.checker.get(outer, 0.0) + time.perf_counter() - began
            self._stack.append([stage, 0.0])
            began = time.perf_counter()
            try:
                return method(*args, **kwargs)
            finally:
                elapsed = time.perf_counter() - began
                _, nested = self._stack.pop()
                self.seconds[stage] = self.seconds.get(stage, 0.0) + elapsed - nested
                self._stack[-1][1] += elapsed

        return timed

    def timed_class(self, cls: type, methods: dict[str, str], **attributes) -> type:
        """A subclass of ``cls`` whose ``methods`` (name -> stage) are timed, with ``attributes`` set."""
        timed = {name: self._timed(stage, getattr(cls, name)) for name, stage in methods.items() if hasattr(cls, name)}
        return type(f"Timed{cls.__name__}", (cls,), {**timed, **attributes})

    def timed_planner(self, planner: Planner) -> Planner:
        """A copy of the roadmap ``planner`` (its parameters) whose stages are timed: its class, its query's and its
        roadmap's, subclassed."""
        roadmap = self.timed_class(Roadmap, ROADMAP_METHODS)
        query = self.timed_class(QueryRoadmap, QUERY_METHODS, roadmap_class=roadmap)
        return self.timed_class(type(planner), PLANNER_METHODS, query_class=query)(planner.params)

    def time_checker(self, checker: CollisionChecker) -> None:
        """Time this ``checker``'s own work (:data:`CHECKER_METHODS`, instance attributes: its class unchanged)."""
        for name in CHECKER_METHODS:
            setattr(checker, name, self._timed(None, getattr(checker, name)))


def profile(scenario: Scenario, *, n_queries: int = 10, seed: int = 9100, sampler: str = "BS") -> dict:
    """Per query and stage, milliseconds (``queries``: a list of ``{"total_ms", "setup_ms", "stages_ms",
    "checker_ms"}``), after one untimed warm-up solve (numba loads its compiled kernels once a process); and
    :func:`summary` of them."""
    query_set = versus_ompl.race_queries(scenario, n_queries, seed)
    solver, robot, records = make_planner(scenario, prm.DEFAULT), scenario.robot, []
    with queries.one_thread():
        build(scenario, query_set[0], sampler=sampler, planner=solver).solve(np.random.default_rng([seed, 0]))
        for n, query in enumerate(query_set):
            began = time.perf_counter()
            exact = exact_checker(query.workspace, robot)
            setup = time.perf_counter() - began
            clock = StageClock()
            clock.time_checker(exact)
            task = build(scenario, query, sampler=sampler, planner=clock.timed_planner(solver), exact=exact)
            began = time.perf_counter()
            result = task.solve(np.random.default_rng([seed, n]))
            total = time.perf_counter() - began
            stages = dict(clock.seconds)
            stages[AROUND] = total - sum(s for name, s in stages.items() if name != AROUND)
            records.append(
                {
                    "success": result.success,
                    "total_ms": 1e3 * total,
                    "setup_ms": 1e3 * setup,
                    "stages_ms": {name: 1e3 * s for name, s in stages.items()},
                    "checker_ms": {name: 1e3 * s for name, s in clock.checker.items()},
                }
            )
    return {"scenario": scenario.name, "seed": seed, "queries": records, "summary": summary(records)}


def summary(records: list[dict]) -> dict:
    """Medians over queries: ``query_ms`` (the plan call), ``setup_ms``, ``setup_over_query``, and per stage
    (set-up first) ``{"median_ms", "share", "checker_share"}``: its share of the summed time of all queries (set-up
    included) and the part of it spent inside the exact checker."""
    names = ["set-up", *PROFILE_STAGES, AROUND]
    per_stage = {name: np.array([r["stages_ms"].get(name, 0.0) for r in records]) for name in names[1:]}
    per_stage["set-up"] = np.array([r["setup_ms"] for r in records])
    checker = {name: sum(r["checker_ms"].get(name, 0.0) for r in records) for name in names}
    grand = sum(float(v.sum()) for v in per_stage.values())
    query_ms = float(np.median([r["total_ms"] for r in records]))
    setup_ms = float(np.median(per_stage["set-up"]))
    return {
        "query_ms": query_ms,
        "setup_ms": setup_ms,
        "setup_over_query": setup_ms / query_ms,
        "checker_share": sum(checker.values()) / grand,
        "solved": float(np.mean([r["success"] for r in records])),
        "stages": {
            name: {
                "median_ms": float(np.median(per_stage[name])),
                "share": float(per_stage[name].sum()) / grand,
                "checker_share": checker[name] / max(float(per_stage[name].sum()), 1e-12),
            }
            for name in names
        },
    }


def markdown(result: dict) -> str:
    """:func:`profile`'s summary as a markdown table and a line of totals."""
    s = result["summary"]
    lines = [
        f"| {result['scenario']}, seed {result['seed']} ({len(result['queries'])} queries) | median ms | share of "
        "all time | of which in the exact checker |",
        "| --- | --- | --- | --- |",
    ]
    for name, row in s["stages"].items():
        lines.append(f"| {name} | {row['median_ms']:.2f} | {row['share']:.0%} | {row['checker_share']:.0%} |")
    lines.append(
        f"\nquery (plan call) median {s['query_ms']:.2f} ms; set-up median {s['setup_ms']:.2f} ms = "
        f"{s['setup_over_query']:.2f}x a query; {s['checker_share']:.0%} of all time inside the exact checker; "
        f"solved {s['solved']:.0%}"
    )
    return "\n".join(lines)
