"""PRM with and without prediction: the paper's Algorithm 1 (§III-B), every returned path exactly valid.

``plan(exact, start, goal, sampler=..., checker=...)`` runs:

1. (the learned checker encoded the workspace when it was built: Algorithm 1, line 1);
2. sample a set S with one of the four samplers, validity decided by ``checker``
   (the learned one, or ``exact`` itself): S' are the samples it accepts (lines 2-3);
3. build the roadmap: each new node's k nearest neighbours, straight-line edges (line 4);
4. connect start and goal (while they lie in different components, also try the k
   closest pairs between each one's component and the rest); when the roadmap does
   not join them, sample another S with the same (auxiliary) sampler and repeat (line 4),
   "creating additional valid samples" (``PRMOptions.auxiliary``): with the exact
   checker (the paper preset), or (the default and the strong preset) with
   prediction, keeping what the exact checker confirms, and every fourth round
   (``exact_every``) exactly; either keeps the planner probabilistically complete
   however poor the prediction;
5. extract the cheapest path and **verify** it with the exact checker: its nodes, and
   its edges at ``resolution`` (unless checked exactly when they were added), then at
   ``resolution / verify_refinement`` (10x finer: shortest paths hug obstacles, and an
   edge that grazes a corner between two checks at ``resolution`` is caught here);
   whatever fails is removed from the roadmap and the query repeats (line 5). Each
   edge remembers the finest resolution it passed at (``Roadmap.edge_checked_at``),
   so the next candidate path re-checks none of them. Verification uses clearance
   certificates (``local_planner.certify_edges``: the same answer as checking every
   point, but a stretch whose ends are far enough from every obstacle needs no check).
   While start and goal still lie in different components (repairs split a lazy
   roadmap; or the bridges failed), the planner bridges them again with the closest
   pairs not yet tried (the roadmap remembers rejected pairs), up to ``rebridge``
   times, before it samples another round. A returned path is always valid under the
   exact checker at both resolutions; otherwise ``success`` is False.

To watch these steps, pass ``trace=[]``: the planner appends a :class:`PlanStep`, a
snapshot of the roadmap, at every stage (``STAGES``: new samples, edges, bridges, each
candidate path, each repair, the verified path), e.g. to draw the roadmap as it grows
and is repaired (notebook 04). Snapshots cost copies: time the planner without it.

Two exact planners (no ``checker``), both as above:

- the paper's baseline (``PAPER_BASELINE``: ``lazy=False, first_samples=None``; the
  ``paper`` preset's Table 3): every round draws |S| = ``n_samples`` configurations, and every candidate
  edge is checked exactly, point by point, as it is added. Most of those edges are
  never on the path, and a first solution rarely needs |S| samples.
- the default, the best exact planner we have: a *lazy PRM* (Bohlin & Kavraki 2000).
  Edges cost their length and are confirmed only when a candidate path uses them
  (step 5). As they are added, the exact checker looks at a few points of each,
  ``lazy_screen`` resolutions apart, all edges in one call: a point in collision
  rejects an edge for certain, and the candidate paths that follow fail less often
  (each failure costs a shortest-path search and a few small checker calls). Rounds
  grow: ``first_samples``, doubled each round up to |S|, so an easy query is solved
  on a small roadmap. Checking many configurations in one call is what makes our
  checkers fast (a call's fixed cost dwarfs a configuration's): the planner asks in
  batches wherever it can.

"With" and "without prediction" differ in the ``checker`` argument only. With
prediction, edges are decided in one of two ways (``PRMOptions.screen_edges``):

- ``False``: as without prediction (the paper's Algorithm 1: ``lazy=False``, edges
  checked exactly while the roadmap is built);
- ``True`` (default; beyond the paper, its stated future work): *learned edge
  screening*, the lazy PRM with prediction in place of the few exact checks: every
  edge is screened by batched prediction (edges mostly predicted in collision are
  dropped, the rest cost more the more of them is predicted in collision) and only
  the candidate path's edges are checked exactly, first at the roadmap's resolution
  (most edges that fail, fail there), then 10x finer. Screening only estimates the
  fraction in collision, so it predicts points ``screen_spacing`` resolutions apart.
  Before certifying a path's edges, the exact checker looks at the one point of each
  edge where screening predicted a collision (the middle predicted-invalid point;
  ``Roadmap.edge_suspect``, ``local_planner.refute_at``): a screened edge that fails
  usually fails there, for one exact check instead of a certificate's several calls.

So the ``strong`` preset's "with / without" compares the same lazy planner, with the
same rounds, with and without prediction: only the checker differs.
What each of these choices buys, measured, is in ``docs/benchmarks.md`` ("Planner design",
"Against OMPL").
"""

