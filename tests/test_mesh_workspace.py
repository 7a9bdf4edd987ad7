"""Workspaces from triangle meshes (issue 19): the mesh checker, the voxel grid, files, the demo room.

The references: the box checker on the same boxes (a mesh of boxes is the same
obstacle), cells whose place relative to the boxes is known from the boxes alone,
and trimesh's own voxelizer where it is well-defined (faces off the cell boundaries).
"""

from pathlib import Path

import fcl
import numpy as np
import pytest
import trimesh

from toolkit import scenarios
from toolkit.geometry import meshes, robots
from toolkit.geometry.collision import CompiledMeshChecker, FCLChecker, MeshChecker, exact_checker
from toolkit.geometry.robots import BoxRobot, Link
from toolkit.geometry.workspace import MeshWorkspace, Workspace, from_mesh, generate
from toolkit.learning import data

ROOM = Path(__file__).resolve().parents[1] / "tutorials" / "data" / "room.stl"
REGION = dict(lower=np.zeros(3), upper=np.full(3, 11.0))


def mesh_twin(ws: Workspace) -> MeshWorkspace:
    """The same boxes as one triangle mesh."""
    return from_mesh(meshes.mesh_of_boxes(ws.boxes), lower=ws.lower, upper=ws.upper)


def off_grid_boxes(rng, count=6):
    """Boxes whose faces lie a quarter cell off the cell boundaries, sides of 1 to 3.5 cells, inside 11^3."""
    lo = rng.integers(0, 8, size=(count, 3)) + rng.choice([0.25, 0.75], size=(count, 3))
    size = rng.integers(1, 4, size=(count, 3)) + rng.choice([0.0, 0.5], size=(count, 3))
    return np.stack([lo, np.minimum(lo + size, 10.75)], axis=1)


def trimesh_voxels(mesh, shape):
    """trimesh's voxelizer (surface, then filled) with its voxel centres on our cell centres, as a -1 / +1 grid."""
    shifted = mesh.copy()
    shifted.apply_translation(-0.5 * np.ones(3))  # trimesh's voxel centres lie on integers
    index = np.round(shifted.voxelized(pitch=1.0).fill().points).astype(int)
    grid = np.full(shape, -1.0)
    keep = np.all((index >= 0) & (index < np.array(shape)), axis=1)
    grid[tuple(index[keep].T)] = 1.0
    return grid


def cube_robot(side=0.9):
    """A free-flying cube, small enough to sit inside one cell."""
    half = side / 2
    return BoxRobot(
        "cube", "free", [Link((half, half, half))], [], position_bounds=(np.full(3, half), np.full(3, 11 - half))
    )


# -- the mesh checker against the box checker --------------------------------------------


@pytest.mark.parametrize("name", ["3dc7", "3dc9", "3do"])
@pytest.mark.parametrize("seed", [0, 1])
def test_mesh_checker_agrees_with_the_box_checker_on_the_same_boxes(name, seed):
    scenario = scenarios.get(name)
    ws = scenario.make_workspace(np.random.default_rng(seed))
    twin = mesh_twin(ws)
    Q = scenario.robot.sample(np.random.default_rng(seed + 10), 2000)
    boxes, mesh = FCLChecker(ws, scenario.robot).are_valid(Q), exact_checker(twin, scenario.robot).are_valid(Q)
    assert 0.2 < boxes.mean() < 0.9  # both answers occur
    np.testing.assert_array_equal(mesh, boxes)


def test_mesh_checker_agrees_on_configurations_grazing_the_boxes():
    """Chain bases a hair inside and outside a block's faces: the closed-box rule (touching collides) holds for both."""
    scenario = scenarios.get("3dc7")
    ws = scenario.make_workspace(np.random.default_rng(2))
    rng = np.random.default_rng(3)
    Q = scenario.robot.sample(rng, 600)
    lo, hi = ws.boxes[rng.integers(len(ws.boxes), size=600)].transpose(1, 0, 2)  # (600, 3) each
    axis = rng.integers(3, size=600)
    face = np.where(  # 0.05: the small link's half side
        rng.random(600) < 0.5, lo[np.arange(600), axis] - 0.05, hi[np.arange(600), axis] + 0.05
    )
    Q[:, :3] = (lo + hi) / 2
    Q[np.arange(600), axis] = face + rng.choice([-1e-6, 1e-6], size=600)
    boxes, mesh = (
        FCLChecker(ws, scenario.robot).are_valid(Q),
        exact_checker(mesh_twin(ws), scenario.robot).are_valid(Q),
    )
    np.testing.assert_array_equal(mesh, boxes)


