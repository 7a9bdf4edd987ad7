"""RRT-Connect's compiled move (toolkit.planning.rrt_kernels) against the same move written in numpy: the nearest
node, the step to the target with angles wrapped, the extension's length, the grid's order; on random trees and
targets of three robots, with cut nodes, extensions and connections."""

import numpy as np
import pytest
from numba import njit

from toolkit import scenarios
from toolkit.planning import rrt_kernels
from toolkit.planning.local_planner import step_counts


@njit(cache=True)
def wrap_each(X, wraps):
    """``X (N, dof)`` through :func:`rrt_kernels.wrapped`, a copy."""
    out = np.empty_like(X)
    for i in range(X.shape[0]):
        for j in range(X.shape[1]):
            out[i, j] = rrt_kernels.wrapped(X[i, j], wraps[j])
    return out


def reference(robot, nodes, cut, target, reach, resolution, coarse, connect):
    """The move in numpy: ``(near, segments, per, steps (n,), points (n, dof))``, the grid in the order checked."""
    steps = robot.wrap(target - nodes)  # (N, dof) from each node to target, angles the short way round
    distance = np.where(cut, np.inf, np.abs(steps) @ robot.motion_weights)  # (N,)
    near = int(distance.argmin())
    step, length = steps[near], distance[near]
    if not connect and length > reach:
        step, length = step * (reach / length), reach
    segments = max(int(np.ceil(length / reach)), 1)
    per = max(int(np.ceil(length / segments / resolution)), 1)
    k = np.arange(1, segments * per + 1)  # (n,)
    first = (k % coarse == 0) | (k % per == 0)
    order = np.concatenate([k[first], k[~first]])
    return near, segments, per, int(first.sum()), order, robot.wrap(nodes[near] + (order / len(k))[:, None] * step)


def test_wrapped_is_robot_wrap_bit_for_bit_where_a_move_reaches_and_close_beyond():
    robot = scenarios.get("3dc9").robot  # a free base: three angles among nine coordinates
    rng = np.random.default_rng(0)
    X = rng.uniform(-2 * np.pi, 2 * np.pi, size=(2000, robot.dof))  # a move's differences and points lie here
    edges = np.array([-2 * np.pi, -np.pi, -1e-300, 0.0, -0.0, 1e-17, np.pi, np.pi - 1e-16, 2 * np.pi - 1e-15, 6.0])
    X[: len(edges)] = edges[:, None]
    wraps = np.array(robot.wraps)
    np.testing.assert_array_equal(wrap_each(X, wraps), robot.wrap(X.copy()))
    far = rng.uniform(-50, 50, size=(2000, robot.dof))
    np.testing.assert_allclose(wrap_each(far, wraps), robot.wrap(far.copy()), rtol=0, atol=1e-12)
    assert (wrap_each(far, wraps)[:, wraps] < np.pi).all() and (wrap_each(far, wraps)[:, wraps] >= -np.pi).all()


@pytest.mark.parametrize("name", ["3dc9", "3do", "2ds"])
def test_steer_agrees_with_numpy(name):
    robot = scenarios.get(name).robot
    rng = np.random.default_rng(1)
    resolution, coarse = 0.05, 8
    points, grid_steps = np.empty((20_000, robot.dof)), np.empty(20_000, dtype=np.int64)
    weights, wraps = np.array(robot.motion_weights), np.array(robot.wraps)
    for trial in range(60):
        n = int(rng.integers(1, 40))
        nodes = np.zeros((64, robot.dof))
        nodes[:n] = robot.sample(rng, n)
        cut = np.zeros(64, dtype=bool)
        cut[1:n] = rng.random(n - 1) < 0.3  # a tree's root is never cut
        targets = robot.sample(rng, 4)
        connect, reach = bool(trial % 2), float(rng.uniform(0.5, 4.0))
        near, segments, per, c, reached = rrt_kernels.steer(
            nodes, n, cut, targets, 2, weights, wraps, reach, resolution, coarse, connect, points, grid_steps
        )
        want = reference(robot, nodes[:n], cut[:n], targets[2], reach, resolution, coarse, connect)
        assert (near, segments, per, c) == want[:4] and not cut[near]
        total = segments * per
        np.testing.assert_array_equal(grid_steps[:total], want[4])
        np.testing.assert_allclose(points[:total], want[5], rtol=0, atol=1e-12)
        end = points[c - 1]  # the segment's end: the target when reached
        assert reached == (connect or np.allclose(end, targets[2], rtol=0, atol=1e-12))
        if segments == 1:  # one edge of per steps, as the local planner counts them
            assert step_counts(robot, nodes[near][None], end[None], resolution)[0] == per


def test_steer_asks_for_room_when_the_grid_does_not_fit():
    robot = scenarios.get("3dc7").robot
    rng = np.random.default_rng(2)
    nodes, targets = robot.sample(rng, 3), robot.sample(rng, 1)
    args = (nodes, 3, np.zeros(3, dtype=bool), targets, 0, np.array(robot.motion_weights), np.array(robot.wraps))
    small = (np.empty((4, robot.dof)), np.empty(4, dtype=np.int64))
    near, segments, per, c, reached = rrt_kernels.steer(*args, 0.5, 0.05, 8, True, *small)
    assert c == -1 and reached and segments * per > 4
    room = (np.empty((segments * per, robot.dof)), np.empty(segments * per, dtype=np.int64))
    k = np.arange(1, segments * per + 1)
    coarse = int(((k % 8 == 0) | (k % per == 0)).sum())
    assert rrt_kernels.steer(*args, 0.5, 0.05, 8, True, *room) == (near, segments, per, coarse, True)
