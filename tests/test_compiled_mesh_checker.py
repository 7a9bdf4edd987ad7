"""The compiled mesh checker (issue 36) gives the reference's answers: python-fcl's BVH and numpy winding numbers.

Per robot, in the tutorials' room subdivided (4,608 triangles: the boxes' faces cut into many
triangles, as a scanned or CAD mesh would be): uniform configurations, then pairs within 1e-6 of
each other on either side of the boundary of the free space, found by bisection with either
checker; in an icosphere (one large closed part, where links lie wholly inside it); and an open
surface (no inside: every cell asks the winding number).
"""

import numpy as np
import pytest
import trimesh
from test_compiled_checker import straddle_the_boundary

from toolkit import scenarios
from toolkit.experiments import crossover
from toolkit.geometry import meshes
from toolkit.geometry.collision import CompiledMeshChecker, MeshChecker, exact_checker
from toolkit.geometry.mesh_kernels import INSIDE, OUTSIDE
from toolkit.geometry.workspace import from_mesh

REGION = dict(lower=np.zeros(3), upper=np.full(3, 11.0))


@pytest.fixture(scope="module")
def room():
    """The demo room, its 288 triangles subdivided twice."""
    return from_mesh(meshes.room().subdivide().subdivide(), **REGION)


def assert_agree(ws, robot, Q) -> np.ndarray:
    compiled, reference = CompiledMeshChecker(ws, robot).are_valid(Q), MeshChecker(ws, robot).are_valid(Q)
    np.testing.assert_array_equal(compiled, reference)
    return compiled


@pytest.mark.parametrize("name", ["3dc7", "3dc9", "3do"])
def test_compiled_mesh_checker_equals_the_reference_near_contact(room, name):
    robot = scenarios.get(name).robot
    assert len(room.faces) == 4_608
    # the youBot's base ranges over 41 x 41 cells, the room 11 x 11: its base link is posed and bounded first
    assert CompiledMeshChecker(room, robot)._base_first == (name == "3do")
    valid = assert_agree(room, robot, robot.sample(np.random.default_rng(0), 3000))
    assert 0.02 < valid.mean() < 0.95  # both answers occur
    for seed, checker in enumerate((MeshChecker(room, robot), CompiledMeshChecker(room, robot))):
        n = max(150, int(100 / valid.mean()))  # 3DO: few valid configurations to start from
        inside, outside = straddle_the_boundary(checker, np.random.default_rng(seed + 1), n)
        assert len(inside) > 50
        assert assert_agree(room, robot, inside).all()
        assert not assert_agree(room, robot, outside).any()


def test_a_far_bit_says_the_ball_round_a_link_lies_in_the_region_and_misses_every_part(room):
    robot = scenarios.get("3dc9").robot
    checker = CompiledMeshChecker(room, robot)
    grid, mesh = checker._grid, checker._mesh
    points = np.random.default_rng(7).uniform(grid.lower, grid.upper, (20_000, 3))  # (N, 3) link centres
    cells = np.clip(np.floor((points - grid.lower) / grid.cell).astype(np.int64), 0, grid.shape - 1)  # (N, 3)
    flat = np.ravel_multi_index(tuple(cells.T), tuple(grid.shape))  # (N,)
    lo, hi = room.solid.bounds[:, 0], room.solid.bounds[:, 1]  # (K, 3) the parts' bounds
    gaps = np.maximum(np.maximum(lo - points[:, None], points[:, None] - hi), 0.0)  # (N, K, 3)
    walls = np.minimum(points - grid.lower, grid.upper - points).min(axis=1)  # (N,)
    clearance = np.minimum(np.linalg.norm(gaps, axis=-1).min(axis=1), walls)  # (N,)
    assert len(np.unique(mesh.link_ball)) == 2  # 3DC-9's links: two sizes
    for link, half in enumerate(robot.half_extents):
        radius = np.linalg.norm(half)
        word = mesh.far[mesh.link_ball[link]][flat >> 6]
        far = ((word >> (flat & 63).astype(np.uint64)) & np.uint64(1)).astype(bool)  # (N,)
        assert (clearance[far] > radius).all()  # safe: the ball misses every part and every wall
        assert far[clearance > radius + np.sqrt(3) * grid.cell].all()  # and loses at most a cell's diagonal
        assert 0.5 < far.mean() < 0.99


def test_links_wholly_inside_a_sphere_collide_and_cells_are_classified_once():
    scenario = scenarios.get("3dc9")
    ws = crossover.sphere(scenario.workspaces("query", 1, 0)[0], 3)  # 1,280 triangles, radius 3.3
    checker = CompiledMeshChecker(ws, scenario.robot)
    centres = ws.lower + checker._grid.cell * (
        np.stack(np.unravel_index(np.arange(len(checker._mesh.cell_state)), tuple(checker._grid.shape)), axis=-1) + 0.5
    )
    known = np.flatnonzero(checker._mesh.cell_state != 2)
    assert {INSIDE, OUTSIDE} <= set(checker._mesh.cell_state[known].tolist())
    # a classified cell's centre: the winding number's answer, on every cell beside the unclassified band round the
    # surface (where a fill would first go wrong) and 20,000 others (all 1.3 million took 66 s of the suite's time)
    unknown = (checker._mesh.cell_state == 2).reshape(tuple(checker._grid.shape))  # (nx, ny, nz)
    beside = np.zeros_like(unknown)
    for axis in range(3):
        ahead, behind = [slice(None)] * 3, [slice(None)] * 3
        ahead[axis], behind[axis] = slice(1, None), slice(None, -1)
        beside[tuple(ahead)] |= unknown[tuple(behind)]
        beside[tuple(behind)] |= unknown[tuple(ahead)]
    border = np.flatnonzero((beside & ~unknown).ravel())
    others = np.random.default_rng(3).choice(known, 20_000, replace=False)
    cells = np.union1d(border, others)
    assert len(border) > 1_000  # the band is round the whole sphere
    np.testing.assert_array_equal(checker._mesh.cell_state[cells] == INSIDE, ws.solid.inside(centres[cells]))
    Q = scenario.robot.sample(np.random.default_rng(4), 3000)
    assert_agree(ws, scenario.robot, Q)
    inside, outside = straddle_the_boundary(checker, np.random.default_rng(5), 100)
    assert assert_agree(ws, scenario.robot, inside).all() and not assert_agree(ws, scenario.robot, outside).any()


def test_an_open_surface_has_no_inside():
    box = trimesh.creation.box(bounds=[[3.0, 3.0, 3.0], [8.0, 8.0, 8.0]])
    open_box = trimesh.Trimesh(box.vertices, box.faces[2:], process=False)  # one face missing
    ws = from_mesh(open_box, **REGION)
    robot = scenarios.get("3dc7").robot
    assert (CompiledMeshChecker(ws, robot)._mesh.cell_state == 2).all()  # nothing classified
    assert_agree(ws, robot, robot.sample(np.random.default_rng(6), 3000))


def test_exact_checker_compiles_a_mesh_and_refuses_a_box_world():
    robot = scenarios.get("3dc7").robot
    assert type(exact_checker(from_mesh(meshes.room(), **REGION), robot)) is CompiledMeshChecker
    with pytest.raises(ValueError, match="MeshWorkspace"):
        CompiledMeshChecker(scenarios.get("3dc7").workspaces("query", 1, 0)[0], robot)