def test_a_link_wholly_inside_a_solid_collides_though_it_touches_no_triangle():
    ws = mesh_twin(Workspace(np.zeros(3), np.full(3, 11.0), np.array([[[2.0, 2.0, 2.0], [8.0, 8.0, 8.0]]])))
    robot = cube_robot()
    q = np.array([5.0, 5.0, 5.0, 0.0, 0.0, 0.0])
    assert not ws.solid.touches(q[:3], np.full(3, 0.9))  # fcl alone sees no contact
    assert not exact_checker(ws, robot).is_valid(q)
    assert exact_checker(ws, robot).is_valid(np.array([9.0, 9.0, 9.0, 0.0, 0.0, 0.0]))


def test_exact_checker_picks_the_mesh_checker_and_the_box_checkers_refuse_a_mesh():
    twin = mesh_twin(generate("3dc", np.random.default_rng(0)))
    assert type(exact_checker(twin, robots.box_chain(1))) is CompiledMeshChecker
    with pytest.raises(ValueError, match="exact_checker"):
        FCLChecker(twin, robots.box_chain(1))
    with pytest.raises(ValueError, match="MeshWorkspace"):
        MeshChecker(generate("3dc", np.random.default_rng(0)), robots.box_chain(1))


# -- the voxel grid ---------------------------------------------------------------------


@pytest.mark.parametrize("family", ["3dc", "3do"])
def test_grid_of_a_mesh_of_blocks_is_the_block_workspaces_grid(family):
    for seed in range(3):
        ws = generate(family, np.random.default_rng(seed))
        np.testing.assert_array_equal(mesh_twin(ws).occupancy(), ws.occupancy())


@pytest.mark.parametrize("seed", range(4))
def test_grid_and_checker_agree_where_a_cell_is_wholly_inside_or_outside(seed):
    """Known from the boxes alone: a cell inside one box is occupied, a cell no box touches is free; a cube robot
    sitting in the cell collides in the first and is valid in the second."""
    boxes = off_grid_boxes(np.random.default_rng(seed), count=10)
    ws = from_mesh(meshes.mesh_of_boxes(boxes), **REGION)
    grid = ws.occupancy().reshape(-1)
    cells = np.stack(np.meshgrid(*[np.arange(11.0)] * 3, indexing="ij"), axis=-1).reshape(-1, 3)  # (C, 3) min corners
    wholly_inside = np.any(
        np.all((cells[:, None] >= boxes[:, 0]) & (cells[:, None] + 1 <= boxes[:, 1]), axis=-1), axis=1
    )
    wholly_outside = ~np.any(
        np.all((cells[:, None] <= boxes[:, 1]) & (cells[:, None] + 1 >= boxes[:, 0]), axis=-1), axis=1
    )
    assert wholly_inside.sum() > 5 and wholly_outside.sum() > 500
    assert np.all(grid[wholly_inside] == 1.0) and np.all(grid[wholly_outside] == -1.0)
    Q = np.concatenate([cells + 0.5, np.zeros((len(cells), 3))], axis=1)  # the cube at each cell's centre
    valid = exact_checker(ws, cube_robot()).are_valid(Q)
    assert not valid[wholly_inside].any() and valid[wholly_outside].all()


def test_grid_marks_a_board_thinner_than_a_cell_and_only_the_cells_it_crosses():
    board = np.array([[[1.25, 2.25, 4.6], [6.75, 5.75, 4.75]]])  # 0.15 thick, between the cell centres 4.5 and 5.5
    grid = from_mesh(meshes.mesh_of_boxes(board), **REGION).occupancy()
    expected = np.full((11, 11, 11), -1.0)
    expected[1:7, 2:6, 4] = 1.0
    np.testing.assert_array_equal(grid, expected)
    assert np.all(Workspace(np.zeros(3), np.full(3, 11.0), board).occupancy() == -1)  # the centre rule misses it


