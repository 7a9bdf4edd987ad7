"""RRT-Connect's move before its checks, compiled (numba): the tree's node nearest a target, the straight segment
from it (angles the short way round), and that segment's grid of points in the order they are checked.

:func:`toolkit.planning.rrt_connect.move` asks this once a move, then the exact checker once or twice. Written in
numpy the same work took about 40 us a move in a dozen small calls (a tree holds tens of nodes, so each call's fixed
cost was most of it: ``docs/benchmarks.md``), more than the checker's answer for its points; here it is one call of
a few microseconds. The arithmetic is numpy's, operation for operation (``robot.wrap``'s ``mod`` bit for bit), but
for the order in which the motion bound ``sum |step| * weight`` adds up (numpy leaves it to BLAS): a seed plans the
path it planned in numpy up to rounding (the race's 180 queries in 3D: the same paths to 1e-14, and in all but one
the same checks; that one made one more).

``cache=True`` keeps the compiled code on disk like the checker's kernels (:mod:`toolkit.geometry.kernels`): a
process loads it on its first move, which a timed run makes before its clock starts (the untimed warm-up solve of
``toolkit.experiments.queries`` and ``versus_ompl.race``).
"""

from __future__ import annotations

import numpy as np
from numba import njit

TWO_PI = 2 * np.pi


@njit(cache=True, inline="always")
def wrapped(x: float, wraps: bool) -> float:
    """``x``, if an angle (``wraps``), mapped to [-pi, pi) as ``robot.wrap`` maps it: ``(x + pi) mod 2 pi - pi``.

    numpy's ``mod`` is C's ``fmod`` (exact), plus 2 pi where that is negative. A move's angles lie within 2 pi of
    [-pi, pi) (its nodes and targets are within the bounds), and there it is written out, bit for bit: below 2 pi
    ``fmod`` returns its argument, from 2 pi to 4 pi the argument less 2 pi (exact: Sterbenz's lemma). Not
    ``%``: a loop that holds one runs ten times slower even where it is never reached (numba 0.68, measured). An
    angle farther out is first brought nearer in steps of 2 pi."""
    if not wraps:
        return x
    shifted = x + np.pi
    while shifted >= 2 * TWO_PI:
        shifted -= TWO_PI
    while shifted <= -TWO_PI:
        shifted += TWO_PI
    if shifted > 0.0:
        return (shifted if shifted < TWO_PI else shifted - TWO_PI) - np.pi
    return (shifted + TWO_PI if shifted < 0.0 else 0.0) - np.pi


@njit(cache=True, inline="always")
def nearest(nodes, n, cut, target, weights, wraps, step) -> tuple[int, float]:
    """The uncut node of ``nodes[:n] (n, dof)`` nearest ``target (dof,)`` by the motion bound ``sum |step| *
    weights`` (the first of equals) and that bound; ``step (dof,)`` receives the step from it to ``target``."""
    best, near = np.inf, -1
    for i in range(n):
        if cut[i]:
            continue
        distance = 0.0
        for j in range(len(target)):
            distance += abs(wrapped(target[j] - nodes[i, j], wraps[j])) * weights[j]
        if distance < best:
            best, near = distance, i
    for j in range(len(target)):
        step[j] = wrapped(target[j] - nodes[near, j], wraps[j])
    return near, best


@njit(cache=True, inline="always")
def grid(segments, per, coarse, steps) -> int:
    """``steps[:segments * per]`` receives the grid's steps ``1..n`` in the order they are checked: the coarse ones
    (every ``coarse``-th and every edge's end) first, then the rest, each part ascending. Returns the coarse ones'
    count. (Counters, not ``k % coarse``: an integer division costs tens of cycles, a connection has hundreds.)"""
    n, c = segments * per, 0
    for rest in (False, True):
        since_coarse, since_end = 0, 0  # steps since the last multiple of coarse, of per
        for k in range(1, n + 1):
            since_coarse, since_end = since_coarse + 1, since_end + 1
            if since_coarse == coarse:
                since_coarse = 0
            if since_end == per:
                since_end = 0
            if (since_coarse == 0 or since_end == 0) != rest:
                steps[c] = k
                c += 1
        if not rest:
            first = c
    return first


@njit(cache=True)
def steer(nodes, n, cut, targets, row, weights, wraps, reach, resolution, coarse, connect, points, steps):
    """A move of the tree ``nodes[:n] (n, dof)`` (``cut (n,)`` marks nodes it may not grow from) towards
    ``targets[row] (dof,)``, up to its checks: the nearest node ``near``, the segment from it, ``reach`` long at most
    unless ``connect``, in ``segments`` edges of ``per`` grid steps of ``resolution`` at most (as
    ``local_planner.step_counts`` counts them), and its ``segments * per`` points in the order checked, into
    ``points (>= n, dof)`` and their steps into ``steps (>= n,)`` (:func:`grid`).

    Returns ``(near, segments, per, c, reached)``: ``c`` coarse points come first, and ``reached`` says whether the
    segment ends at the target. When ``points`` holds too few rows it fills nothing: ``c`` is -1 and the caller
    asks again with ``segments * per`` rows."""
    target, dof = targets[row], targets.shape[1]
    step = np.empty(dof)
    near, length = nearest(nodes, n, cut, target, weights, wraps, step)
    reached = connect or length <= reach
    if not reached:  # an extension short of target: one range along the way
        scale = reach / length
        for j in range(dof):
            step[j] = step[j] * scale
        length = reach
    segments = max(int(np.ceil(length / reach)), 1)  # edges, each no longer than reach: one for an extension
    per = max(int(np.ceil(length / segments / resolution)), 1)  # grid steps an edge
    total = segments * per
    if total > len(points):
        return near, segments, per, -1, reached
    c = grid(segments, per, coarse, steps)
    for i in range(total):
        fraction = steps[i] / total
        for j in range(dof):
            points[i, j] = wrapped(nodes[near, j] + fraction * step[j], wraps[j])
    return near, segments, per, c, reached
