"""Robots (issue 2, paper §IV-A): kinematics against 4x4 matrices, bounds, interpolation, motion bound."""

import itertools

import numpy as np
import pytest
import trimesh.transformations as tf

from toolkit.geometry import robots

ROBOTS = {
    "point2d": robots.point_robot(),
    "youbot": robots.youbot(),
    "chain7": robots.box_chain(1),
    "chain9": robots.box_chain(3),
}
AXIS_VECTORS = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}


def corner_signs(dim):
    return np.array(list(itertools.product([-1.0, 1.0], repeat=dim)))  # (2^D, D)


def reference_corners(robot, q):
    """World corners ``(L, 2^D, D)`` of one configuration, chaining 4x4 homogeneous matrices."""
    if robot.base == "point2d":
        frame, n_base = tf.translation_matrix([q[0], q[1], 0.0]), 2
    elif robot.base == "planar":
        frame = tf.translation_matrix([q[0], q[1], robot.base_height]) @ tf.rotation_matrix(q[2], [0, 0, 1])
        n_base = 3
    else:  # x, y, z, then Z-Y-X Euler angles about the turning axes
        frame, n_base = tf.translation_matrix(q[:3]) @ tf.euler_matrix(q[3], q[4], q[5], "rzyx"), 6
    frames = [frame]
    for joint, angle in zip(robot.joints, q[n_base:]):
        frame = frame @ tf.translation_matrix(joint.origin) @ tf.rotation_matrix(angle, AXIS_VECTORS[joint.axis])
        frames.append(frame)
    corners = []
    for frame, link in zip(frames, robot.links):
        local = np.zeros((2**robot.dim, 4))
        local[:, :3] = link.offset
        local[:, : robot.dim] += corner_signs(robot.dim) * np.array(link.half_extents[: robot.dim])
        local[:, 3] = 1.0
        corners.append((local @ frame.T)[:, : robot.dim])
    return np.array(corners)


def corners_of(robot, Q):
    """World corners ``(N, L, 2^D, D)`` from ``link_boxes``."""
    centers, rotations, half = robot.link_boxes(Q)
    local = corner_signs(robot.dim)[None, :, :] * half[:, None, :]  # (L, 2^D, D)
    return centers[:, :, None, :] + np.einsum("nlij,lkj->nlki", rotations, local)


def config(robot, **values):
    q = np.zeros(robot.dof)
    for name, value in values.items():
        q[robot.dof_names.index(name)] = value
    return q


# -- forward kinematics ---------------------------------------------------------------


@pytest.mark.parametrize("name", list(ROBOTS))
def test_link_boxes_match_homogeneous_matrices(name, rng):
    robot = ROBOTS[name]
    Q = robot.sample(rng, 64)
    got = corners_of(robot, Q)
    expected = np.array([reference_corners(robot, q) for q in Q])
    np.testing.assert_allclose(got, expected, atol=1e-12)


@pytest.mark.parametrize("name, links", [("point2d", 1), ("youbot", 6), ("chain7", 2), ("chain9", 4)])
def test_link_boxes_shapes_follow_the_contract(name, links, rng):
    robot = ROBOTS[name]
    d = robot.dim
    centers, rotations, half = robot.link_boxes(robot.sample(rng, 5))
    assert (centers.shape, rotations.shape, half.shape) == ((5, links, d), (5, links, d, d), (links, d))
    assert robot.n_links == links
    assert robot.link_aabbs(robot.sample(rng, 5)).shape == (5, links, 2, d)


@pytest.mark.parametrize("name", list(ROBOTS))
def test_rotations_are_proper(name, rng):
    robot = ROBOTS[name]
    _, rotations, _ = robot.link_boxes(robot.sample(rng, 200))
    eye = np.eye(robot.dim)
    product = rotations @ np.swapaxes(rotations, -1, -2)
    np.testing.assert_allclose(product, np.broadcast_to(eye, rotations.shape), atol=1e-12)
    np.testing.assert_allclose(np.linalg.det(rotations), 1.0, atol=1e-12)


