"""Workspaces (issue 2, paper §IV-A): the three families, occupancy grids, files, bad input."""

import json

import numpy as np
import pytest

from toolkit.geometry.workspace import OFFICE_TYPES, Workspace, generate

SEEDS = range(40)


def family_samples(family):
    return [generate(family, np.random.default_rng(seed)) for seed in SEEDS]


def slow_occupancy(ws):
    """Reference grid: a Python loop over every cell centre and every box (closed boxes)."""
    grid = np.full(ws.grid_shape, -1.0)
    for index in np.ndindex(*ws.grid_shape):
        centre = ws.lower + np.array(index) + 0.5
        for lo, hi in ws.boxes:
            if all(lo[d] <= centre[d] <= hi[d] for d in range(ws.dim)):
                grid[index] = 1.0
    return grid


# -- the three families -----------------------------------------------------------


def test_2ds_has_3_to_5_integer_blocks_inside_31x31():
    spaces = family_samples("2ds")
    assert {len(ws.boxes) for ws in spaces} == {3, 4, 5}
    for ws in spaces:
        assert ws.family == "2ds" and ws.dim == 2 and ws.grid_shape == (31, 31)
        np.testing.assert_array_equal(ws.lower, [0, 0])
        np.testing.assert_array_equal(ws.upper, [31, 31])
        assert np.all(ws.boxes >= 0) and np.all(ws.boxes <= 31)
        np.testing.assert_array_equal(ws.boxes, np.round(ws.boxes))
        sides = ws.boxes[:, 1] - ws.boxes[:, 0]
        assert np.all((sides >= 2) & (sides <= 9))
    all_sides = np.concatenate([ws.boxes[:, 1] - ws.boxes[:, 0] for ws in spaces])
    assert len(np.unique(all_sides, axis=0)) > 20  # "different shapes and sizes"


def test_3do_has_25_to_30_office_blocks_on_the_floor():
    spaces = family_samples("3do")
    counts = {len(ws.boxes) for ws in spaces}
    assert counts <= set(range(25, 31)) and len(counts) >= 4
    seen_labels = set()
    for ws in spaces:
        assert ws.family == "3do" and ws.grid_shape == (41, 41, 6)
        np.testing.assert_array_equal(ws.upper, [41, 41, 6])
        assert np.all(ws.boxes >= 0) and np.all(ws.boxes[:, 1] <= ws.upper)
        np.testing.assert_array_equal(ws.boxes[:, 0, 2], 0.0)  # standing on the floor
        assert len(ws.labels) == len(ws.boxes)
        for label, (lo, hi) in zip(ws.labels, ws.boxes):
            x, y, z = OFFICE_TYPES[label]
            assert tuple(hi - lo) in {(x, y, z), (y, x, z)}  # the type's size, possibly turned by 90 degrees
        seen_labels |= set(ws.labels)
    assert seen_labels == set(OFFICE_TYPES)


def test_3dc_has_110_to_125_distinct_unit_blocks():
    spaces = family_samples("3dc")
    counts = [len(ws.boxes) for ws in spaces]
    assert min(counts) >= 110 and max(counts) <= 125 and len(set(counts)) >= 8
    for ws in spaces:
        assert ws.family == "3dc" and ws.grid_shape == (11, 11, 11)
        np.testing.assert_array_equal(ws.boxes[:, 1] - ws.boxes[:, 0], 1.0)
        assert np.all(ws.boxes >= 0) and np.all(ws.boxes <= 11)
        assert len(np.unique(ws.boxes[:, 0], axis=0)) == len(ws.boxes)  # identical blocks, never stacked twice
        assert (ws.occupancy() == 1).sum() == len(ws.boxes)  # each block fills exactly one cell


@pytest.mark.parametrize("family", ["2ds", "3do", "3dc"])
def test_same_seed_same_workspace_other_seed_other(family):
    a = generate(family, np.random.default_rng(7))
    b = generate(family, np.random.default_rng(7))
    c = generate(family, np.random.default_rng(8))
    assert a == b
    assert a != c
    np.testing.assert_array_equal(a.occupancy(), b.occupancy())


