"""The compiled exact checker (issue 25) gives the python-fcl reference's answers, and the separating-axis one's.

Per scenario: 100,000 uniform configurations (FCL on all, the numpy separating-axis reference
on a share), then pairs of configurations within 1e-6 of each other on either side of the
boundary of the free space (obstacles and the region's walls), found by bisection, and
configurations on the robot's bounds: every one goes to all three checkers. Then exact
contacts (faces, edges, corners touching in exact arithmetic), a 2D arm, user workspaces
with boxes of any size at any place, and the clearance bounds against the numpy ones.
"""

import subprocess
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from toolkit import scenarios
from toolkit.geometry import robots
from toolkit.geometry.box_world import BoxGrid, BoxWorldChecker
from toolkit.geometry.collision import (
    CompiledChecker,
    CompiledMeshChecker,
    FCLChecker,
    PointRobotChecker,
    SeparatingAxisChecker,
    exact_checker,
)
from toolkit.geometry.robots import BoxRobot, Joint, Link
from toolkit.geometry.workspace import Workspace, from_mesh

SCENARIOS = ["2ds", "3do", "3dc7", "3dc9"]
seeds = st.integers(0, 2**32 - 1)


def three_answers(ws, robot, Q) -> np.ndarray:
    """``(3, N)`` validity by the compiled, the FCL and the separating-axis checkers."""
    return np.array([make(ws, robot).are_valid(Q) for make in (CompiledChecker, FCLChecker, SeparatingAxisChecker)])


def assert_all_agree(ws, robot, Q) -> np.ndarray:
    compiled, fcl, sat = three_answers(ws, robot, Q)
    np.testing.assert_array_equal(compiled, fcl, err_msg="compiled vs FCL")
    np.testing.assert_array_equal(compiled, sat, err_msg="compiled vs separating axes")
    return compiled


def straddle_the_boundary(checker, rng, n, tol=1e-6):
    """``(inside, outside)``, ``(M, dof)`` each: valid and invalid configurations less than ``tol`` apart.

    Bisects segments from a valid configuration towards an invalid one (far: a uniform
    one; near: a step of about 5 % of the range of each degree of freedom) until they are shorter than ``tol``,
    keeping a valid start and an invalid end. Segments stay within the bounds (they are a
    box; angles go the short way round), so the boundary is an obstacle or a region wall.
    """
    robot = checker.robot
    Q = robot.sample(rng, 4 * n)
    valid = checker.are_valid(Q)
    start = Q[valid][:n]
    far = Q[~valid][rng.integers((~valid).sum(), size=len(start))]
    near = np.clip(
        start + rng.normal(0, 0.05, size=start.shape) * (robot.upper - robot.lower), robot.lower, robot.upper
    )
    end = np.where(rng.random((len(start), 1)) < 0.5, far, near)
    keep = ~checker.are_valid(end)
    start, step = start[keep], robot.difference(start[keep], end[keep])  # (M, dof) each
    lo, hi = np.zeros(len(start)), np.ones(len(start))  # fractions: valid at lo, invalid at hi
    for _ in range(int(np.ceil(np.log2(np.linalg.norm(step, axis=1).max() / tol)))):
        mid = (lo + hi) / 2
        ok = checker.are_valid(robot.wrap(start + mid[:, None] * step))
        lo, hi = np.where(ok, mid, lo), np.where(ok, hi, mid)
    inside, outside = robot.wrap(start + lo[:, None] * step), robot.wrap(start + hi[:, None] * step)
    assert np.all(robot.distance(inside, outside) < tol)
    return inside, outside


# -- the four scenarios: uniform, near contact, on the bounds ----------------------------------------------