@pytest.mark.parametrize("seed", range(4))
def test_grid_is_trimeshs_voxelization_off_the_cell_boundaries(seed):
    mesh = meshes.mesh_of_boxes(off_grid_boxes(np.random.default_rng(seed)))
    np.testing.assert_array_equal(from_mesh(mesh, **REGION).occupancy(), trimesh_voxels(mesh, (11, 11, 11)))


def test_trimeshs_voxelizer_grows_blocks_whose_faces_lie_on_cell_boundaries():
    """Why the grid is not trimesh's: on the grid's boundaries it rounds half to even, so blocks grow."""
    ws = generate("3dc", np.random.default_rng(0))
    ours, theirs = mesh_twin(ws).occupancy(), trimesh_voxels(meshes.mesh_of_boxes(ws.boxes), ws.grid_shape)
    assert np.all(theirs[ours > 0] > 0) and (theirs > 0).sum() > 2 * (ours > 0).sum()


# -- inside tests -----------------------------------------------------------------------


def test_winding_numbers_of_a_closed_box_and_of_overlapping_boxes():
    box = meshes.mesh_of_boxes(np.array([[[0.0, 0.0, 0.0], [2.0, 2.0, 2.0]]]))
    points = np.array([[1.0, 1.0, 1.0], [3.0, 1.0, 1.0], [1.0, 1.0, -0.5]])
    np.testing.assert_allclose(meshes.winding_numbers(points, box.triangles), [1.0, 0.0, 0.0], atol=1e-9)
    both = meshes.Solid(
        *(lambda m: (m.vertices, m.faces))(
            meshes.mesh_of_boxes(np.array([[[0.0, 0.0, 0.0], [2.0, 2.0, 2.0]], [[1.0, 1.0, 1.0], [3.0, 3.0, 3.0]]]))
        )
    )
    assert len(both.parts) == 2
    np.testing.assert_array_equal(
        both.inside(np.array([[1.5, 1.5, 1.5], [0.5, 0.5, 0.5], [2.5, 2.5, 2.5], [0.5, 2.5, 0.5]])),
        [True, True, True, False],
    )


def test_contains_points_follows_the_mesh_not_its_covering_boxes():
    ws = from_mesh(trimesh.creation.icosphere(subdivisions=3, radius=3.0).apply_translation((5.5, 5.5, 5.5)), **REGION)
    assert len(ws.boxes) == 1
    corner_of_bounds = np.array([2.7, 2.7, 2.7])  # inside the sphere's bounding box, outside the sphere
    assert ws.contains_points(np.array([[5.5, 5.5, 5.5], corner_of_bounds])).tolist() == [True, False]


# -- workspaces, files, bad input ------------------------------------------------------


def test_from_mesh_reads_a_file_and_round_trips_through_files(tmp_path):
    ws = from_mesh(meshes.room(), **REGION)
    path = tmp_path / "room.stl"
    meshes.room().export(path)
    from_file = from_mesh(path, **REGION)
    np.testing.assert_array_equal(from_file.occupancy(), ws.occupancy())
    ws.save(tmp_path / "ws.json")
    again = Workspace.load(tmp_path / "ws.json")
    assert (
        isinstance(again, MeshWorkspace)
        and again == ws
        and again != Workspace(ws.lower, ws.upper, ws.boxes, family=ws.family)
    )
    np.testing.assert_array_equal(again.occupancy(), ws.occupancy())


