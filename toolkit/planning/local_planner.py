"""The straight-line local planner (paper §III-B, "Connection and Path Planning").

A segment ``q0 -> q1`` (angles the short way round) is checked at configurations
spaced so that **no point of the robot moves more than** ``resolution`` **between
two consecutive checks**: the segment gets ``ceil(robot.motion_bound(q0, q1) /
resolution)`` steps. The default resolution is half the thickness of the robot's
thinnest link (``default_resolution``).

Everything is batched over many segments at once. ``check_edges`` visits the
interior points of all segments coarse-to-fine (odd multiples of 2^k steps, k
decreasing, like OMPL's ``DiscreteMotionValidator`` bisection order), so a segment
that collides is usually dropped after a few checks; its first batch takes every
multiple of the coarsest level that still holds ``MIN_BATCH`` points, because a
checker call has a fixed cost, worth many configurations in a batch, that tiny coarse
levels would repeat; ``certify_edges`` gives the same answer from the checker's
clearance bounds, checking only where they cannot vouch for a stretch (the planner's
path verification: at 10x finer resolution it checks a small fraction of the points
``check_edges`` would). ``invalid_fractions`` asks about every interior point (for
screening by prediction), and ``refute_at`` checks one point a segment, where screening
saw it fail; ``last_valid_along`` walks segments from their start and stops at the first
invalid point (for the obstacle-based sampler). ``path_points`` lists the points a
path's segments are checked at and ``path_at`` the configurations at fractions of a
path's length (to draw, check or play back a path). The measurements behind
``MIN_BATCH`` and the certificates are in ``docs/benchmarks.md`` ("Planner design").
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.util.ragged import ragged

MAX_BATCH = 100_000  # configurations per checker call
MIN_BATCH = 256  # check_edges: configurations in its first, coarsest call (when the segments have that many)


def default_resolution(robot: BoxRobot) -> float:
    """Half the thickness of the robot's thinnest link: 0.25 (2D point), 0.03 (youBot), 0.05 (box chains)."""
    return float(np.min(robot.half_extents))


def step_counts(robot: BoxRobot, Q0: np.ndarray, Q1: np.ndarray, resolution: float) -> np.ndarray:
    """``(E,)`` number of steps of each segment so that no robot point moves more than ``resolution`` per step."""
    if not resolution > 0:
        raise ValueError(f"resolution must be positive, got {resolution}")
    return np.maximum(np.ceil(robot.motion_bound(Q0, Q1) / resolution).astype(int), 1)


def segment_points(robot: BoxRobot, Q0: np.ndarray, Q1: np.ndarray, t: np.ndarray) -> np.ndarray:
    """``(P, dof)`` points at fractions ``t (P,)`` along segments ``Q0[p] -> Q1[p]`` (``(P, dof)`` each)."""
    return robot.wrap(Q0 + t[:, None] * robot.difference(Q0, Q1))


def _are_valid_batched(checker: CollisionChecker, Q: np.ndarray) -> np.ndarray:
    return np.concatenate(
        [checker.are_valid(Q[i : i + MAX_BATCH]) for i in range(0, len(Q), MAX_BATCH)] or [np.zeros(0, bool)]
    )