@pytest.mark.parametrize("name", SCENARIOS)
def test_compiled_equals_fcl_on_100000_uniform_configurations(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(10)
    ws = scenario.make_workspace(rng)
    Q = robot.sample(rng, 100_000)
    compiled = CompiledChecker(ws, robot).are_valid(Q)
    np.testing.assert_array_equal(compiled, FCLChecker(ws, robot).are_valid(Q))
    np.testing.assert_array_equal(compiled[:10_000], SeparatingAxisChecker(ws, robot).are_valid(Q[:10_000]))
    assert 0.05 < compiled.mean() < 0.95


@pytest.mark.parametrize("name", SCENARIOS)
def test_compiled_equals_fcl_and_separating_axes_within_1e_6_of_contact(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(11)
    ws = scenario.make_workspace(rng)
    inside, outside = straddle_the_boundary(CompiledChecker(ws, robot), rng, 5000)
    assert len(inside) > 2500
    assert np.all(robot.motion_bound(inside, outside) < 1e-5)  # no point of the robot is farther from contact
    valid = assert_all_agree(ws, robot, np.concatenate([inside, outside]))
    assert valid[: len(inside)].all() and not valid[len(inside) :].any()
    # both kinds of boundary were met: a link's bounds at a region wall, and against a block (the point robot's
    # bounds keep it off the walls)
    aabbs = robot.link_aabbs(outside)  # (M, L, 2, D)
    at_wall = np.any((aabbs[..., 0, :] < ws.lower) | (aabbs[..., 1, :] > ws.upper), axis=(1, 2))
    assert 0.01 < at_wall.mean() < 0.99 or (name == "2ds" and not at_wall.any())


@pytest.mark.parametrize("name", SCENARIOS)
def test_configurations_on_the_bounds_are_in_and_a_step_beyond_is_out(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(12)
    ws = scenario.make_workspace(rng)
    Q = np.repeat(robot.sample(rng, 200), 2, axis=0)
    rows, dof = np.arange(len(Q)), rng.integers(robot.dof, size=len(Q))
    at = np.where(rows % 2 == 0, robot.lower[dof], robot.upper[dof])
    Q[rows, dof] = at
    beyond = Q.copy()
    beyond[rows, dof] = np.where(rows % 2 == 0, np.nextafter(at, -np.inf), np.nextafter(at, np.inf))
    assert not assert_all_agree(ws, robot, beyond).any()
    assert assert_all_agree(ws, robot, Q).any()


# -- exact contacts ------------------------------------------------------------------------------------------

# Sizes and places are multiples of 1/8 and angles zero, so contacts are exact in floating point.
DYADIC_3D = BoxRobot(
    "dyadic",
    "free",
    [Link((0.25, 0.125, 0.125), (0.25, 0.0, 0.0)), Link((0.5, 0.125, 0.25), (0.5, 0.0, 0.0))],
    [Joint((0.5, 0.0, 0.0), "z", (-2.0, 2.0))],
    position_bounds=(np.zeros(3), np.full(3, 8.0)),
)
DYADIC_2D = BoxRobot(
    "dyadic2d",
    "point2d",
    [Link((0.25, 0.25, 0.0)), Link((0.75, 0.125, 0.0), (0.75, 0.0, 0.0))],
    [Joint((0.25, 0.0, 0.0), "z", (-2.0, 2.0))],
    position_bounds=(np.zeros(2), np.full(2, 8.0)),
)


@settings(max_examples=40, deadline=None)
@given(
    dim=st.sampled_from([2, 3]),
    link=st.integers(0, 1),
    sides=st.lists(st.integers(-1, 1), min_size=3, max_size=3).filter(any),
    eighths=st.lists(st.integers(1, 16), min_size=6, max_size=6),
    gap=st.sampled_from([0.0, 2.0**-20, -(2.0**-20)]),
)
def test_faces_edges_and_corners_touching_exactly(dim, link, sides, eighths, gap):
    """A box placed against one link's face (one side nonzero), edge (two) or corner (three): touching is a
    collision for all three checkers; 2^-20 away, or into it, they agree with exact arithmetic on the bounds."""
    robot = DYADIC_3D if dim == 3 else DYADIC_2D
    sides = np.array(sides[:dim])
    if not sides.any():
        return
    q = np.zeros(robot.dof)
    q[:dim] = 3.0
    aabbs = robot.link_aabbs(q)[0]  # (L, 2, D): the link boxes themselves, as no angle turns them
    size, overlap = np.array(eighths[:dim]) / 8, np.array(eighths[dim : 2 * dim]) / 16
    lo, hi = aabbs[link]
    box = np.stack([lo - overlap, hi + overlap])  # along an axis whose side is 0, the box overlaps the link
    box[:, sides > 0] = hi[sides > 0] + gap + np.stack([0 * size, size])[:, sides > 0]
    box[:, sides < 0] = lo[sides < 0] - gap - np.stack([size, 0 * size])[:, sides < 0]
    ws = Workspace(np.zeros(dim), np.full(dim, 8.0), box[None])
    meets = np.all((aabbs[:, 0] <= box[1]) & (aabbs[:, 1] >= box[0]), axis=-1).any()  # exact, axis-aligned boxes
    assert assert_all_agree(ws, robot, q[None])[0] == (not meets)
    assert meets or gap > 0


# -- robots and workspaces of one's own ------------------------------------------------------------------


def planar_arm() -> BoxRobot:
    """A 3-link arm on a sliding 2D base (tests/test_extension_points.py's)."""
    links = [
        Link((0.4, 0.4, 0.0)),
        Link((1.0, 0.15, 0.0), (1.0, 0.0, 0.0)),
        Link((0.75, 0.15, 0.0), (0.75, 0.0, 0.0)),
        Link((0.5, 0.15, 0.0), (0.5, 0.0, 0.0)),
    ]
    joints = [
        Joint((0.0, 0.0, 0.0), "z", (-3.0, 3.0)),
        Joint((2.0, 0.0, 0.0), "z", (-2.6, 2.6)),
        Joint((1.5, 0.0, 0.0), "z", (-2.6, 2.6)),
    ]
    return BoxRobot("arm2d", "point2d", links, joints, position_bounds=(np.full(2, 0.4), np.full(2, 30.6)))


def scattered_boxes(rng, lower, upper, n) -> np.ndarray:
    """``(n, 2, D)`` boxes of any size (0.01 to 6, some thin) anywhere, poking out of the region too."""
    size = np.exp(rng.uniform(np.log(0.01), np.log(6.0), size=(n, len(lower))))
    corner = rng.uniform(lower - 1, upper, size=(n, len(lower)))
    return np.stack([corner, corner + size], axis=1)


@settings(max_examples=8, deadline=None)
@given(seed=seeds)
def test_a_2d_arm_among_boxes_of_any_size(seed):
    robot, rng = planar_arm(), np.random.default_rng(seed)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), scattered_boxes(rng, np.zeros(2), np.full(2, 31.0), 12))
    assert type(exact_checker(ws, robot)) is CompiledChecker
    inside, outside = straddle_the_boundary(CompiledChecker(ws, robot), rng, 300)
    assert_all_agree(ws, robot, np.concatenate([robot.sample(rng, 2000), inside, outside]))


@pytest.mark.parametrize("name", ["3do", "3dc9"])
@settings(max_examples=6, deadline=None)
@given(seed=seeds)
def test_a_user_workspace_with_non_integer_boxes(name, seed):
    robot, rng = scenarios.get(name).robot, np.random.default_rng(seed)
    lower, upper = np.zeros(3), np.array([41.0, 41.0, 6.0]) if name == "3do" else np.full(3, 11.0)
    ws = Workspace(lower, upper, scattered_boxes(rng, lower, upper, 40 if name == "3dc9" else 60))
    inside, outside = straddle_the_boundary(CompiledChecker(ws, robot), rng, 300)
    assert_all_agree(ws, robot, np.concatenate([robot.sample(rng, 2000), inside, outside]))


def test_an_empty_workspace_and_a_robot_of_one_link():
    cube = BoxRobot("cube", "free", [Link((0.5, 0.25, 0.125))], [], position_bounds=(np.zeros(3), np.full(3, 4.0)))
    rng = np.random.default_rng(13)
    for ws in (
        Workspace(np.zeros(3), np.full(3, 4.0), []),
        Workspace(np.zeros(3), np.full(3, 4.0), [[[1, 1, 1], [2, 2, 2]]]),
    ):
        assert_all_agree(ws, cube, cube.sample(rng, 3000))


# -- the interface: choice, errors, one compiled version, clearances -------------------------------------


def test_exact_checker_compiles_every_box_world_but_the_point_robots():
    for name, expected in (("2ds", PointRobotChecker), ("3do", CompiledChecker), ("3dc7", CompiledChecker)):
        scenario = scenarios.get(name)
        assert type(exact_checker(scenario.make_workspace(np.random.default_rng(0)), scenario.robot)) is expected
    mesh = from_mesh(__import__("trimesh").creation.box((2, 2, 2)), lower=np.zeros(3), upper=np.full(3, 11.0))
    assert type(exact_checker(mesh, robots.box_chain(1))) is CompiledMeshChecker
    with pytest.raises(ValueError, match="a mesh workspace's obstacles are its triangles"):
        CompiledChecker(mesh, robots.box_chain(1))


def test_bad_input_gets_the_same_errors_as_the_reference():
    scenario = scenarios.get("3dc9")
    ws = scenario.make_workspace(np.random.default_rng(0))
    for make in (CompiledChecker, FCLChecker):
        checker = make(ws, scenario.robot)
        with pytest.raises(ValueError, match=r"must have shape \(N, 9\)"):
            checker.are_valid(np.zeros((4, 7)))
        with pytest.raises(ValueError, match="NaN or infinite"):
            checker.are_valid(np.full((2, 9), np.inf))
        with pytest.raises(ValueError, match="NaN or infinite"):
            checker.clearances(np.full((2, 9), np.nan), 0.5)
        assert checker.are_valid(np.zeros((0, 9))).shape == (0,) and checker.n_checked == 0
    plane = scenarios.get("2ds").make_workspace(np.random.default_rng(0))
    with pytest.raises(ValueError, match="robot 'chain9' is 3D but the workspace is 2D"):
        CompiledChecker(plane, robots.box_chain(3))


def test_one_compiled_version_serves_every_robot_and_workspace():
    """Robots and workspaces are arguments, never constants: checking others compiles nothing new."""
    from toolkit.geometry import block_kernels, kernels

    rng = np.random.default_rng(14)
    for name in SCENARIOS:
        scenario = scenarios.get(name)
        checker = CompiledChecker(scenario.make_workspace(rng), scenario.robot)
        checker.are_valid(np.asfortranarray(scenario.robot.sample(rng, 10)))  # any memory layout
        checker.are_valid(scenario.robot.sample(rng, 10).astype(np.float32))  # any float type
        checker.clearances(scenario.robot.sample(rng, 10), 0.3)
    CompiledChecker(Workspace(np.zeros(2), np.full(2, 31.0), []), planar_arm()).are_valid(np.zeros((3, 5)))
    assert len(block_kernels.validity_at.signatures) == 1
    assert len(kernels.clearance_bounds.signatures) == 1


def test_the_kernels_sines_and_cosines_are_the_c_librarys_within_two_ulps():
    """The vectorizable sine and cosine (Cephes') against numpy's: exact at 0, within 2 units in the last place
    of numpy's value over the angles a robot takes, and the C library's own beyond ``SIN_COS_LIMIT``."""
    from numba import njit

    from toolkit.geometry import trig

    @njit
    def both(x):
        out = np.empty((2, len(x)))
        for i in range(len(x)):
            out[0, i], out[1, i] = trig.any_sin_cos(x[i])
        return out

    rng = np.random.default_rng(15)
    x = np.concatenate([[0.0, -0.0, np.pi / 2, np.pi, -np.pi], rng.uniform(-10, 10, 100_000), [3e8, -1e12]])
    sines, cosines = both(x)
    assert (sines[0], cosines[0]) == (0.0, 1.0)
    ulp = np.spacing(1.0) * np.maximum(np.abs(np.sin(x)), np.abs(np.cos(x)))  # the larger of the two: their scale
    assert np.all(np.abs(sines - np.sin(x)) <= 2 * ulp)
    assert np.all(np.abs(cosines - np.cos(x)) <= 2 * ulp)


def test_importing_the_checkers_compiles_nothing():
    code = "import sys, toolkit.geometry.collision, toolkit.geometry.compiled; print('numba' in sys.modules)"
    assert (
        subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.strip()
        == "False"
    )


@pytest.mark.parametrize("name", SCENARIOS)
def test_compiled_clearances_equal_the_numpy_bound(name):
    scenario = scenarios.get(name)
    robot, rng = scenario.robot, np.random.default_rng(15)
    ws = scenario.make_workspace(rng)
    checker = CompiledChecker(ws, robot)
    inside, outside = straddle_the_boundary(checker, rng, 300)
    Q = np.concatenate([robot.sample(rng, 1500), inside, outside])
    for cap in (0.05, 0.5, 2.0):
        compiled = checker.clearances(Q, cap)
        np.testing.assert_allclose(compiled, BoxWorldChecker.clearance_bounds(checker, Q, cap), rtol=0, atol=1e-12)
        valid = checker.are_valid(Q)
        assert np.all(valid[compiled > 0]) and np.all(compiled[~valid] == 0) and (compiled > 0).mean() > 0.2


@pytest.mark.parametrize("name", SCENARIOS)
@pytest.mark.parametrize("grow", [0.0, 0.4])
def test_each_cell_lists_exactly_the_boxes_that_touch_it_grown(name, grow):
    """The broadphase's cell lists (built without a loop over boxes, issue 36) against every (cell, box) pair."""
    scenario = scenarios.get(name)
    ws = scenario.workspaces("query", 1, 3)[0]
    grid = BoxGrid(ws, scenario.robot)
    count, first, members = grid.box_lists(grow)
    shape = grid.shape
    lo, hi = grid.cells(ws.boxes[:, 0] - grow), grid.cells(ws.boxes[:, 1] + grow)  # (K, D)
    index = np.stack(np.unravel_index(np.arange(int(np.prod(shape))), shape), axis=-1)  # (C, D) every cell
    touches = np.all((index[:, None] >= lo) & (index[:, None] <= hi), axis=-1)  # (C, K)
    for c in range(len(index)):
        assert members[first[c] : first[c] + count[c]].tolist() == np.flatnonzero(touches[c]).tolist()


def room_per_cell(boxes, lower, upper, cell, shape, dim) -> np.ndarray:
    """``(C,)`` the far bits' rule in numpy, cell by cell: each cell's distance to the nearest of ``boxes (K, 2, 3)``
    and to the walls of the region's first ``dim`` axes (a cell's gap to a box: per axis, summed squared, rooted)."""
    start = [lower[i] + np.arange(shape[i]) * cell for i in range(3)]  # each layer's first coordinate, per axis
    room = np.full(tuple(shape), np.inf)
    for box in boxes:
        gaps = [np.maximum(np.maximum(box[0, i] - (start[i] + cell), start[i] - box[1, i]), 0.0) ** 2 for i in range(3)]
        room = np.minimum(room, np.sqrt(gaps[0][:, None, None] + gaps[1][None, :, None] + gaps[2][None, None, :]))
    for axis in range(dim):
        index = np.arange(shape[axis])
        layer = np.minimum(index * cell, upper[axis] - lower[axis] - (index + 1) * cell)
        room = np.minimum(room, np.expand_dims(layer, [a for a in range(3) if a != axis]))
    return room.reshape(-1)


def assert_bits_are(bits, expected):
    """``bits (B, W)`` packed little-endian, as ``expected (B, C)``; the bits past the last cell 0."""
    unpacked = np.unpackbits(bits.view(np.uint8), axis=1, bitorder="little")  # (B, 64 W)
    np.testing.assert_array_equal(unpacked[:, : expected.shape[1]].astype(bool), expected)
    assert not unpacked[:, expected.shape[1] :].any()


@pytest.mark.parametrize("name", SCENARIOS)
def test_the_far_bits_are_the_cells_farther_than_each_ball_from_boxes_and_walls(name):
    """The far bits, cleared near each wall and box, against the rule written in numpy, cell by cell: a cell's bit for
    a ball is 1 where its distance to every box and to the region's walls exceeds the ball's radius."""
    from toolkit.geometry import compiled

    scenario = scenarios.get(name)
    ws, robot = scenario.workspaces("query", 1, 5)[0], scenario.robot
    far = compiled.far_grid(ws, robot)
    lower, upper, boxes = np.zeros(3), np.zeros(3), np.zeros((len(ws.boxes), 2, 3))
    lower[: ws.dim], upper[: ws.dim], boxes[..., : ws.dim] = ws.lower, ws.upper, ws.boxes
    radii = np.unique(np.linalg.norm(robot.half_extents, axis=1))  # (B,)
    margin = 1e-9 * float(np.max(upper - lower))
    room = room_per_cell(boxes, lower, upper, far.cell, far.shape, ws.dim)  # (C,)
    expected = room[None] > radii[:, None] + margin  # (B, C)
    assert 0 < expected.sum() < expected.size
    assert_bits_are(far.bits, expected)


@pytest.mark.parametrize("seed", range(4))
def test_the_far_bits_hold_to_the_rule_within_a_rounding_error_of_the_radius(seed):
    """Balls whose radius (plus the margin) lies within a rounding error of some cell's distance to a box or a wall,
    in 2D and 3D grids with boxes partly outside the region: the bits compare squared distances with the largest
    square whose root is at most the radius, and must decide every cell as the rule's square roots do."""
    from toolkit.geometry import compiled

    rng = np.random.default_rng(seed)
    dim = 2 + seed % 2
    lower, upper = np.zeros(3), np.zeros(3)
    upper[:dim] = rng.uniform(2.0, 4.0, dim)
    cell = float(rng.uniform(0.1, 0.2))
    shape = np.ones(3, dtype=np.int64)
    shape[:dim] = np.ceil(upper[:dim] / cell).astype(np.int64) + 1
    boxes = np.sort(rng.uniform(-0.5, upper + 0.5, (12, 2, 3)), axis=1)  # (K, 2, 3)
    boxes[..., dim:] = 0.0
    room = room_per_cell(boxes, lower, upper, cell, shape, dim)  # (C,)
    margin = 1e-9 * float(np.max(upper - lower))
    near = rng.choice(np.unique(room[(room > 0) & (room < 1)]), 8) - margin  # radii that some cell's room matches
    radii = np.unique(np.concatenate([near, np.nextafter(near, 0.0), np.nextafter(near, 1.0)]))  # (B,)
    expected = room[None] > radii[:, None] + margin  # (B, C)
    assert np.any(room[None] == radii[:, None] + margin)  # ties, decided as not far
    assert_bits_are(compiled.far_bits(boxes, lower, upper, cell, shape, radii, dim), expected)


def test_a_planners_small_calls_answer_as_the_batch_and_refuse_nan_and_infinities():
    """What a planner passes (float64, C order) goes straight to the compiled loop once it is compiled: calls of 1 to
    70 configurations (a block and a part) answer as one batch does, and a NaN or an infinity in any row, even within
    bounds that are themselves infinite, gets the reference's error and counts nothing."""
    scenario = scenarios.get("3dc9")
    robot, rng = scenario.robot, np.random.default_rng(16)
    checker = CompiledChecker(scenario.make_workspace(rng), robot)
    Q = robot.sample(rng, 2000)
    batch = checker.are_valid(Q)
    assert 0.1 < batch.mean() < 0.9
    pieces, start = [], 0
    for size in rng.integers(1, 71, size=200):
        pieces.append(checker.are_valid(Q[start : start + size]))
        start += size
    np.testing.assert_array_equal(np.concatenate(pieces), batch[:start])
    # the loop, not Python, tests the order (by the strides): any other order gets the batch's answers too
    wide = np.concatenate([Q, Q], axis=1)  # (2000, 2 dof)
    for size in (1, 2, 16, 130):
        strided = Q[: 2 * size : 2]
        np.testing.assert_array_equal(checker.are_valid(strided), batch[: 2 * size : 2])
        for other in (np.asfortranarray(Q[:size]), wide[:size, : robot.dof], wide[:size, 1::2]):
            np.testing.assert_array_equal(checker.are_valid(other), checker.are_valid(np.ascontiguousarray(other)))
    unbounded = BoxRobot(
        "unbounded", "free", [Link((0.5, 0.25, 0.125))], [], position_bounds=(np.full(3, -np.inf), np.full(3, np.inf))
    )
    cube = CompiledChecker(Workspace(np.zeros(3), np.full(3, 4.0), [[[1, 1, 1], [2, 2, 2]]]), unbounded)
    for compiled, dof in ((checker, robot.dof), (cube, unbounded.dof)):
        compiled.are_valid(np.full((5, dof), 0.5))  # compiled: later calls take the short way
        counted = compiled.n_checked
        for bad in (np.nan, np.inf, -np.inf):
            Q = np.full((70, dof), 0.5)
            Q[rng.integers(70), rng.integers(dof)] = bad
            with pytest.raises(ValueError, match="Q contains NaN or infinite values"):
                compiled.are_valid(Q)
        assert compiled.n_checked == counted