def test_labelled_datasets_of_mesh_workspaces_keep_their_meshes(tmp_path):
    scenario = scenarios.get("3dc7")
    rooms = [from_mesh(meshes.room(np.random.default_rng(i)), **REGION) for i in range(2)]
    dataset = data.label_workspaces(
        scenario, rooms, samples_per_workspace=40, seed=0, stream="train_samples", progress=False
    )
    for ws, Q, valid in zip(rooms, dataset.configs, dataset.valid):
        np.testing.assert_array_equal(exact_checker(ws, scenario.robot).are_valid(Q), valid)
    dataset.save(tmp_path / "rooms.npz")
    loaded = data.CollisionDataset.load(tmp_path / "rooms.npz", "3dc7")
    assert all(isinstance(ws, MeshWorkspace) for ws in loaded.workspaces) and loaded.workspaces == rooms
    np.testing.assert_array_equal(loaded.occupancy, dataset.occupancy)


def test_bad_input_is_named(tmp_path):
    mesh = meshes.room()
    with pytest.raises(ValueError, match="3D"):
        from_mesh(mesh, lower=np.zeros(2), upper=np.full(2, 11.0))
    with pytest.raises(ValueError, match="whole numbers"):
        from_mesh(mesh, lower=np.zeros(3), upper=np.full(3, 10.5))
    with pytest.raises(TypeError, match="trimesh"):
        from_mesh(42, **REGION)
    with pytest.raises(ValueError, match="faces"):
        MeshWorkspace(np.zeros(3), np.ones(3), np.zeros((0, 2, 3)), vertices=np.zeros((3, 3)), faces=[[0, 1, 5]])


# -- the demo room ---------------------------------------------------------------------


def test_the_demo_room_stands_inside_the_region_and_the_committed_file_is_the_script_output():
    room = meshes.room()
    assert np.all(room.bounds[0] >= 0) and np.all(room.bounds[1] <= meshes.ROOM_REGION)
    assert room.bounds[0][2] == 0.0  # on the floor
    committed = trimesh.load(ROOM, force="mesh")
    ours = np.sort(np.round(room.triangles.reshape(-1, 9), 4), axis=0)
    theirs = np.sort(np.round(committed.triangles.reshape(-1, 9), 4), axis=0)
    # rebuild with: python -m toolkit.geometry.meshes tutorials/data/room.stl
    np.testing.assert_array_equal(theirs, ours)


def test_random_rooms_are_seeded_and_inside_the_region():
    first, again = meshes.room(np.random.default_rng(5)), meshes.room(np.random.default_rng(5))
    np.testing.assert_array_equal(first.vertices, again.vertices)
    assert not np.array_equal(first.vertices, meshes.room(np.random.default_rng(6)).vertices)
    for seed in range(20):
        bounds = meshes.room(np.random.default_rng(seed)).bounds
        assert np.all(bounds[0] >= -1e-9) and np.all(bounds[1] <= np.array(meshes.ROOM_REGION) + 1e-9)


def test_furniture_turns_keep_its_size():
    for turns in range(4):
        size = np.ptp(meshes.furniture_boxes("shelf", (0.0, 0.0), turns).reshape(-1, 3), axis=0)
        expected = np.ptp(np.array(meshes.FURNITURE["shelf"]).reshape(-1, 3), axis=0)
        np.testing.assert_allclose(size, expected[[1, 0, 2]] if turns % 2 else expected)


def test_clearances_in_the_room_bound_fcls_distances_to_the_mesh_from_below():
    """Planning certifies edges with these bounds: they must never exceed the true distance to the triangles."""
    scenario = scenarios.get("3dc7")
    ws = from_mesh(meshes.room(), **REGION)
    Q = scenario.robot.sample(np.random.default_rng(0), 300)
    checker = exact_checker(ws, scenario.robot)
    valid, clearance = checker.are_valid(Q), checker.clearances(Q, cap=2.0)
    assert np.all(clearance[~valid] == 0) and np.mean(clearance[valid] > 0) > 0.5
    centers, rotations, half = scenario.robot.link_boxes(Q)
    for i in np.flatnonzero(valid)[:60]:
        distance = min(
            fcl.distance(
                fcl.CollisionObject(fcl.Box(*(2 * half[l])), fcl.Transform(rotations[i, l], centers[i, l])),
                ws.solid.object,
                fcl.DistanceRequest(),
                fcl.DistanceResult(),
            )
            for l in range(scenario.robot.n_links)
        )
        assert distance > 0 and clearance[i] <= distance + 1e-9
