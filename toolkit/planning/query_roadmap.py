"""One query's roadmap: what the paper's PRM and the lazy PRM share (§III-B, Algorithm 1, lines 4-5).

A :class:`QueryRoadmap` holds the state of one query, a
:class:`~toolkit.planning.planner.Problem` (its exact checker, the checker that decides samples,
the sampler drawn through either, the resolution): the
:class:`~toolkit.planning.roadmap.Roadmap`, counters and timers (``stats``) and,
when asked, a trace of :class:`PlanStep` snapshots. It does the steps that both planners take
alike; the planner supplies its *edge rule* (``decide(pairs)``: which candidate edges enter the
roadmap, and how they were checked):

- **connect** (line 4, in the planner's ``solve``): each new node with its ``k`` nearest
  neighbours (``Roadmap.candidate_edges``); then, while start and goal lie in different
  components, the ``k`` closest pairs between each one's component and the rest
  (:meth:`bridge`, :meth:`~toolkit.planning.roadmap.Roadmap.bridge_edges`);
- **extract and verify** (line 5, "the path is extracted and verified"): the cheapest start-goal
  path, checked by the exact checker: its nodes, then its edges at the roadmap's ``resolution``
  (unless checked exactly when they were added) and at ``problem.fine_resolution`` (10x
  finer: shortest paths hug obstacles, and an edge that grazes a corner between two checks at
  ``resolution`` is caught here). Whatever fails is removed from the roadmap (a *repair*) and the
  next cheapest path is tried. Each edge remembers the finest resolution it passed at
  (``Roadmap.edge_checked_at``), so a later candidate re-checks none of them. Edges are verified
  with clearance certificates (``local_planner.certify_edges``: the same answer as checking every
  point, but a stretch whose ends are far enough from every obstacle needs no check) where the
  checker's clearances pay for themselves. A screened edge is first looked at in the one point
  where prediction saw it fail (``Roadmap.edge_suspect``, ``local_planner.refute_at``).
- **bridge again**: while repairs leave start and goal apart (or the bridges failed), the
  closest pairs not yet tried (the roadmap remembers rejected pairs), up to ``rebridge`` times,
  before the planner samples another round.

A returned path is valid under the exact checker at both resolutions; otherwise ``success`` is
False. ``trace=[]`` collects a :class:`PlanStep` at every stage (``STAGES``), e.g. to draw the
roadmap as it grows and is repaired (notebook 04); snapshots cost copies: time a planner without.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from toolkit.planning import sampling
from toolkit.planning.local_planner import certify_edges, check_edges, refute_at
from toolkit.planning.options import RoadmapParams
from toolkit.planning.planner import PlanResult, Problem
from toolkit.planning.roadmap import Roadmap

START, GOAL = 0, 1  # node indices of the query's endpoints (never removed)

STAGES = {  # PlanStep.stage: what the planner just did (Algorithm 1, §III-B)
    "sample": "added this round's accepted samples S' as nodes (lines 2-3; round 1 also start and goal)",
    "connect": "tried edges to each new node's k nearest neighbours, then bridges between start's and goal's "
    "components (line 4): checked exactly (the paper), screened by prediction, or, lazy, looked at in a "
    "few points",
    "bridge": "after repairs left start and goal apart, tried the next closest pairs between their components",
    "candidate": "found the cheapest start-goal path, not yet verified (line 5)",
    "repair": "the exact checker rejected the candidate's removed_nodes or removed_edges; they are removed next",
    "path": "the exact checker confirmed the candidate's nodes and edges at both resolutions: the answer",
}

EdgeRule = Callable[[np.ndarray], None]  # decide(pairs (C, 2)): add the accepted edges, reject the others


@dataclass(frozen=True)
class PlanStep:
    """A snapshot of the roadmap after one stage of the planner (``STAGES``), for ``plan(..., trace=[])``.

    Indices refer to this snapshot's ``nodes`` and ``edges``: a repair removes nodes and
    so shifts the indices of later ones in the steps after it.
    """

    stage: str  # a key of STAGES
    round: int  # the sampling round (1, 2, ...)
    nodes: np.ndarray  # (V, dof)
    node_verified: np.ndarray  # (V,) bool: confirmed by the exact checker
    edges: np.ndarray  # (E, 2) node indices, i < j
    new_nodes: np.ndarray  # (M,) the nodes this stage added ("sample"); empty otherwise
    path: np.ndarray  # (P,) node indices of the candidate path ("candidate", "repair", "path"); empty otherwise
    removed_nodes: np.ndarray  # (R,) nodes the exact checker rejected ("repair"); empty otherwise
    removed_edges: np.ndarray  # (R,) indices into edges the exact checker rejected ("repair"); empty otherwise


class QueryRoadmap:
    """The state of one query: the problem, the planner's parameters, roadmap, counters and timers, the trace."""

    roadmap_class = Roadmap  # the roadmap (a subclass: e.g. timed, toolkit.experiments.profile)

    def __init__(self, problem: Problem, params: RoadmapParams, trace: list | None = None):
        self.problem, self.params, self.trace = problem, params, trace
        self.exact, self.checker, self.predicted = problem.exact, problem.checker, problem.predicts
        self.resolution = problem.resolution
        # a path's edges are confirmed at the roadmap's resolution (where most that fail, fail; exactly checked
        # edges already were), then finer
        self.verify_resolutions = (self.resolution, problem.fine_resolution)
        # the sampler (its name checked by Problem.create) drawing through the deciding checker, and the exact one
        sampler = sampling.SAMPLERS[problem.sampler]  # the registry as it is now
        self.sampler = sampler(self.checker)
        self.exact_sampler = sampler(self.exact) if self.predicted else self.sampler
        self.roadmap = self.roadmap_class(self.exact.robot)
        self.stats: dict[str, float] = {  # counts (ints) and seconds
            "rounds": 0,
            "repairs": 0,
            "rebridges": 0,
            "removed_nodes": 0,
            "removed_edges": 0,
            "sampling_s": 0.0,
            "connection_s": 0.0,
            "query_s": 0.0,
            "node_checks": 0,
            "edge_checks": 0,
            "verify_checks": 0,
        }
        self.began = time.perf_counter()
        self.counts_at_start, self.bounded_at_start = self.counts(), self.exact.n_bounded

    def add_endpoints(self) -> np.ndarray:
        """Add the problem's ``start`` and ``goal`` (checked exactly) as nodes ``START`` and ``GOAL``; returns
        their indices."""
        endpoints = np.stack([self.problem.start, self.problem.goal])  # (2, dof)
        for name, ok, q in zip(("start", "goal"), self.exact.are_valid(endpoints), endpoints):
            if not ok:
                raise ValueError(f"{name} configuration {np.round(q, 4).tolist()} is in collision or out of bounds")
        return self.roadmap.add_nodes(endpoints, verified=True)

    def record(self, stage: str, *, new_nodes=(), path=(), removed_nodes=(), removed_edges=()) -> None:
        """Append a :class:`PlanStep` of the roadmap as it is now to the trace (if tracing)."""
        if self.trace is None:
            return
        roadmap, indices = self.roadmap, lambda a: np.array(a, dtype=int)
        self.trace.append(
            PlanStep(
                stage,
                int(self.stats["rounds"]),
                roadmap.nodes.copy(),
                roadmap.node_verified.copy(),
                roadmap.edges.copy(),
                indices(new_nodes),
                indices(path),
                indices(removed_nodes),
                indices(removed_edges),
            )
        )

    def counts(self) -> tuple[int, int]:
        """Configurations checked so far: (exact, predicted); a second exact checker deciding samples counts as
        exact."""
        deciding = self.checker.n_checked if self.checker is not self.exact else 0  # (not the same counter twice)
        return self.exact.n_checked + (0 if self.predicted else deciding), deciding if self.predicted else 0

    @contextmanager
    def timed(self, seconds_key: str, checks_key: str):
        """Add the block's seconds and configurations checked to ``stats[seconds_key]`` and ``stats[checks_key]``."""
        before, start = sum(self.counts()), time.perf_counter()
        yield
        self.stats[seconds_key] += time.perf_counter() - start
        self.stats[checks_key] += sum(self.counts()) - before

    def bridge(self, decide: EdgeRule) -> int:
        """While start and goal lie apart, try the closest untried pairs from each one's component; edges added."""
        roadmap, before = self.roadmap, len(self.roadmap.edges)
        for end in (START, GOAL):
            if not roadmap.component(START)[GOAL]:
                decide(roadmap.bridge_edges(end, self.params.k))
        return len(roadmap.edges) - before

    def add_decided(
        self,
        pairs: np.ndarray,
        keep: np.ndarray,
        cost: np.ndarray,
        *,
        checked_at: float = np.inf,
        suspect: np.ndarray | None = None,
    ) -> None:
        """Add the candidate edges ``pairs[keep]`` (``pairs (C, 2)``, ``keep``, ``cost`` and ``suspect (C,)``: see
        ``Roadmap.add_edges``) and remember the others as rejected."""
        self.roadmap.add_edges(
            pairs[keep], cost[keep], checked_at=checked_at, suspect=None if suspect is None else suspect[keep]
        )
        self.roadmap.reject(pairs[~keep])

    def extract_path(self, decide: EdgeRule) -> np.ndarray | None:
        """Node indices of a start-goal path the exact checker confirms (repairing the roadmap), bridging again up to
        ``rebridge`` times while repairs leave start and goal apart; None if none."""
        with self.timed("query_s", "verify_checks"):
            path = self.verified_path()
        bridges = 0
        while path is None and bridges < self.params.rebridge:  # still apart: the next closest pairs
            bridges += 1
            self.stats["rebridges"] += 1
            with self.timed("connection_s", "edge_checks"):
                if not self.bridge(decide):
                    break
            self.record("bridge")
            with self.timed("query_s", "verify_checks"):
                path = self.verified_path()
        return path

    def verified_path(self) -> np.ndarray | None:
        """Node indices of the cheapest start-goal path the exact checker confirms, repairing the roadmap; None if
        none."""
        roadmap = self.roadmap
        while (path := roadmap.shortest_path(START, GOAL)) is not None:
            self.record("candidate", path=path)
            unsure = path[~roadmap.node_verified[path]]
            ok = self.exact.are_valid(roadmap.nodes[unsure]) if len(unsure) else np.zeros(0, bool)
            roadmap.node_verified[unsure[ok]] = True
            if not ok.all():
                self.repair(path, nodes=unsure[~ok])
                continue
            failed = self.failed_edges(path)
            if len(failed):
                self.repair(path, edges=failed)
                continue
            self.record("path", path=path)
            return path
        return None

    def failed_edges(self, path: np.ndarray) -> np.ndarray:
        """Indices of the edges of ``path`` that fail exactly at the first verification resolution that fails any
        (empty: all pass at both); each passed edge remembers it."""
        roadmap = self.roadmap
        steps = roadmap.edge_index(path)
        for resolution in self.verify_resolutions:
            unsure = steps[roadmap.edge_checked_at[steps] > resolution]
            Q0, Q1 = roadmap.nodes[roadmap.edges[unsure].T]
            suspect = roadmap.edge_suspect[unsure]
            if resolution == self.resolution and np.isfinite(suspect).any():  # where screening saw edges fail
                refuted = refute_at(self.exact, Q0, Q1, suspect, resolution)  # one exact check each, first
                roadmap.edge_suspect[unsure] = np.nan  # looked at
                if refuted.any():
                    return unsure[refuted]
            if self.exact.certificates_pay:
                ok = certify_edges(
                    self.exact, Q0, Q1, resolution, spacing=self.resolution * self.params.certify_spacing
                )
            else:
                ok = check_edges(self.exact, Q0, Q1, resolution)
            roadmap.edge_checked_at[unsure[ok]] = resolution  # remembered across repairs
            roadmap.edge_cost[unsure[ok]] = roadmap.distance(Q0[ok], Q1[ok])
            if not ok.all():
                return unsure[~ok]
        return np.zeros(0, dtype=int)

    def repair(self, path: np.ndarray, nodes=(), edges=()) -> None:
        """Remove the candidate ``path``'s ``nodes`` or ``edges`` (indices) that the exact checker rejected."""
        self.record("repair", path=path, removed_nodes=nodes, removed_edges=edges)
        self.stats["repairs"] += 1
        self.stats["removed_nodes"] += len(nodes)
        self.stats["removed_edges"] += len(edges)
        if len(nodes):
            self.roadmap.remove_nodes(np.asarray(nodes, dtype=int))
        if len(edges):
            self.roadmap.remove_edges(np.asarray(edges, dtype=int))

    def result(self, path: np.ndarray | None, planner: str) -> PlanResult:
        """The query's answer by ``planner`` (its name): the path's configurations (if any), the final stats and
        roadmap."""
        exact, predicted = np.subtract(self.counts(), self.counts_at_start)
        stats = dict(
            self.stats,
            nodes=len(self.roadmap.nodes),
            edges=len(self.roadmap.edges),
            exact_checks=int(exact),
            predicted_checks=int(predicted),
            resolution=self.resolution,
            exact_clearances=self.exact.n_bounded - self.bounded_at_start,
            total_s=time.perf_counter() - self.began,
        )
        path_q = self.roadmap.nodes[path] if path is not None else np.zeros((0, self.exact.robot.dof))
        return PlanResult(path is not None, path_q, stats, planner, self.roadmap)