def test_chain9_hand_worked_configurations():
    robot = ROBOTS["chain9"]
    straight = config(robot, x=1, y=2, z=3)
    elbow = config(robot, x=1, y=2, z=3, joint1=np.pi / 2)
    centers, rotations, half = robot.link_boxes(np.array([straight, elbow]))
    np.testing.assert_allclose(half, [[0.05, 0.05, 0.05], [0.2, 0.05, 0.05]] * 2)  # 0.1^3 and 0.4x0.1x0.1 links
    np.testing.assert_allclose(centers[0], [[1.05, 2, 3], [1.3, 2, 3], [1.55, 2, 3], [1.8, 2, 3]], atol=1e-12)
    np.testing.assert_allclose(rotations[0], np.broadcast_to(np.eye(3), (4, 3, 3)), atol=1e-12)
    # the first joint sits at the small link's far face and turns the rest about z: the chain goes +y
    np.testing.assert_allclose(centers[1], [[1.05, 2, 3], [1.1, 2.2, 3], [1.1, 2.45, 3], [1.1, 2.7, 3]], atol=1e-12)
    np.testing.assert_allclose(rotations[1, 3], [[0, -1, 0], [1, 0, 0], [0, 0, 1]], atol=1e-12)


@pytest.mark.parametrize(
    "angles, small, big",
    [
        ({"alpha": np.pi / 2}, [1, 2.05, 3], [1, 2.3, 3]),  # yaw: the chain points along +y
        ({"beta": np.pi / 2}, [1, 2, 2.95], [1, 2, 2.7]),  # pitch about y: +x turns to -z
        ({"gamma": 1.0}, [1.05, 2, 3], [1.3, 2, 3]),  # roll about the chain's own axis
        ({"alpha": np.pi / 2, "beta": np.pi / 2}, [1, 2, 2.95], [1, 2, 2.7]),  # Z then the turned Y
    ],
)
def test_chain7_base_angles(angles, small, big):
    robot = ROBOTS["chain7"]
    centers, _, _ = robot.link_boxes(config(robot, x=1, y=2, z=3, **angles))
    np.testing.assert_allclose(centers[0], [small, big], atol=1e-12)


def test_youbot_is_the_papers_size_and_stands_upright_at_zero():
    robot = ROBOTS["youbot"]
    centers, _, _ = robot.link_boxes(config(robot, x=5, y=6))
    np.testing.assert_allclose(centers[0, :, :2], [[5, 6]] + [[5.45, 6]] * 5, atol=1e-12)  # the arm stands at x + 0.45
    assert np.all(np.diff(centers[0, :, 2]) > 0)  # each link above the previous one
    corners = corners_of(robot, config(robot, x=5, y=6)).reshape(-1, 3)
    size = corners.max(axis=0) - corners.min(axis=0)
    np.testing.assert_allclose(size, [1.5, 1.0, 1.0], atol=0.05)  # paper: "the size of (1.5x1x1)"
    assert corners[:, 2].min() > 0  # clear of the floor
    turned, _, _ = robot.link_boxes(config(robot, x=5, y=6, yaw=np.pi / 2))
    np.testing.assert_allclose(turned[0, 1, :2], [5, 6.45], atol=1e-12)


def test_point_robot_is_a_half_unit_square():
    robot = ROBOTS["point2d"]
    centers, rotations, half = robot.link_boxes(np.array([[3.0, 4.0], [10.5, 0.25]]))
    np.testing.assert_array_equal(centers[:, 0], [[3, 4], [10.5, 0.25]])
    np.testing.assert_array_equal(rotations, np.broadcast_to(np.eye(2), (2, 1, 2, 2)))
    np.testing.assert_array_equal(half, [[0.25, 0.25]])


@pytest.mark.parametrize("name", list(ROBOTS))
def test_link_aabbs_are_the_tight_bounds_of_the_corners(name, rng):
    robot = ROBOTS[name]
    Q = robot.sample(rng, 100)
    corners = corners_of(robot, Q)  # (N, L, 2^D, D)
    aabbs = robot.link_aabbs(Q)
    np.testing.assert_allclose(aabbs[:, :, 0], corners.min(axis=2), atol=1e-12)
    np.testing.assert_allclose(aabbs[:, :, 1], corners.max(axis=2), atol=1e-12)


# -- configuration space ------------------------------------------------------------------


def test_bounds_and_wrapping_dofs():
    pi = np.pi
    point, youbot, chain7, chain9 = ROBOTS.values()
    np.testing.assert_array_equal(point.lower, [0.25, 0.25])
    np.testing.assert_array_equal(point.upper, [30.75, 30.75])
    assert youbot.dof == 8 and youbot.dof_names[:3] == ("x", "y", "yaw")
    np.testing.assert_array_equal(youbot.lower[:3], [0, 0, -pi])
    np.testing.assert_array_equal(youbot.upper[:3], [41, 41, pi])
    np.testing.assert_array_equal(youbot.wraps, [False, False, True] + [False] * 5)
    assert np.all(youbot.lower[3:] < 0) and np.all(youbot.upper[3:] > 0)
    for chain, dof in ((chain7, 7), (chain9, 9)):
        assert chain.dof == dof
        np.testing.assert_array_equal(chain.lower, [0, 0, 0, -pi, -pi, -pi] + [-2.0] * (dof - 6))
        np.testing.assert_array_equal(chain.upper, [11, 11, 11, pi, pi, pi] + [2.0] * (dof - 6))
        np.testing.assert_array_equal(chain.wraps, [False] * 3 + [True] * 3 + [False] * (dof - 6))


