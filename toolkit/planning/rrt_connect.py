"""RRT-Connect (Kuffner & LaValle 2000): two trees, one from the start and one from the goal, that grow towards
random configurations and towards each other; a fast exact planner for a single query.

Each iteration draws a configuration uniformly, **extends** one tree towards it by at most ``range`` (of
``robot.motion_bound``: no robot point moves farther), and then **connects** the other tree to the new node: it
extends towards it again and again until it reaches it (the trees meet: a path) or is stopped by an obstacle. Then
the trees swap roles.

An extension is an edge of the tree, checked exactly at the local planner's grid (``local_planner.step_counts``
steps of ``resolution``, the end included) *coarse to fine*: first every ``coarse``-th point and the end in one
checker call, then the rest in a second, so that an extension into an obstacle usually stops after the first,
small call. An extension that meets an obstacle adds nothing (the tree is *trapped*). OMPL's RRTConnect (Şucan,
Moll, Kavraki 2012) asks its checker one configuration a call; here a call holds a few tens, since a call's fixed
cost outweighs many configurations' (``docs/benchmarks.md``, "How do our planners compare with OMPL's?").

Every edge of a path was checked at ``resolution`` as it grew; the path is then verified exactly at the problem's
``fine_resolution`` (10x finer) with clearance certificates (``local_planner.certify_edges``: the answer of
checking every point). An edge that fails there is cut from its tree, with the branch beyond it, and the search goes
on; so a returned path is valid at both resolutions.

:func:`rrt_connect` is the planner as one function of a :class:`~toolkit.planning.planner.Problem`;
:class:`RRTConnect` offers it by name (``rrt-connect``: ``toolkit plan --planner rrt-connect``). Its targets are
uniform configurations, whatever the problem's sampler, and it plans without prediction.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from toolkit.planning.local_planner import certify_edges
from toolkit.planning.planner import Planner, PlanResult, Problem
from toolkit.planning.roadmap import Roadmap

SAMPLES = 64  # random configurations drawn at a time


@dataclass(frozen=True)
class RRTConnectParams:
    """RRT-Connect's settings; ``range`` in resolutions, as an edge's length is in checks."""

    range: float = 64.0  # an extension moves no robot point farther than resolution * this
    coarse: int = 8  # an extension's first call checks every coarse-th point of its grid and its end
    certify_spacing: float = 8.0  # verification: intervals of motion resolution * this first (certify_edges)
    max_iterations: int = 5_000  # samples drawn before reporting failure

    def __post_init__(self):
        for name in ("range", "certify_spacing"):
            if not (np.isfinite(getattr(self, name)) and getattr(self, name) > 0):
                raise ValueError(f"RRTConnectParams.{name} must be positive and finite, got {getattr(self, name)!r}")
        for name in ("coarse", "max_iterations"):
            if not (int(getattr(self, name)) == getattr(self, name) and getattr(self, name) >= 1):
                raise ValueError(f"RRTConnectParams.{name} must be a positive integer, got {getattr(self, name)!r}")


class Tree:
    """Configurations ``nodes[:n] (n, dof)``, each with the index of its ``parent`` (the root's is -1); ``cut`` marks
    the nodes of branches that failed verification."""

    def __init__(self, root: np.ndarray, capacity: int = 256):
        self.nodes = np.zeros((capacity, len(root)))
        self.parent = np.full(capacity, -1)
        self.cut = np.zeros(capacity, dtype=bool)
        self.nodes[0], self.n = root, 1

    def add(self, q: np.ndarray, parent: int) -> int:
        if self.n == len(self.nodes):  # full: twice the room
            self.nodes = np.concatenate([self.nodes, np.zeros_like(self.nodes)])
            self.parent = np.concatenate([self.parent, np.full(self.n, -1)])
            self.cut = np.concatenate([self.cut, np.zeros(self.n, dtype=bool)])
        self.nodes[self.n], self.parent[self.n] = q, parent
        self.n += 1
        return self.n - 1

    def branch(self, i: int) -> list[int]:
        """Node indices from ``i`` up to the root."""
        indices = [i]
        while self.parent[indices[-1]] >= 0:
            indices.append(int(self.parent[indices[-1]]))
        return indices

    def cut_below(self, i: int) -> None:
        """Cut node ``i`` and every node whose branch passes through it."""
        self.cut[i] = True
        while True:  # a child of a cut node is cut: spread down the tree until nothing changes
            spread = self.cut[: self.n] | (self.parent[: self.n] >= 0) & self.cut[np.maximum(self.parent[: self.n], 0)]
            if (spread == self.cut[: self.n]).all():
                return
            self.cut[: self.n] = spread


def rrt_connect(problem: Problem, rng: np.random.Generator, params: RRTConnectParams | None = None) -> PlanResult:
    """One query ``problem.start -> problem.goal`` with RRT-Connect, ``problem.exact`` deciding validity; the
    result's ``roadmap`` holds the two trees (:func:`as_roadmap`)."""
    params = RRTConnectParams() if params is None else params
    if problem.predicts:
        raise ValueError("RRT-Connect plans without prediction: give it no learned checker")
    exact, robot = problem.exact, problem.robot
    began, checked = time.perf_counter(), exact.n_checked
    ends = np.stack([problem.start, problem.goal])  # (2, dof)
    for name, ok, q in zip(("start", "goal"), exact.are_valid(ends), ends):
        if not ok:
            raise ValueError(f"{name} configuration {np.round(q, 4).tolist()} is in collision or out of bounds")
    trees = (Tree(ends[0]), Tree(ends[1]))
    stats: dict[str, float] = {"iterations": 0, "extensions": 0, "cuts": 0, "verify_checks": 0}

    def grow_by(tree: Tree, target: np.ndarray, near: int | None = None) -> tuple[int, bool]:
        stats["extensions"] += 1
        return extend(problem, params, tree, target, near)

    path = None
    for iteration in range(params.max_iterations):
        stats["iterations"] = iteration + 1
        if iteration % SAMPLES == 0:
            samples = robot.sample(rng, SAMPLES)  # (SAMPLES, dof) drawn a block at a time
        grow, other = (trees[0], trees[1]) if iteration % 2 == 0 else (trees[1], trees[0])
        new, _ = grow_by(grow, samples[iteration % SAMPLES])
        if new < 0:
            continue
        met, reached = grow_by(other, grow.nodes[new])  # connect: extend again and again from the last node added
        while met >= 0 and not reached:
            met, reached = grow_by(other, grow.nodes[new], near=met)
        if not reached:
            continue
        meeting = (new, met) if grow is trees[0] else (met, new)  # the same configuration, in either tree
        if (path := verified_path(problem, trees, meeting, params, stats)) is not None:
            break
    roadmap = as_roadmap(robot, trees, problem.resolution)
    stats.update(
        nodes=len(roadmap.nodes),
        edges=len(roadmap.edges),
        predicted_checks=0,
        exact_checks=exact.n_checked - checked,
        resolution=problem.resolution,
        total_s=time.perf_counter() - began,
    )
    if path is None:
        return PlanResult(False, np.zeros((0, robot.dof)), stats, RRTConnect.name, roadmap)
    return PlanResult(True, path, stats, RRTConnect.name, roadmap)


def extend(
    problem: Problem, params: RRTConnectParams, tree: Tree, target: np.ndarray, near: int | None
) -> tuple[int, bool]:
    """Extend ``tree`` from node ``near`` (None: its node nearest ``target``) towards ``target`` by at most
    ``resolution * range``, the edge checked coarse to fine: (the new node, or -1 if trapped; whether it reached
    ``target``)."""
    exact, robot, resolution = problem.exact, problem.robot, problem.resolution
    reach = resolution * params.range
    if near is None:
        steps = robot.difference(tree.nodes[: tree.n], target)  # (n, dof) from each node to target
        distance = np.abs(steps) @ robot.motion_weights  # (n,) robot.motion_bound of each step
        near = int(np.argmin(np.where(tree.cut[: tree.n], np.inf, distance)))
        step, length = steps[near], float(distance[near])
    else:
        step = robot.difference(tree.nodes[near], target)  # (dof,)
        length = float(np.abs(step) @ robot.motion_weights)
    q0, reached = tree.nodes[near], length <= reach
    if not reached:
        step, length = step * (reach / length), reach
    n = max(int(np.ceil(length / resolution)), 1)  # local_planner.step_counts
    k = np.arange(1, n + 1)  # the grid's points, the end (k = n) included
    for part in (k[(k % params.coarse == 0) | (k == n)], k[(k % params.coarse != 0) & (k != n)]):
        if len(part) and not exact.are_valid(robot.wrap(q0 + (part / n)[:, None] * step)).all():
            return -1, False
    return tree.add(target if reached else robot.wrap(q0 + step), near), reached


def verified_path(
    problem: Problem, trees: tuple[Tree, Tree], meeting: tuple[int, int], params: RRTConnectParams, stats: dict
) -> np.ndarray | None:
    """The path ``(P, dof)`` from the start tree's root through its node ``meeting[0]``, which is the goal tree's
    node ``meeting[1]``, to the goal tree's root, if it passes exactly at ``problem.fine_resolution``; else None,
    each failed edge's end away from its root cut, with the branch beyond it."""
    exact = problem.exact
    from_start, to_goal = trees[0].branch(meeting[0])[::-1], trees[1].branch(meeting[1])  # root -> a, b -> root
    path = np.concatenate([trees[0].nodes[from_start], trees[1].nodes[to_goal[1:]]])  # (P, dof)
    before, spacing = exact.n_checked, problem.resolution * params.certify_spacing
    ok = certify_edges(exact, path[:-1], path[1:], problem.fine_resolution, spacing=spacing)
    stats["verify_checks"] += exact.n_checked - before
    for edge in np.flatnonzero(~ok):
        stats["cuts"] += 1
        if edge + 1 < len(from_start):
            trees[0].cut_below(from_start[edge + 1])
        else:
            trees[1].cut_below(to_goal[edge + 1 - len(from_start)])
    return path if ok.all() else None


def as_roadmap(robot, trees: tuple[Tree, Tree], resolution: float) -> Roadmap:
    """The ``trees`` as one roadmap, to draw or inspect: the start tree's nodes, then the goal tree's, and an edge
    from each node to its parent, checked at ``resolution`` (none for a node of a cut branch)."""
    roadmap = Roadmap(robot)
    for tree in trees:
        offset = len(roadmap.nodes)
        roadmap.add_nodes(tree.nodes[: tree.n], verified=True)
        child = np.flatnonzero((tree.parent[: tree.n] >= 0) & ~tree.cut[: tree.n])  # (E,)
        pairs = np.sort(np.stack([child, tree.parent[child]], axis=1), axis=1) + offset  # (E, 2) i < j
        roadmap.add_edges(pairs, roadmap.distance(*roadmap.nodes[pairs.T]), checked_at=resolution)
    return roadmap


class RRTConnect(Planner):
    """:func:`rrt_connect` as a planner offered by name (``toolkit.planning.prm.get("rrt-connect")``)."""

    name = "rrt-connect"
    Params = RRTConnectParams
    params: RRTConnectParams

    def solve(self, problem: Problem, rng: np.random.Generator) -> PlanResult:
        return rrt_connect(problem, rng, self.params)
