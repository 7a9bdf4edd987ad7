"""Exact collision checking (issue 2): FCL against the separating-axis reference, grazing contacts, rules.

The checkers must agree on random configurations and on constructed contacts: a link
exactly touching an obstacle is in collision (boxes are closed sets), a gap of 1e-6 is
free, an overlap of 1e-6 is not. The constructed contacts hold the compiled checker too
(tests/test_compiled_checker.py holds it to FCL at scale).
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import linprog

from toolkit import scenarios
from toolkit.geometry import collision, robots
from toolkit.geometry.collision import (
    CompiledChecker,
    FCLChecker,
    PointRobotChecker,
    SeparatingAxisChecker,
    exact_checker,
)
from toolkit.geometry.workspace import Workspace

SCENARIOS = ["2ds", "3do", "3dc7", "3dc9"]
EPS = 1e-6
seeds = st.integers(0, 2**32 - 1)

# A chain whose sizes are powers of two, so that exact touching is exact in floating point too:
# at zero angles it spans [x, x + 1.5] x [y -+ 0.125] x [z -+ 0.125].
DYADIC = robots.BoxRobot(
    "dyadic",
    "free",
    [robots.Link((0.25, 0.125, 0.125), (0.25, 0.0, 0.0)), robots.Link((0.5, 0.125, 0.125), (0.5, 0.0, 0.0))],
    [robots.Joint((0.5, 0.0, 0.0), "z", (-2.0, 2.0))],
    position_bounds=(np.zeros(3), np.full(3, 8.0)),
)


def position_dofs(robot):
    return 2 if robot.base in ("point2d", "planar") else 3


def near_contact(robot, ws, rng, n):
    """Uniform configurations shifted until a random link's bounds overlap a random block's by -0.02 to 0.1.

    Along the other axes the link lands anywhere from just off the block's edge to just
    off the opposite one: the hard cases, where bounds meet and the boxes may or may not.
    """
    Q = robot.sample(rng, n)
    k, rows = position_dofs(robot), np.arange(n)
    link = robot.link_aabbs(Q)[rows, rng.integers(robot.n_links, size=n)]  # (n, 2, D)
    box = ws.boxes[rng.integers(len(ws.boxes), size=n)]  # (n, 2, D)
    reach = (link[:, 1] - link[:, 0]) / 2  # (n, D)
    shift = rng.uniform(box[:, 0] - reach, box[:, 1] + reach) - link.mean(axis=1)  # (n, D)
    axis, depth = rng.integers(k, size=n), rng.uniform(-0.02, 0.1, size=n)
    from_above = box[rows, 1, axis] - depth - link[rows, 0, axis]
    from_below = box[rows, 0, axis] + depth - link[rows, 1, axis]
    shift[rows, axis] = np.where(rng.random(n) < 0.5, from_above, from_below)
    Q[:, :k] = np.clip(Q[:, :k] + shift[:, :k], robot.lower[:k], robot.upper[:k])
    return Q


def checkers(ws, robot):
    found = [FCLChecker(ws, robot), SeparatingAxisChecker(ws, robot), CompiledChecker(ws, robot)]
    if robot.base == "point2d" and robot.dof == 2:
        found.append(PointRobotChecker(ws, robot))
    return found


def answers(ws, robot, Q):
    """``(checkers, N)`` validity from every exact checker of this robot."""
    return np.array([c.are_valid(Q) for c in checkers(ws, robot)])


# -- random agreement: 3,000 configurations per example, 5 examples per scenario ----------------


@pytest.mark.parametrize("name", SCENARIOS)
@settings(max_examples=5, deadline=None)
@given(seed=seeds)
def test_fcl_and_separating_axes_agree_on_random_configurations(name, seed):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(seed)
    ws = scenario.make_workspace(rng)
    Q = np.concatenate([robot.sample(rng, 2000), near_contact(robot, ws, rng, 1000)])
    by_fcl, by_sat = FCLChecker(ws, robot).are_valid(Q), SeparatingAxisChecker(ws, robot).are_valid(Q)
    np.testing.assert_array_equal(by_fcl, by_sat)
    assert 0.05 < by_fcl.mean() < 0.95
    if robot.dim == 3:  # the narrow phase had real work: valid configurations whose link bounds meet a block
        aabbs = robot.link_aabbs(Q)[:, :, None]  # (N, L, 1, 2, D)
        near = np.all((aabbs[..., 0, :] <= ws.boxes[:, 1]) & (aabbs[..., 1, :] >= ws.boxes[:, 0]), axis=-1)
        assert (near.any(axis=(1, 2)) & by_fcl).sum() >= 20


@settings(max_examples=5, deadline=None)
@given(seed=seeds)
def test_point_robot_checker_agrees_with_fcl_on_random_and_grazing_configurations(seed):
    scenario = scenarios.get("2ds")
    robot, rng = scenario.robot, np.random.default_rng(seed)
    ws = scenario.make_workspace(rng)
    # grazing: the square's centre on a block grown by its half side 0.25 (touching), and 1e-6 either side
    n, rows = 500, np.arange(500)
    grown = ws.boxes[rng.integers(len(ws.boxes), size=n)] + np.array([-0.25, 0.25])[:, None]  # (n, 2, 2)
    touching = rng.uniform(grown[:, 0], grown[:, 1])  # (n, 2)
    axis, side = rng.integers(2, size=n), rng.integers(2, size=n)
    touching[rows, axis] = grown[rows, side, axis]
    outward = np.zeros((n, 2))
    outward[rows, axis] = np.where(side == 1, EPS, -EPS)
    Q = np.concatenate([robot.sample(rng, 2000), touching, touching + outward, touching - outward])
    found = answers(ws, robot, Q)
    for other in found[:3]:  # FCL, separating axes, compiled == numpy
        np.testing.assert_array_equal(other, found[3])
    assert not found[3, 2000:2500].any()  # touching a block is a collision
    assert not found[3, 3000:].any()  # so is overlapping it by 1e-6
    assert found[3, 2500:3000].mean() > 0.1  # 1e-6 away is often free (unless another block or a wall is there)


# -- constructed contacts ------------------------------------------------------------------------


def test_point_robot_grazing_cases():
    robot = robots.point_robot()
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10, 10], [12, 12]], [[12, 12], [14, 13]]], float))
    cases = [
        ((9.75, 11.0), False),  # touches the left face
        ((9.75 - EPS, 11.0), True),  # 1e-6 gap
        ((9.75 + EPS, 11.0), False),  # 1e-6 overlap
        ((9.75, 9.75), False),  # corner touches corner
        ((9.75 - EPS, 9.75 - EPS), True),
        ((11.0, 12.25), False),  # touches the top face of the first block
        ((12.25, 11.75), False),  # the seam where two blocks touch at a corner
        ((11.75 - EPS, 12.25 + EPS), True),  # the notch beside that corner: 1e-6 from both blocks
        ((0.25, 0.25), True),  # touching the region's corner is inside it
        ((0.25 - EPS, 5.0), False),  # out of bounds
    ]
    Q = np.array([q for q, _ in cases])
    expected = np.array([valid for _, valid in cases])
    for checker in checkers(ws, robot):
        np.testing.assert_array_equal(checker.are_valid(Q), expected, err_msg=type(checker).__name__)


DYADIC_WS = Workspace(np.zeros(3), np.full(3, 8.0), np.array([[[4, 4, 4], [5, 5, 5]], [[5, 4, 4], [6, 5, 5]]], float))


@pytest.mark.parametrize(
    "base, valid",
    [
        ((2.5, 4.5, 4.5), False),  # the tip face touches the block's face x = 4
        ((2.5 - EPS, 4.5, 4.5), True),
        ((2.5 + EPS, 4.5, 4.5), False),
        ((3.0, 3.875, 3.875), False),  # a link edge touches the block's edge y = z = 4
        ((3.0, 3.875 - EPS, 3.875), True),
        ((3.0, 3.875 + EPS, 3.875 + EPS), False),
        ((2.5, 3.875, 3.875), False),  # the tip's corner touches the block's corner (4, 4, 4)
        ((2.5, 3.875, 3.875 - EPS), True),
        ((2.5 - EPS, 3.875 + EPS, 3.875 + EPS), True),
        ((4.0, 4.5, 5.125), False),  # lying on the top of both blocks, across the seam where they touch
        ((4.0, 4.5, 5.125 + EPS), True),
        ((4.0, 5.125, 4.5), False),  # against the side of both blocks
        ((4.0, 5.125 + EPS, 4.5), True),
        ((6.5, 4.5, 4.5), True),  # beyond the second block, nothing near
        ((6.5, 4.5, 0.125), True),  # touching the floor from inside the region
        ((6.5, 4.5, 0.125 - EPS), False),  # 1e-6 through the floor
        ((6.5, 7.875, 2.0), True),  # touching the side wall
        ((6.5 + EPS, 2.0, 2.0), False),  # the tip 1e-6 past the wall x = 8
    ],
)
def test_dyadic_chain_grazing_cases(base, valid):
    q = np.concatenate([base, np.zeros(4)])
    for checker in checkers(DYADIC_WS, DYADIC):
        assert checker.is_valid(q) == valid, type(checker).__name__


def contact_offset(robot, q, size, anchor, direction):
    """Largest ``t`` at which the box ``anchor + t * direction + [0, size]`` still meets the robot at ``q``.

    An independent reference: one linear program per link (scipy's HiGHS), maximising
    ``t`` over a point ``c + R a`` of the link (``|a| <= half``) that is also a point
    ``anchor + u + t * direction`` of the box (``0 <= u <= size``). ``-inf`` if none meets.
    """
    centers, rotations, half = robot.link_boxes(q)
    d, best = robot.dim, -np.inf
    for c, R, h in zip(centers[0], rotations[0], half):
        A = np.hstack([R, -np.eye(d), -direction[:, None]])  # unknowns: a (D), u (D), t
        bounds = [(-x, x) for x in h] + [(0, s) for s in size] + [(None, None)]
        cost = np.zeros(2 * d + 1)
        cost[-1] = -1.0
        result = linprog(
            cost,
            A_eq=A,
            b_eq=anchor - c,
            bounds=bounds,
            method="highs",
            options={"primal_feasibility_tolerance": 1e-10, "dual_feasibility_tolerance": 1e-10},
        )
        if result.status == 0:
            best = max(best, result.x[-1])
    return best


@pytest.mark.parametrize("name", ["3do", "3dc7", "3dc9"])
@settings(max_examples=30, deadline=None)
@given(seed=seeds)
def test_turned_links_grazing_a_block_by_linear_programming(name, seed):
    """A block slides along an axis until it last meets the robot: 1e-6 further is free, 1e-6 back is not."""
    robot, rng = scenarios.get(name).robot, np.random.default_rng(seed)
    region = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]) if name == "3do" else np.full(3, 11.0), [])
    Q = robot.sample(rng, 200)
    Q[:, :2] = rng.uniform(4, 7, size=(200, 2))  # away from the region's walls
    aabbs = robot.link_aabbs(Q)
    inside = np.all((aabbs[:, :, 0] >= region.lower) & (aabbs[:, :, 1] <= region.upper), axis=(1, 2))
    q = Q[np.flatnonzero(inside)[0]]
    centers, _, _ = robot.link_boxes(q)
    target = centers[0, rng.integers(robot.n_links)]
    direction = np.eye(3)[rng.integers(3)] * rng.choice([-1.0, 1.0])
    size = rng.uniform(0.3, 2.0, size=3)
    anchor = target - size * rng.uniform(0.1, 0.9, size=3)  # the block's cross-section covers the link's centre
    t = contact_offset(robot, q[None], size, anchor, direction)
    assert np.isfinite(t)
    for gap, valid in ((EPS, True), (-EPS, False)):
        lo = anchor + (t + gap) * direction
        ws = Workspace(region.lower, region.upper, np.array([[lo, lo + size]]))
        for checker in checkers(ws, robot):
            assert checker.is_valid(q) == valid, (type(checker).__name__, gap)


# -- the rules: bounds, region, counting, errors ---------------------------------------------------


def test_out_of_bounds_and_out_of_region_are_invalid():
    robot = robots.box_chain(1)  # spans [x, x + 0.5] along +x at zero angles
    empty = Workspace(np.zeros(3), np.full(3, 11.0), [])
    cases = [
        ((5, 5, 5, 0, 0, 0, 0), True),
        ((5, 5, 5, 0, 0, 0, 2.01), False),  # joint beyond its limit
        ((5, 5, 11.01, 0, 0, 0, 0), False),  # base beyond the position bounds
        ((10.7, 5, 5, 0, 0, 0, 0), False),  # base in bounds, tip out of the region
        ((10.7, 5, 5, np.pi, 0, 0, 0), True),  # turned round: inside again
        ((5, 5, 0.04, 0, 0, 0, 0), False),  # the link's lower face below the floor
        ((5, 5, 0.06, 0, 0, 0, 0), True),
    ]
    Q = np.array([q for q, _ in cases], dtype=float)
    expected = np.array([valid for _, valid in cases])
    for checker in checkers(empty, robot):
        np.testing.assert_array_equal(checker.are_valid(Q), expected, err_msg=type(checker).__name__)


def test_youbot_must_stay_in_the_office_region():
    robot = robots.youbot()
    empty = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]), [])
    upright = np.array([20, 20, 0.3, 0, 0, 0, 0, 0], dtype=float)
    by_the_wall = upright.copy()
    by_the_wall[0] = 0.5  # the 1.5-long base sticks out of x = 0
    bowing = upright.copy()
    bowing[4:6] = [1.5, 1.6]  # shoulder flat, elbow bent straight down: the gripper goes through the floor
    assert robot.link_aabbs(bowing)[0, -1, 0, 2] < 0
    for checker in checkers(empty, robot):
        np.testing.assert_array_equal(checker.are_valid([upright, by_the_wall, bowing]), [True, False, False])


def test_counter_and_single_configurations():
    scenario = scenarios.get("3dc7")
    ws = scenario.make_workspace(np.random.default_rng(0))
    checker = FCLChecker(ws, scenario.robot)
    Q = scenario.robot.sample(np.random.default_rng(1), 10)
    batch = checker.are_valid(Q)
    assert checker.n_checked == 10
    singles = [checker.is_valid(q) for q in Q]
    assert singles == list(batch) and all(type(s) is bool for s in singles)
    assert checker.n_checked == 20
    checker.are_valid(np.zeros((0, 7)))
    assert checker.n_checked == 20
    checker.reset_count()
    assert checker.n_checked == 0
    assert checker.are_valid(np.zeros((0, 7))).shape == (0,)


def test_bad_input_is_named():
    scenario = scenarios.get("3dc9")
    checker = FCLChecker(scenario.make_workspace(np.random.default_rng(0)), scenario.robot)
    with pytest.raises(ValueError, match=r"must have shape \(N, 9\)"):
        checker.are_valid(np.zeros((4, 7)))
    with pytest.raises(ValueError, match="NaN or infinite"):
        checker.are_valid(np.full((2, 9), np.nan))
    with pytest.raises(ValueError, match=r"q must have shape \(9,\)"):
        checker.is_valid(np.zeros((1, 9)))
    assert checker.n_checked == 0


def test_robot_and_workspace_dimensions_must_match():
    plane = scenarios.get("2ds").make_workspace(np.random.default_rng(0))
    room = scenarios.get("3dc7").make_workspace(np.random.default_rng(0))
    for make in (FCLChecker, SeparatingAxisChecker, CompiledChecker):
        with pytest.raises(ValueError, match="robot 'chain9' is 3D but the workspace is 2D"):
            make(plane, robots.box_chain(3))
        with pytest.raises(ValueError, match="robot 'point2d' is 2D but the workspace is 3D"):
            make(room, robots.point_robot())
    with pytest.raises(ValueError, match="needs the 2D point robot"):
        PointRobotChecker(room, robots.box_chain(1))


def test_exact_checker_picks_the_fastest_exact_one():
    plane = scenarios.get("2ds").make_workspace(np.random.default_rng(0))
    assert type(exact_checker(plane, robots.point_robot())) is PointRobotChecker
    room = scenarios.get("3dc9").make_workspace(np.random.default_rng(0))
    assert type(exact_checker(room, robots.box_chain(3))) is CompiledChecker
    arm = robots.BoxRobot(  # a 2D base with a joint: no longer a lone square
        "arm2d",
        "point2d",
        [robots.Link((0.25, 0.25)), robots.Link((0.5, 0.1))],
        [robots.Joint((0.5, 0, 0), "z", (-1, 1))],
        position_bounds=(plane.lower, plane.upper),
    )
    assert type(exact_checker(plane, arm)) is CompiledChecker


def test_exact_checker_reads_one_table(monkeypatch):
    """Issue 48: the choice is a table, not an if-chain: a row for a workspace kind of one's own is taken first."""

    class Walled(Workspace):
        pass

    room = scenarios.get("3dc9").make_workspace(np.random.default_rng(0))
    walled, robot = Walled(room.lower, room.upper, room.boxes), robots.box_chain(3)
    monkeypatch.setattr(
        collision, "EXACT_CHECKERS", [(Walled, collision.any_robot, FCLChecker)] + collision.EXACT_CHECKERS
    )
    assert type(exact_checker(walled, robot)) is FCLChecker and type(exact_checker(room, robot)) is CompiledChecker
    with pytest.raises(ValueError, match=r"^no exact checker for a str and robot 'chain9'$"):
        exact_checker("room", robot)


# -- clearance bounds: below FCL's distances, and not vacuous --------------------------------


def true_clearance(ws, robot, q, cap):
    """Min over links of FCL's distance to every block and the exact distance to the walls (corners), capped."""
    import fcl

    centers, rotations, half = robot.link_boxes(q[None])
    distance = cap
    for l in range(robot.n_links):
        corners = centers[0, l] + (np.array(list(np.ndindex(*(2,) * robot.dim))) * 2 - 1) * half[l] @ rotations[0, l].T
        walls = np.minimum(corners - ws.lower, ws.upper - corners)  # (2^D, D)
        if l < robot.level_links:  # never moves vertically: floor and ceiling are out of reach
            walls = walls[:, :-1]
        distance = min(distance, walls.min())
        R, c, h = np.eye(3), np.zeros(3), np.full(3, 0.5)
        R[: robot.dim, : robot.dim], c[: robot.dim], h[: robot.dim] = rotations[0, l], centers[0, l], half[l]
        link = fcl.CollisionObject(fcl.Box(*(2 * h)), fcl.Transform(R, c))
        for lo, hi in ws.boxes:
            lo3, hi3 = np.full(3, -1.0), np.full(3, 1.0)
            lo3[: robot.dim], hi3[: robot.dim] = lo, hi
            box = fcl.CollisionObject(fcl.Box(*(hi3 - lo3)), fcl.Transform((lo3 + hi3) / 2))
            distance = min(distance, fcl.distance(link, box, fcl.DistanceRequest(), fcl.DistanceResult()))
    return max(distance, 0.0)


@pytest.mark.parametrize("name", SCENARIOS)
def test_clearances_bound_fcl_distances_from_below_and_closely(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(3)
    ws = scenario.make_workspace(rng)
    exact, cap = exact_checker(ws, robot), 0.5
    Q = np.concatenate([robot.sample(rng, 100), near_contact(robot, ws, rng, 300)])
    Q = Q[exact.are_valid(Q)][:150]
    bound = exact.clearances(Q, cap)
    truth = np.array([true_clearance(ws, robot, q, cap) for q in Q])
    assert np.all((bound >= 0) & (bound <= truth + 1e-9))  # a lower bound
    near = truth < cap
    assert near.sum() >= 20 and np.median(bound[near] / truth[near]) > 0.9  # and mostly a tight one
    assert exact.n_bounded == len(Q)


def test_clearances_are_zero_where_invalid_and_positive_proves_validity():
    scenario = scenarios.get("3dc9")
    robot, rng = scenario.robot, np.random.default_rng(4)
    ws = scenario.make_workspace(rng)
    exact = exact_checker(ws, robot)
    Q = np.concatenate([robot.sample(rng, 1000), near_contact(robot, ws, rng, 1000)])
    Q[:50, 0] = robot.upper[0] + 1  # out of bounds
    bound, valid = exact.clearances(Q, 0.1), exact.are_valid(Q)
    assert np.all(valid[bound > 0]) and np.all(bound[~valid] == 0)
    assert (bound > 0).sum() > 0.5 * valid.sum()
    for bad in (0.0, -1.0, np.nan, np.inf):
        with pytest.raises(ValueError, match="cap must be positive"):
            exact.clearances(Q[:3], bad)


def test_level_links_never_move_vertically():
    robot, rng = robots.youbot(), np.random.default_rng(5)
    assert robot.level_links == 2  # the base and the turret, turned about vertical axes
    assert robots.box_chain(3).level_links == 0 and robots.point_robot().level_links == 0
    Q = robot.sample(rng, 200)
    moved = robot.sample(rng, 200)
    heights = robot.link_aabbs(Q)[:, :, :, 2], robot.link_aabbs(moved)[:, :, :, 2]  # (N, L, 2) each
    np.testing.assert_allclose(heights[0][:, :2], heights[1][:, :2], atol=1e-12)
    assert np.abs(heights[0][:, 2:] - heights[1][:, 2:]).max() > 0.1  # the arm does
