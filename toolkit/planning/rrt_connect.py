"""RRT-Connect (Kuffner & LaValle 2000): two trees, one from the start and one from the goal, that grow towards
random configurations and towards each other; a fast exact planner for a single query.

Each iteration draws a configuration uniformly, **extends** one tree towards it by at most ``range`` (of
``robot.motion_bound``: no robot point moves farther), and then **connects** the other tree to the new node: it
extends towards it again and again, a node every ``range``, until it reaches it (the trees meet: a path) or is
stopped by an obstacle. Then the trees swap roles.

A move, an extension or a whole connection, is a straight segment from the tree's node nearest its target, checked
exactly at the local planner's grid (``local_planner.step_counts`` steps of ``resolution``, the end included)
*coarse to fine* in two checker calls: first every ``coarse``-th point and the nodes, then the rest before the first
point that failed, so that a move into an obstacle usually stops after the first, small call. The nodes before the
first invalid point join the tree (an extension that meets an obstacle adds nothing: the tree is *trapped*). The
move up to its checks (the nearest node, the segment, its grid in that order) is one compiled call
(:mod:`toolkit.planning.rrt_kernels`), the rest a few lines of Python around the two checker calls. OMPL's
RRTConnect (Şucan, Moll, Kavraki 2012) asks its checker one configuration a call and a connection one extension at a
time; here a call holds tens of configurations, since a call's fixed cost outweighs many configurations'
(``docs/planner_race.md``, "Our planners against OMPL's").

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
from typing import ClassVar

import numpy as np

from toolkit.planning.local_planner import certify_edges
from toolkit.planning.options import CheckedParams
from toolkit.planning.planner import Planner, PlanResult, Problem
from toolkit.planning.roadmap import Roadmap

SAMPLES = 64  # random configurations drawn at a time


@dataclass(frozen=True)
class RRTConnectParams(CheckedParams):
    """RRT-Connect's settings; ``range`` in resolutions, as an edge's length is in checks."""

    range: float = 64.0  # an extension moves no robot point farther than resolution * this
    coarse: int = 8  # an extension's first call checks every coarse-th point of its grid and its end
    certify_spacing: float = 8.0  # verification: intervals of motion resolution * this first (certify_edges)
    max_iterations: int = 5_000  # samples drawn before reporting failure

    rules: ClassVar[dict[str, str]] = {  # field -> what it must be (options.RULES), checked as it is made
        **dict.fromkeys(("range", "certify_spacing"), "positive and finite"),
        **dict.fromkeys(("coarse", "max_iterations"), "a positive integer"),
    }


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
    steering = Steering(problem, params)
    stats: dict[str, float] = {"iterations": 0, "cuts": 0, "verify_checks": 0}
    path = None
    for iteration in range(params.max_iterations):
        stats["iterations"] = iteration + 1
        if iteration % SAMPLES == 0:  # (SAMPLES, dof) drawn a block at a time, as the compiled move reads them
            samples = np.array(robot.sample(rng, SAMPLES), dtype=np.float64, order="C")
        grow, other = (trees[0], trees[1]) if iteration % 2 == 0 else (trees[1], trees[0])
        new, _ = move(problem, steering, grow, samples, iteration % SAMPLES, connect=False)
        if new < 0:
            continue
        met, reached = move(problem, steering, other, grow.nodes, new, connect=True)  # the other tree follows
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


class Steering:
    """What a move reads besides its tree and target, as :func:`toolkit.planning.rrt_kernels.steer` reads it: the
    robot's motion weights and angles, the edge lengths, and the grid's buffers ``points (G, dof)`` and ``steps
    (G,)``, grown when a connection needs more.

    Every argument of ``steer`` is laid out alike in every query (made here, by :class:`Tree` and by
    :func:`rrt_connect`: float64, int64 and bool arrays, C-ordered and writable), so one compiled version serves
    them all: found once a process (``compiled.entry_point``) and then called without numba's dispatcher, which
    costs more than the call."""

    compiled: ClassVar = None  # steer's compiled version, once known

    def __init__(self, problem: Problem, params: RRTConnectParams):
        robot = problem.robot
        self.weights = np.array(robot.motion_weights, dtype=np.float64)  # (dof,) writable copies: one compiled
        self.wraps = np.array(robot.wraps, dtype=np.bool_)  # (dof,) version serves every robot
        self.reach, self.resolution = float(problem.resolution * params.range), float(problem.resolution)
        self.coarse = int(params.coarse)
        self.points = np.empty((4 * (int(params.range) + 1), robot.dof))  # (G, dof) a few extensions' grids
        self.steps = np.empty(len(self.points), dtype=np.int64)  # (G,)

    def __call__(self, tree: Tree, targets: np.ndarray, row: int, connect: bool) -> tuple[int, int, int, int, bool]:
        """``rrt_kernels.steer`` of ``tree`` towards ``targets[row]``: ``(near, segments, per, c, reached)``, the
        grid in :attr:`points` and :attr:`steps`."""
        while True:
            args: tuple = (tree.nodes, tree.n, tree.cut, targets, row, self.weights, self.wraps, self.reach)
            args += (self.resolution, self.coarse, connect, self.points, self.steps)
            if Steering.compiled is None:
                from toolkit.geometry.compiled import entry_point
                from toolkit.planning import rrt_kernels  # numba loads (or compiles) on first use, not on import

                near, segments, per, c, reached = rrt_kernels.steer(*args)
                Steering.compiled = entry_point(rrt_kernels.steer, args)
            else:
                near, segments, per, c, reached = Steering.compiled(*args)
            if c >= 0:
                return near, segments, per, c, reached
            self.points = np.empty((2 * segments * per, len(self.weights)))  # too few rows: room for twice as many
            self.steps = np.empty(len(self.points), dtype=np.int64)


def move(
    problem: Problem, steering: Steering, tree: Tree, targets: np.ndarray, row: int, *, connect: bool
) -> tuple[int, bool]:
    """Move ``tree`` from its node nearest ``targets[row]`` towards it: by at most ``resolution * range`` (an
    extension), or with ``connect`` all the way in edges no longer; the segment's grid is checked coarse to fine,
    and the edges before its first invalid point join the tree. Returns the last node added (-1: none, trapped)
    and whether it is the target."""
    exact = problem.exact
    near, segments, per, c, reached = steering(tree, targets, row, connect)  # one compiled call
    n = segments * per
    points, steps = steering.points, steering.steps  # (>= n, dof), (>= n,): the grid, in the order checked
    blocked = first_invalid(exact, points[:c], steps[:c], n + 1)  # the first invalid step (n + 1: none)
    if connect or blocked > n:  # an extension that failed adds nothing: it needs no fine points
        useful = blocked if blocked > n else (blocked - 1) // per * per  # the end of the last edge that may be kept
        fine = c + int(np.searchsorted(steps[c:n], useful))  # only points before it matter: the rest ascend
        blocked = first_invalid(exact, points[c:fine], steps[c:fine], blocked)
    last = near
    for k in range(per, min(blocked, n), per):  # a connection's edges, each valid up to its end
        last = tree.add(points[np.searchsorted(steps[:c], k)], last)
    if blocked <= n:
        return (last if last != near else -1), False
    return tree.add(targets[row] if reached else points[c - 1], last), reached  # steps[c - 1] == n: the end


def first_invalid(exact, points: np.ndarray, steps: np.ndarray, blocked: int) -> int:
    """The least of ``blocked`` and the steps ``(P,)`` of the invalid ones of ``points (P, dof)`` (one call)."""
    if not len(points):
        return blocked
    ok = exact.are_valid(points)
    return blocked if ok.all() else min(blocked, int(steps[np.argmin(ok)]))


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