from __future__ import annotations

import time
from contextlib import contextmanager
from dataclasses import dataclass, field

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.local_planner import (
    certify_edges,
    check_edges,
    default_resolution,
    invalid_fractions,
    refute_at,
)
from toolkit.planning.roadmap import Roadmap
from toolkit.planning.sampling import make_sampler

START, GOAL = 0, 1  # node indices of the query's endpoints (never removed)
AUXILIARY = {  # PRMOptions.auxiliary: how rounds after the first sample, with prediction
    "exact": "with the exact checker",
    "confirmed": "with prediction, keeping what the exact checker confirms; every PRMOptions.exact_every-th round "
                 "(counting from the first) with the exact checker",
    "predicted": "with prediction, like the first (nodes are checked when a candidate path uses them)",
}

PAPER_BASELINE = {"lazy": False, "first_samples": None}  # PRMOptions of Algorithm 1 as the paper has it: see above

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


@dataclass
class PRMOptions:
    """Planner settings; ``k`` follows OMPL's PRM, ``n_samples`` the paper's |S| (§IV-A)."""

    n_samples: int = 200  # sampler attempts per round (|S|)
    k: int = 10  # nearest neighbours tried for each new node
    resolution: float | None = None  # local planner step bound; None: default_resolution(robot)
    verify_refinement: int = 10  # the returned path's edges are checked exactly at resolution / this
    max_rounds: int = 20  # sampling rounds before reporting failure
    rebridge: int = 3  # when no path survives verification, bridge again up to this often before sampling again
    auxiliary: str = "confirmed"  # with prediction, rounds after the first: see AUXILIARY
    exact_every: int = 4  # auxiliary "confirmed": rounds 1 + exact_every, 1 + 2 * exact_every, ... sample exactly
    screen_edges: bool = True  # with prediction: learned edge screening (lazy PRM); False: the paper's exact edges
    lazy: bool = True  # edges not screened by prediction: confirmed only on candidate paths; False: as added (paper)
    lazy_screen: float | None = 32.0  # lazy edges: exact checks resolution * this apart as they are added (None: none)
    first_samples: int | None = 50  # round r samples min(first_samples * 2**(r-1), n_samples); None: n_samples (paper)
    screen_reject: float = 0.9  # screening drops edges with a larger predicted-invalid fraction
    screen_penalty: float = 10.0  # screened edge cost = length * (1 + penalty * predicted-invalid fraction)
    screen_spacing: float = 8.0  # screening predicts points resolution * this apart (an estimate of the fraction)
    certify_spacing: float = 8.0  # path verification: intervals of motion resolution * this first (certify_edges)
    sampler_options: dict = field(default_factory=dict)

    def __post_init__(self):
        for name in ("n_samples", "k", "verify_refinement", "max_rounds", "exact_every", "first_samples"):
            value = getattr(self, name)
            if value is None and name == "first_samples":
                continue
            if int(value) != value or value < 1:
                raise ValueError(f"PRMOptions.{name} must be a positive integer, got {value!r}")
        if int(self.rebridge) != self.rebridge or self.rebridge < 0:
            raise ValueError(f"PRMOptions.rebridge must be a non-negative integer, got {self.rebridge!r}")
        for name in ("resolution", "screen_spacing", "certify_spacing", "lazy_screen"):
            value = getattr(self, name)
            if value is not None and not (np.isfinite(value) and value > 0):
                raise ValueError(f"PRMOptions.{name} must be positive and finite, got {value!r}")
        if self.auxiliary not in AUXILIARY:
            raise ValueError(f"PRMOptions.auxiliary must be one of {sorted(AUXILIARY)}, got {self.auxiliary!r}")
        if not 0 <= self.screen_reject <= 1:
            raise ValueError(f"PRMOptions.screen_reject must lie in [0, 1], got {self.screen_reject!r}")
        if not (np.isfinite(self.screen_penalty) and self.screen_penalty >= 0):
            raise ValueError(f"PRMOptions.screen_penalty must be non-negative and finite, got {self.screen_penalty!r}")