@pytest.mark.parametrize("name", list(ROBOTS))
def test_wrap_maps_only_the_angles_into_minus_pi_to_pi_in_place(name, rng):
    robot = ROBOTS[name]
    Q = rng.uniform(-20, 20, size=(500, robot.dof))
    wrapped = robot.wrap(Q.copy())
    np.testing.assert_array_equal(wrapped[:, ~robot.wraps], Q[:, ~robot.wraps])
    angles = wrapped[:, robot.wraps]
    assert np.all((angles >= -np.pi) & (angles < np.pi))
    np.testing.assert_allclose(np.cos(angles), np.cos(Q[:, robot.wraps]), atol=1e-9)  # the same angle
    np.testing.assert_allclose(np.sin(angles), np.sin(Q[:, robot.wraps]), atol=1e-9)
    assert robot.wrap(Q) is Q and np.array_equal(Q, wrapped)  # in place


@pytest.mark.parametrize("name", list(ROBOTS))
def test_sample_is_uniform_within_bounds_and_reproducible(name):
    robot = ROBOTS[name]
    Q = robot.sample(np.random.default_rng(5), 4000)
    assert Q.shape == (4000, robot.dof)
    assert np.all(robot.in_bounds(Q))
    np.testing.assert_array_equal(Q, robot.sample(np.random.default_rng(5), 4000))
    assert not np.array_equal(Q, robot.sample(np.random.default_rng(6), 4000))
    span = robot.upper - robot.lower
    np.testing.assert_allclose(Q.mean(axis=0), (robot.lower + robot.upper) / 2, atol=0.03 * span.max())
    np.testing.assert_allclose(Q.min(axis=0), robot.lower, atol=0.01 * span.max())
    np.testing.assert_allclose(Q.max(axis=0), robot.upper, atol=0.01 * span.max())


def test_in_bounds():
    robot = ROBOTS["chain7"]
    Q = np.array([robot.lower, robot.upper, (robot.lower + robot.upper) / 2, robot.upper + 1e-9 * np.eye(7)[6]])
    np.testing.assert_array_equal(robot.in_bounds(Q), [True, True, True, False])


def test_interpolate_endpoints_and_midpoint(rng):
    robot = ROBOTS["chain9"]
    q0, q1 = robot.sample(rng, 2)
    path = robot.interpolate(q0, q1, np.linspace(0, 1, 11))
    assert path.shape == (11, 9)
    np.testing.assert_allclose(path[0], q0, atol=1e-12)
    np.testing.assert_allclose(path[-1], q1, atol=1e-12)
    np.testing.assert_allclose(path[5, [0, 1, 2, 6, 7, 8]], (q0 + q1)[[0, 1, 2, 6, 7, 8]] / 2, atol=1e-12)
    assert robot.interpolate(q0, q1, 0.5).shape == (1, 9)


def test_interpolate_takes_the_short_way_round():
    robot = ROBOTS["chain7"]
    q0, q1 = config(robot, x=1, alpha=3.0, joint1=-1.9), config(robot, x=2, alpha=-3.0, joint1=1.9)
    path = robot.interpolate(q0, q1, np.linspace(0, 1, 101))
    alpha = path[:, 3]
    assert np.all(np.abs(alpha) >= 3.0 - 1e-12)  # through +-pi, never through 0
    np.testing.assert_allclose(abs(alpha[50]), np.pi, atol=1e-12)
    np.testing.assert_allclose(robot.interpolate(q0, q1, 0.25)[0, 3], 3.0 + 0.25 * (2 * np.pi - 6.0), atol=1e-12)
    assert np.all(robot.in_bounds(path))
    joint = path[:, 6]  # joints have limits: no wrap-around, straight through 0
    np.testing.assert_allclose(joint, np.linspace(-1.9, 1.9, 101), atol=1e-12)
    yaw = ROBOTS["youbot"].interpolate(config(ROBOTS["youbot"], yaw=-3.0), config(ROBOTS["youbot"], yaw=3.0), [0.5])
    np.testing.assert_allclose(abs(yaw[0, 2]), np.pi, atol=1e-12)