def check_edges(checker: CollisionChecker, Q0, Q1, resolution: float) -> np.ndarray:
    """``(E,)`` bool: whether every interior point of each segment is valid (endpoints are not checked)."""
    robot = checker.robot
    Q0, Q1 = robot.check_configs(Q0, "Q0"), robot.check_configs(Q1, "Q1")
    n = step_counts(robot, Q0, Q1, resolution)  # (E,)
    valid = np.ones(len(n), dtype=bool)
    stride = 1  # the coarsest stride with MIN_BATCH multiples below n
    while np.sum((n - 1) // (2 * stride)) >= MIN_BATCH:
        stride *= 2
    # visit every multiple of stride, then the odd multiples of stride / 2, stride / 4, ..., 1
    for unit, every in [(stride, 1)] + [(stride >> k, 2) for k in range(1, stride.bit_length())]:
        active = np.flatnonzero(valid & (n > unit))
        owner, ordinal = ragged(((n[active] - 1) // unit + every - 1) // every)  # points unit * (1 + every * i) below n
        edge = active[owner]
        t = unit * (1 + every * ordinal) / n[edge]  # (P,)
        ok = _are_valid_batched(checker, segment_points(robot, Q0[edge], Q1[edge], t))
        valid[edge[~ok]] = False
    return valid


def certify_edges(checker: CollisionChecker, Q0, Q1, resolution: float, *, spacing: float) -> np.ndarray:
    """``(E,)`` bool: the answer of ``check_edges(checker, Q0, Q1, resolution)``, from far fewer checks.

    A clearance certificate (as in conservative advancement): the checker bounds the
    clearance at the two ends of an interval of a segment (``checker.clearances``);
    when they sum to more than the interval's motion bound, the interval is
    collision-free throughout — a robot point at fraction t of it has moved at most
    t x step from one end and (1 - t) x step from the other, so it stays within one
    end's clearance. Segments start as intervals of motion ``spacing`` at most, between
    points of the ``resolution`` grid; an interval that is not certified is halved at
    a grid point, until it holds no grid point inside. Every grid point is thus inside
    a certified interval or an interval's end, and an end whose clearance is 0 is
    checked exactly. A checker that bounds no clearance (0 everywhere) gets every grid
    point checked, once.
    """
    robot = checker.robot
    Q0, Q1 = robot.check_configs(Q0, "Q0"), robot.check_configs(Q1, "Q1")
    m = step_counts(robot, Q0, Q1, resolution)  # (E,) grid steps
    bound = robot.motion_bound(Q0, Q1)  # (E,)
    valid = np.ones(len(m), dtype=bool)

    def cut(edge, lo, hi, c_lo, c_hi, pieces):
        """Intervals ``[lo, hi]`` (grid steps) of segments ``edge``, with end clearances, cut in ``pieces`` each."""
        owner, i = ragged(pieces + 1)
        edge, f = edge[owner], lo[owner] + i * (hi - lo)[owner] // pieces[owner]  # (P,) the cuts, ends included
        clearance = np.where(i == 0, c_lo[owner], np.where(i == pieces[owner], c_hi[owner], np.nan))
        new = np.flatnonzero(np.isnan(clearance))
        Q = segment_points(robot, Q0[edge[new]], Q1[edge[new]], f[new] / m[edge[new]])
        clearance[new] = checker.clearances(Q, cap=spacing)
        unsure = (clearance[new] <= 0) & (f[new] > 0) & (f[new] < m[edge[new]])  # an interior grid point: check it
        valid[edge[new[unsure]][~_are_valid_batched(checker, Q[unsure])]] = False
        first = np.flatnonzero(i < pieces[owner])
        return edge[first], f[first], f[first + 1], clearance[first], clearance[first + 1]

    unknown = np.full(len(m), np.nan)
    first_pieces = np.minimum(step_counts(robot, Q0, Q1, spacing), m)  # (E,)
    intervals = cut(np.arange(len(m)), np.zeros_like(m), m, unknown, unknown, first_pieces)
    while True:
        edge, lo, hi, c_lo, c_hi = intervals
        unsure = valid[edge] & (hi - lo > 1) & (c_lo + c_hi <= bound[edge] * (hi - lo) / m[edge])
        if not unsure.any():
            return valid
        edge, lo, hi, c_lo, c_hi = (x[unsure] for x in intervals)
        intervals = cut(edge, lo, hi, c_lo, c_hi, np.full(unsure.sum(), 2))  # halved


def invalid_fractions(checker: CollisionChecker, Q0, Q1, resolution: float) -> tuple[np.ndarray, np.ndarray]:
    """Screening: ``(E,)`` fraction of each segment's interior points that ``checker`` calls invalid (0 without
    interior), and ``(E,)`` where along the segment (a fraction of it) the middle one of those points lies
    (NaN: none)."""
    robot = checker.robot
    Q0, Q1 = robot.check_configs(Q0, "Q0"), robot.check_configs(Q1, "Q1")
    n = step_counts(robot, Q0, Q1, resolution)  # (E,)
    edge, ordinal = ragged(n - 1)  # edge ascending
    t = (ordinal + 1) / n[edge]  # (P,)
    bad = np.flatnonzero(~_are_valid_batched(checker, segment_points(robot, Q0[edge], Q1[edge], t)))
    count = np.bincount(edge[bad], minlength=len(n))  # (E,) invalid points per segment
    suspect = np.full(len(n), np.nan)
    some = count > 0
    suspect[some] = t[bad[(np.cumsum(count) - count + count // 2)[some]]]  # each segment's middle invalid point
    return count / np.maximum(n - 1, 1), suspect


def refute_at(checker: CollisionChecker, Q0, Q1, suspect: np.ndarray, resolution: float) -> np.ndarray:
    """``(E,)`` bool: whether ``checker`` finds invalid the ``resolution`` grid point nearest fraction ``suspect`` of
    each segment, an interior point (NaN, or no interior point: False). True is certain: ``check_edges`` says False.

    One call over one point a segment: where a cheap checker's screening
    (:func:`invalid_fractions`) saw a segment fail, the exact checker usually does too.
    """
    robot = checker.robot
    n = step_counts(robot, Q0, Q1, resolution)  # (E,)
    look = np.flatnonzero(np.isfinite(suspect) & (n > 1))
    t = np.clip(np.round(suspect[look] * n[look]), 1, n[look] - 1) / n[look]  # a grid point inside
    refuted = np.zeros(len(n), dtype=bool)
    refuted[look] = ~_are_valid_batched(checker, segment_points(robot, Q0[look], Q1[look], t))
    return refuted


def last_valid_along(
    checker: CollisionChecker,
    Q0: np.ndarray,
    Q1: np.ndarray,
    resolution: float,
    *,
    bisections: int = 0,
    chunk: int = 16,
) -> np.ndarray:
    """``(E, dof)``: along each segment from a valid ``Q0[e]``, the last valid point before the first invalid one.

    Walks all segments together, ``chunk`` steps of ``resolution`` at a time; then
    ``bisections`` halvings of the step that went from valid to invalid bring the
    point within ``resolution / 2**bisections`` of the boundary. A segment with no
    invalid point returns ``Q1[e]``.
    """
    robot = checker.robot
    n = step_counts(robot, Q0, Q1, resolution)  # (E,)
    first_bad = np.full(len(n), -1)  # step index of the first invalid point, -1 while unknown
    done = 0
    while np.any((first_bad < 0) & (n > done)):
        active = np.flatnonzero((first_bad < 0) & (n > done))
        owner, ordinal = ragged(np.minimum(n[active] - done, chunk))
        edge, step = active[owner], done + 1 + ordinal
        ok = _are_valid_batched(checker, segment_points(robot, Q0[edge], Q1[edge], step / n[edge]))
        bad_steps = np.full(len(n), np.iinfo(int).max)
        np.minimum.at(bad_steps, edge[~ok], step[~ok])
        hit = bad_steps < np.iinfo(int).max
        first_bad[hit] = bad_steps[hit]
        done += chunk
    found = first_bad > 0
    good = np.where(found, first_bad - 1, n) / n  # (E,) fraction of the last valid point
    bad = first_bad[found] / n[found]
    for _ in range(bisections):
        middle = (good[found] + bad) / 2
        ok = _are_valid_batched(checker, segment_points(robot, Q0[found], Q1[found], middle))
        good[found] = np.where(ok, middle, good[found])
        bad = np.where(ok, bad, middle)
    return segment_points(robot, Q0, Q1, good)


def path_points(robot: BoxRobot, path, resolution: float) -> np.ndarray:
    """``(T, dof)`` every configuration of ``path (P, dof)`` and, between them, the points its segments are checked at
    (``step_counts`` steps each), in order along the path: the robot's motion, e.g. to draw or check it frame by
    frame."""
    path = robot.check_configs(path, "path")  # (P, dof)
    steps = step_counts(robot, path[:-1], path[1:], resolution)  # (P-1,)
    t = np.concatenate([np.arange(k) / k for k in steps] + [np.zeros(0)])  # (T-1,) fractions along each segment
    starts = np.repeat(np.arange(len(path) - 1), steps)  # (T-1,) the segment of each point
    return np.concatenate([segment_points(robot, path[starts], path[starts + 1], t), path[-1:]])


def path_is_valid(checker: CollisionChecker, path, resolution: float) -> bool:
    """Whether every configuration of ``path (P, dof)`` and every segment between them is valid."""
    path = checker.robot.check_configs(path, "path")
    return bool(checker.are_valid(path).all() and check_edges(checker, path[:-1], path[1:], resolution).all())


def path_at(robot: BoxRobot, path, t) -> np.ndarray:
    """``(T, dof)`` the configurations at fractions ``t (T,)`` (clipped to [0, 1]) of the length of ``path (P, dof)``
    (``robot.distance``): where a point moving at constant speed along the path's segments is at those times."""
    path = robot.check_configs(path, "path")  # (P, dof)
    if len(path) < 2:
        raise ValueError(f"a path to move along needs two configurations or more, got {len(path)}")
    lengths = robot.distance(path[:-1], path[1:])  # (P-1,)
    ends = np.cumsum(lengths)
    at = np.clip(np.asarray(t, dtype=float).reshape(-1), 0.0, 1.0) * ends[-1]  # (T,) distance travelled
    segment = np.minimum(np.searchsorted(ends, at), len(lengths) - 1)  # (T,)
    fraction = (at - (ends[segment] - lengths[segment])) / np.maximum(lengths[segment], 1e-12)
    return segment_points(robot, path[segment], path[segment + 1], np.clip(fraction, 0.0, 1.0))