@dataclass
class PlanResult:
    """``success``; ``path (P, dof)`` (empty on failure); ``stats`` (counts, seconds); the final ``roadmap``."""

    success: bool
    path: np.ndarray
    stats: dict
    roadmap: Roadmap


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


def plan(exact: CollisionChecker, start, goal, *, sampler: str = "BS", checker: CollisionChecker | None = None,
         options: PRMOptions | None = None, rng: np.random.Generator, trace: list | None = None) -> PlanResult:
    """Solve one query ``start -> goal`` (``(dof,)`` each) with PRM; ``checker`` decides samples (default: ``exact``);
    a ``trace`` list receives a :class:`PlanStep` at every stage."""
    began = time.perf_counter()
    options = options or PRMOptions()
    robot = exact.robot
    checker = exact if checker is None else checker
    if checker.robot.dof != robot.dof:
        raise ValueError(f"checker is for a {checker.robot.dof}-DoF robot, the exact checker for {robot.dof}")
    endpoints = np.concatenate([_single(robot, start, "start"), _single(robot, goal, "goal")])  # (2, dof)
    planner = _Planner(exact, checker, options, make_sampler(sampler, checker, **options.sampler_options),
                       make_sampler(sampler, exact, **options.sampler_options), trace)
    for name, ok, q in zip(("start", "goal"), exact.are_valid(endpoints), endpoints):
        if not ok:
            raise ValueError(f"{name} configuration {np.round(q, 4).tolist()} is in collision or out of bounds")
    new = planner.roadmap.add_nodes(endpoints, verified=True)  # START, GOAL
    path = None
    while path is None and planner.stats["rounds"] < options.max_rounds:
        planner.stats["rounds"] += 1
        with planner.timed("sampling_s", "node_checks"):
            S_valid, verified = planner.sample_round(rng)  # S' (M, dof)
        new = np.concatenate([new, planner.roadmap.add_nodes(S_valid, verified=verified)])
        planner.record("sample", new_nodes=new)
        with planner.timed("connection_s", "edge_checks"):
            planner.connect(new)
        planner.record("connect")
        new = new[:0]
        with planner.timed("query_s", "verify_checks"):
            path = planner.verified_path()
        bridges = 0
        while path is None and bridges < options.rebridge:  # still apart (repairs split it): the next closest pairs
            bridges += 1
            planner.stats["rebridges"] += 1
            with planner.timed("connection_s", "edge_checks"):
                if not planner.bridge():
                    break
            planner.record("bridge")
            with planner.timed("query_s", "verify_checks"):
                path = planner.verified_path()
    stats = planner.finish(began)
    roadmap = planner.roadmap
    path_q = roadmap.nodes[path] if path is not None else np.zeros((0, robot.dof))
    return PlanResult(path is not None, path_q, stats, roadmap)


def _single(robot, q, name: str) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    if q.shape != (robot.dof,):
        raise ValueError(f"{name} must have shape ({robot.dof},) for robot {robot.name!r}, got {q.shape}")
    return robot.check_configs(q, name)