def test_distance_is_symmetric_and_wrap_aware(rng):
    robot = ROBOTS["chain9"]
    Q0, Q1 = robot.sample(rng, 300), robot.sample(rng, 300)
    d = robot.distance(Q0, Q1)
    np.testing.assert_allclose(d, robot.distance(Q1, Q0), atol=1e-12)
    assert np.all(d <= np.linalg.norm(Q1 - Q0, axis=1) + 1e-12)
    np.testing.assert_allclose(robot.distance(Q0, Q0), 0.0)
    q0, q1 = config(robot, alpha=3.0, beta=-3.0), config(robot, alpha=-3.0, beta=3.0)
    np.testing.assert_allclose(robot.distance(q0, q1), np.sqrt(2) * (2 * np.pi - 6.0), atol=1e-12)
    pairwise = robot.distance(Q0[:10, None], Q0[None, :10])  # leading axes broadcast
    assert pairwise.shape == (10, 10)
    np.testing.assert_allclose(pairwise, pairwise.T, atol=1e-12)
    np.testing.assert_allclose(pairwise[3, 7], robot.distance(Q0[3], Q0[7]), atol=1e-12)
    q2 = config(robot, x=3.0, joint1=2.0)
    np.testing.assert_allclose(robot.distance(config(robot, joint1=-2.0), q2), 5.0, atol=1e-12)  # joints do not wrap


@pytest.mark.parametrize("name", list(ROBOTS))
def test_motion_bound_bounds_every_corner_path(name, rng):
    robot = ROBOTS[name]
    Q0 = robot.sample(rng, 40)
    Q1 = Q0 + rng.normal(scale=0.3, size=Q0.shape) * (robot.upper - robot.lower) / 4
    Q1 = np.clip(Q1, robot.lower, robot.upper)
    bound = robot.motion_bound(Q0, Q1)
    t = np.linspace(0, 1, 400)
    for q0, q1, b in zip(Q0, Q1, bound):
        corners = corners_of(robot, robot.interpolate(q0, q1, t))  # (T, L, 2^D, D)
        travelled = np.linalg.norm(np.diff(corners, axis=0), axis=-1).sum(axis=0)  # (L, 2^D)
        assert travelled.max() <= b + 1e-9
        assert travelled.max() > 0.2 * b  # a bound, but not a vacuous one


def test_motion_bound_is_exact_for_a_translation():
    robot = ROBOTS["chain9"]
    q0 = config(robot, x=1, y=1, z=1, alpha=0.3, joint2=1.0)
    q1 = q0 + np.eye(9)[1] * 0.7
    np.testing.assert_allclose(robot.motion_bound(q0, q1), 0.7)


# -- bad input ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "Q, message",
    [
        (np.zeros((3, 8)), r"Q must have shape \(N, 9\) or \(9,\) for robot 'chain9', got \(3, 8\)"),
        (np.zeros(10), r"got \(10,\)"),
        (np.zeros((2, 3, 9)), r"got \(2, 3, 9\)"),
        (np.zeros(()), r"got \(\)"),
        (np.full((2, 9), np.nan), "Q contains NaN or infinite values"),
        (np.array([[0.0] * 8 + [np.inf]]), "Q contains NaN or infinite values"),
    ],
)
def test_bad_configurations_are_named(Q, message):
    robot = ROBOTS["chain9"]
    for call in (robot.link_boxes, robot.link_aabbs, robot.link_frames, robot.check_configs):
        with pytest.raises(ValueError, match=message):
            call(Q)


def test_bad_segments_are_named():
    robot = ROBOTS["youbot"]
    q = np.zeros(8)
    with pytest.raises(ValueError, match=r"Q1 must have shape \(\.\.\., 8\) for robot 'youbot', got \(7,\)"):
        robot.distance(q, np.zeros(7))
    with pytest.raises(ValueError, match=r"Q0 must have shape \(\.\.\., 8\)"):
        robot.difference(5.0, q)
    with pytest.raises(ValueError, match="Q0 contains NaN"):
        robot.motion_bound(np.full(8, np.nan), q)
    with pytest.raises(ValueError, match=r"q0 must have shape"):
        robot.interpolate(np.zeros(9), q, [0.5])
    with pytest.raises(ValueError, match="t contains NaN"):
        robot.interpolate(q, q, [0.0, np.nan])


def test_box_chain_with_another_joint_count_is_refused():
    with pytest.raises(ValueError, match="1 or 3 joints, not 2"):
        robots.box_chain(2)