def test_unknown_family_is_named():
    with pytest.raises(ValueError, match="unknown workspace family 'kitchen'"):
        generate("kitchen", np.random.default_rng(0))


# -- occupancy ------------------------------------------------------------------------


@pytest.mark.parametrize("family, shape", [("2ds", (31, 31)), ("3do", (41, 41, 6)), ("3dc", (11, 11, 11))])
def test_occupancy_matches_a_cell_by_cell_loop(family, shape):
    ws = generate(family, np.random.default_rng(3))
    grid = ws.occupancy()
    assert grid.shape == shape and grid.dtype == np.float32
    assert set(np.unique(grid)) == {-1.0, 1.0}
    np.testing.assert_array_equal(grid, slow_occupancy(ws))


def test_occupancy_of_a_hand_made_workspace():
    ws = Workspace(np.zeros(2), np.array([4.0, 3.0]), np.array([[[1, 0], [3, 1]], [[0, 2], [0.6, 2.6]]], float))
    expected = np.array(
        [  # x rows, y columns; cell centres at 0.5, 1.5, ...
            [-1, -1, 1],  # x=0.5: the thin box covers y=2.5 only
            [1, -1, -1],  # x=1.5: first box covers y=0.5
            [1, -1, -1],
            [-1, -1, -1],
        ]
    )
    np.testing.assert_array_equal(ws.occupancy(), expected)
    np.testing.assert_array_equal(ws.occupancy(), slow_occupancy(ws))


def test_closed_boxes_occupy_the_cell_centre_on_their_face():
    ws = Workspace(np.zeros(2), np.array([3.0, 3.0]), np.array([[[0.0, 0.0], [1.5, 0.5]]]))
    np.testing.assert_array_equal(ws.occupancy()[:, 0], [1, 1, -1])  # centre (1.5, 0.5) lies on the corner


def test_grid_points_are_cell_centres():
    ws = generate("3do", np.random.default_rng(0))
    points = ws.grid_points()
    assert points.shape == (41, 41, 6, 3)
    np.testing.assert_array_equal(points[0, 0, 0], [0.5, 0.5, 0.5])
    np.testing.assert_array_equal(points[40, 3, 5], [40.5, 3.5, 5.5])


def test_contains_points_uses_closed_boxes():
    ws = Workspace(np.zeros(3), np.full(3, 5.0), np.array([[[1, 1, 1], [2, 2, 2]]], float))
    points = np.array([[1.5, 1.5, 1.5], [2, 2, 2], [2 + 1e-9, 1.5, 1.5], [0, 0, 0]])
    np.testing.assert_array_equal(ws.contains_points(points), [True, True, False, False])


# -- files and equality -----------------------------------------------------------------


@pytest.mark.parametrize("family", ["2ds", "3do", "3dc"])
def test_save_load_round_trip(tmp_path, family):
    ws = generate(family, np.random.default_rng(11))
    ws.save(tmp_path / "ws.json")
    back = Workspace.load(tmp_path / "ws.json")
    assert back == ws
    assert back.labels == ws.labels and back.family == family
    np.testing.assert_array_equal(back.occupancy(), ws.occupancy())
    assert not list(tmp_path.glob("*.tmp"))


def test_equality_sees_every_field():
    ws = Workspace(np.zeros(2), np.full(2, 5.0), np.array([[[1, 1], [2, 2]]], float), family="2ds")
    moved = Workspace(np.zeros(2), np.full(2, 5.0), np.array([[[1, 1], [2, 3]]], float), family="2ds")
    other_family = Workspace(np.zeros(2), np.full(2, 5.0), ws.boxes, family="")
    assert ws != moved and ws != other_family and ws != "2ds"


def test_arrays_are_read_only():
    ws = generate("2ds", np.random.default_rng(0))
    with pytest.raises(ValueError):
        ws.boxes[0, 0, 0] = 5.0


# -- bad input ---------------------------------------------------------------------------