class _Planner:
    """The state of one query: roadmap, checkers, counters and timers."""

    def __init__(self, exact, checker, options: PRMOptions, sampler, exact_sampler, trace: list | None = None):
        self.exact, self.checker, self.options, self.trace = exact, checker, options, trace
        self.sampler, self.exact_sampler = sampler, exact_sampler  # the same sampler over each checker
        self.predicted = checker is not exact
        self.resolution = default_resolution(exact.robot) if options.resolution is None else float(options.resolution)
        self.screened = self.predicted and options.screen_edges  # edges screened by prediction, not checked exactly
        self.lazy = not self.screened and options.lazy  # edges unchecked until a candidate path uses them
        # a path's edges are confirmed at the roadmap's resolution (where most that fail, fail; exactly checked
        # edges already were), then finer
        self.verify_resolutions = (self.resolution, self.resolution / options.verify_refinement)
        self.roadmap = Roadmap(exact.robot)
        self.stats = {"rounds": 0, "repairs": 0, "rebridges": 0, "removed_nodes": 0, "removed_edges": 0,
                      "sampling_s": 0.0, "connection_s": 0.0, "query_s": 0.0,
                      "node_checks": 0, "edge_checks": 0, "verify_checks": 0}
        self._start_counts, self._start_bounded = self._counts(), exact.n_bounded

    def record(self, stage: str, *, new_nodes=(), path=(), removed_nodes=(), removed_edges=()) -> None:
        """Append a :class:`PlanStep` of the roadmap as it is now to the trace (if tracing)."""
        if self.trace is None:
            return
        roadmap, indices = self.roadmap, lambda a: np.array(a, dtype=int)
        self.trace.append(PlanStep(stage, self.stats["rounds"], roadmap.nodes.copy(), roadmap.node_verified.copy(),
                                   roadmap.edges.copy(), indices(new_nodes), indices(path), indices(removed_nodes),
                                   indices(removed_edges)))

    def _counts(self) -> tuple[int, int]:
        """Configurations checked so far: (exact, predicted)."""
        return self.exact.n_checked, self.checker.n_checked if self.predicted else 0

    @contextmanager
    def timed(self, seconds_key: str, checks_key: str):
        before, start = sum(self._counts()), time.perf_counter()
        yield
        self.stats[seconds_key] += time.perf_counter() - start
        self.stats[checks_key] += sum(self._counts()) - before

    def round_size(self) -> int:
        """Sampler attempts this round: |S| (the paper), or, growing, ``first_samples`` doubled each round up to |S|."""
        n, first = self.options.n_samples, self.options.first_samples
        return n if first is None else min(n, first << min(self.stats["rounds"] - 1, 30))

    def sample_round(self, rng: np.random.Generator) -> tuple[np.ndarray, bool]:
        """This round's samples ``(M, dof)`` and whether the exact checker vouches for them (``PRMOptions.auxiliary``)."""
        n, auxiliary, round_ = self.round_size(), self.options.auxiliary, self.stats["rounds"]
        exact_round = auxiliary == "exact" or (auxiliary == "confirmed" and (round_ - 1) % self.options.exact_every == 0)
        if not self.predicted or (round_ > 1 and exact_round):
            return self.exact_sampler.sample(n, rng), True
        S = self.sampler.sample(n, rng)
        if round_ > 1 and auxiliary == "confirmed":
            return S[self.exact.are_valid(S)], True
        return S, False

    def connect(self, new: np.ndarray) -> None:
        """Edges from the new nodes to their k nearest; then, while start and goal lie apart, bridges from their components."""
        self.decide(self.roadmap.candidate_edges(new, self.options.k))
        self.bridge()

    def bridge(self) -> int:
        """While start and goal lie apart, try the closest untried pairs from each one's component; edges added."""
        roadmap, before = self.roadmap, len(self.roadmap.edges)
        for end in (START, GOAL):
            if not roadmap.component(START)[GOAL]:
                self.decide(roadmap.bridge_edges(end, self.options.k))
        return len(roadmap.edges) - before

    def decide(self, pairs: np.ndarray) -> None:
        """Add the candidate edges ``pairs (C, 2)`` that screening (with prediction) or the exact check accepts;
        remember the others as rejected."""
        roadmap, options = self.roadmap, self.options
        Q0, Q1 = roadmap.nodes[pairs[:, 0]], roadmap.nodes[pairs[:, 1]]
        length = roadmap.distance(Q0, Q1)  # (C,)
        if self.screened:
            fraction, suspect = invalid_fractions(self.checker, Q0, Q1, self.resolution * options.screen_spacing)
            keep = fraction <= options.screen_reject
            roadmap.add_edges(pairs[keep], length[keep] * (1 + options.screen_penalty * fraction[keep]),
                              suspect=suspect[keep])
        elif self.lazy:  # a few exact checks now (one call for all), the rest if a candidate path uses the edge
            keep = np.ones(len(pairs), dtype=bool)
            if options.lazy_screen is not None:
                keep = invalid_fractions(self.exact, Q0, Q1, self.resolution * options.lazy_screen)[0] == 0
            roadmap.add_edges(pairs[keep], length[keep])
        else:
            keep = check_edges(self.exact, Q0, Q1, self.resolution)
            roadmap.add_edges(pairs[keep], length[keep], checked_at=self.resolution)
        roadmap.reject(pairs[~keep])

    def verified_path(self) -> np.ndarray | None:
        """Node indices of a start-goal path the exact checker confirms, repairing the roadmap; None if none."""
        roadmap, options = self.roadmap, self.options
        while (path := roadmap.shortest_path(START, GOAL)) is not None:
            self.record("candidate", path=path)
            unsure = path[~roadmap.node_verified[path]]
            ok = self.exact.are_valid(roadmap.nodes[unsure]) if len(unsure) else np.zeros(0, bool)
            roadmap.node_verified[unsure[ok]] = True
            if not ok.all():
                self._repair(path, nodes=unsure[~ok])
                continue
            steps = roadmap.edge_index(path)
            for resolution in self.verify_resolutions:
                unsure = steps[roadmap.edge_checked_at[steps] > resolution]
                Q0, Q1 = roadmap.nodes[roadmap.edges[unsure].T]
                suspect = roadmap.edge_suspect[unsure]
                if resolution == self.resolution and np.isfinite(suspect).any():  # where screening saw edges fail
                    refuted = refute_at(self.exact, Q0, Q1, suspect, resolution)  # one exact check each, first
                    roadmap.edge_suspect[unsure] = np.nan  # looked at
                    if refuted.any():
                        self._repair(path, edges=unsure[refuted])
                        break
                if self.exact.certificates_pay:
                    ok = certify_edges(self.exact, Q0, Q1, resolution, spacing=self.resolution * options.certify_spacing)
                else:
                    ok = check_edges(self.exact, Q0, Q1, resolution)
                roadmap.edge_checked_at[unsure[ok]] = resolution  # remembered across repairs
                roadmap.edge_cost[unsure[ok]] = roadmap.distance(Q0[ok], Q1[ok])
                if not ok.all():
                    self._repair(path, edges=unsure[~ok])
                    break
            else:
                self.record("path", path=path)
                return path
        return None

    def _repair(self, path: np.ndarray, nodes=(), edges=()) -> None:
        """Remove the candidate ``path``'s ``nodes`` or ``edges`` (indices) that the exact checker rejected."""
        self.record("repair", path=path, removed_nodes=nodes, removed_edges=edges)
        self.stats["repairs"] += 1
        self.stats["removed_nodes"] += len(nodes)
        self.stats["removed_edges"] += len(edges)
        if len(nodes):
            self.roadmap.remove_nodes(np.asarray(nodes, dtype=int))
        if len(edges):
            self.roadmap.remove_edges(np.asarray(edges, dtype=int))

    def finish(self, began: float) -> dict:
        exact, predicted = np.subtract(self._counts(), self._start_counts)
        return dict(self.stats, nodes=len(self.roadmap.nodes), edges=len(self.roadmap.edges),
                    exact_checks=int(exact), predicted_checks=int(predicted), resolution=self.resolution,
                    exact_clearances=self.exact.n_bounded - self._start_bounded,
                    total_s=time.perf_counter() - began)