GOOD_BOX = [[[1.0, 1.0], [2.0, 2.0]]]


@pytest.mark.parametrize(
    "lower, upper, boxes, message",
    [
        ([0, 0], [5, 5], [[[1, 1, 1], [2, 2, 2]]], r"boxes must have shape \(K, 2, 2\)"),
        ([0, 0], [5, 5], [[1, 1], [2, 2]], r"boxes must have shape"),
        ([0, 0], [5, 5], [[[1, 1], [2, 2], [3, 3]]], r"boxes must have shape"),
        ([0, 0], [5, 5], [[[1, np.nan], [2, 2]]], "boxes contains NaN"),
        ([0, 0], [5, np.inf], GOOD_BOX, "upper contains NaN or infinite"),
        ([0, 0], [5, 0], GOOD_BOX, "upper .* must exceed lower"),
        ([0, 0], [5, -1], GOOD_BOX, "must exceed lower"),
        ([0, 0], [5, 5, 5], GOOD_BOX, "lower and upper must both have shape"),
        ([0], [5], [], "lower and upper must both have shape"),
        ([[0, 0]], [5, 5], GOOD_BOX, "lower must be a 1-D array"),
        ([0, 0], [5, 5], [[[2, 2], [1, 3]]], "max corner >= min corner"),
    ],
)
def test_bad_workspace_is_named(lower, upper, boxes, message):
    with pytest.raises(ValueError, match=message):
        Workspace(np.array(lower, float), np.array(upper, float), boxes)


def test_wrong_number_of_labels():
    with pytest.raises(ValueError, match="1 labels for 2 boxes"):
        Workspace(np.zeros(2), np.full(2, 5.0), np.array(GOOD_BOX * 2), labels=("desk",))


def test_empty_workspace_is_all_free():
    ws = Workspace(np.zeros(3), np.full(3, 4.0), [])
    assert ws.boxes.shape == (0, 2, 3)
    np.testing.assert_array_equal(ws.occupancy(), -np.ones((4, 4, 4)))


@pytest.mark.parametrize(
    "content, message",
    [
        (None, "corrupted or truncated JSON"),  # truncated: the first half of a real file
        ("[1, 2, 3]", "expected a JSON object"),
        ('{"lower": [0, 0], "upper": [5, 5]}', r"missing keys \['boxes'\]"),
        ('{"lower": [0, 0], "upper": [5, 5], "boxes": [[[1, 1], [2, "x"]]]}', "boxes must be an array of numbers"),
        ('{"lower": [0, 0], "upper": [5, 5], "boxes": [[[1, 1], [2]]]}', "boxes must be an array of numbers"),
        ('{"lower": null, "upper": [5, 5], "boxes": []}', "lower must be a 1-D array"),
        ('{"lower": ["a", 0], "upper": [5, 5], "boxes": []}', "lower must be an array of numbers"),
        ('{"lower": [0, 0], "upper": [5, 5], "boxes": [[[3, 3], [2, 2]]]}', "max corner >= min corner"),
    ],
)
def test_corrupted_workspace_file_is_named(tmp_path, content, message):
    path = tmp_path / "ws.json"
    if content is None:
        generate("3dc", np.random.default_rng(0)).save(path)
        text = path.read_text()
        path.write_text(text[: len(text) // 2])
    else:
        path.write_text(content)
    with pytest.raises(ValueError, match=message):
        Workspace.load(path)


def test_binary_garbage_file_is_named(tmp_path):
    path = tmp_path / "ws.json"
    path.write_bytes(bytes(range(128, 256)))
    with pytest.raises(ValueError, match="not a valid workspace file"):
        Workspace.load(path)


def test_saved_file_is_plain_json(tmp_path):
    ws = generate("3do", np.random.default_rng(2))
    ws.save(tmp_path / "ws.json")
    data = json.loads((tmp_path / "ws.json").read_text())
    assert data["family"] == "3do" and len(data["boxes"]) == len(ws.boxes) and data["labels"] == list(ws.labels)
