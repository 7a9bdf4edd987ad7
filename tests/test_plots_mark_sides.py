"""Marks drawn on their own mistakes (toolkit.plots.mark_sides; reader r42c, chapter 03's P(valid) maps)."""

import numpy as np

from toolkit.geometry import robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.plots import answers, cell_marks, mark_sides, slices
from toolkit.plots import classifier as pc


def marked_cells(fig, grid, label):
    """The cells (m, 2) under the centres of ``fig``'s first map's marks of ``label``, and whether each is one."""
    (marks,) = [c for c in cell_marks.cell_marks(fig.axes[0]) if c.get_label() == label]
    first, cell = np.array([grid.axes[0][0], grid.axes[1][0]]), grid.axes[0][1] - grid.axes[0][0]
    at = (np.asarray(marks.get_offsets()) - first) / cell  # (m, 2) in cells
    return np.rint(at).astype(int), np.allclose(at, np.rint(at))


def test_every_square_on_a_kept_colliding_cell_and_every_circle_on_a_rejected_free_one():
    """Reader r42c: marks moved towards the truth's side of the outline sat where the model is right (squares on the
    black it rejects, circles past the dotted line on the white it keeps). Each mark is now centred on a cell of its
    own kind: every square on a cell kept (P(valid) >= threshold) and in collision, every circle on a cell rejected
    and free, so never across the threshold's contour; here a block's corner cells kept and a ring of free cells
    rejected around it, on a fine map where a mark stands for a tile."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    i, j = np.nonzero(~valid)
    ring = np.zeros_like(valid)
    ring[i.min() - 2 : i.max() + 3, j.min() - 2 : j.max() + 3] = True
    probability = np.where(valid & ~ring, 0.9, 0.1)  # free cells two wide around the block rejected
    probability[[i.min(), i.max()], j.min() : j.max() + 1] = 0.9  # the block's left and right edges kept
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    kept = probability >= 0.5
    for label, right_kind in (("invalid kept (dangerous)", kept & ~valid), ("valid rejected", ~kept & valid)):
        cells, centred = marked_cells(fig, fine, label)
        assert len(cells) and centred, label  # each centred on a cell
        assert right_kind[cells[:, 0], cells[:, 1]].all(), label


def test_a_tiles_mark_sits_on_its_mistake_nearest_their_centroid():
    """Reader r42c: "Put each square and circle on a mistake cell of its tile (the one nearest the tile's mistake
    centroid)". An L of mistakes, whose centroid lies off it, is marked on its cell nearest that centroid."""
    cells = np.array([[0, 0], [1, 0], [2, 0], [3, 0], [0, 1], [0, 2], [0, 3]], dtype=float)  # centroid (0.86, 0.86)
    at = mark_sides.nearest_mistake(cells, np.zeros((0, 2)), 0.0, 0.0, (10, 10))  # not the centroid: no mistake
    assert at is not None and tuple(at) in {(1, 0), (0, 1)}  # 0.87 cells from it; the corner (0, 0) is 1.21
    row = np.array([[0, 5], [1, 5], [2, 5]], dtype=float)  # by the map's left edge; a mark 1.5 cells to its rings
    framed = mark_sides.nearest_mistake(row, np.zeros((0, 2)), 0.0, 1.5, (10, 10))  # (1, 5)'s would cross the frame
    np.testing.assert_array_equal(framed, [2, 5])  # r19b: a mark inside the map's frame, rings and all
    assert mark_sides.nearest_mistake(cells, np.array([[1.0, 1.0]]), 5.0, 0.0, (10, 10)) is None  # beside a mark


def test_a_maps_marks_match_its_counted_mistakes():
    """Every map's squares stand for its dangerous cells only: a map with none has no square."""
    grid = slices.slice_grid(robots.point_robot(), n=40)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = grid.image(exact_checker(ws, robots.point_robot()).are_valid(grid.configs))  # (40, 40)
    probability = np.where(valid, 0.9, 0.1)
    probability[valid.nonzero()[0][:3], valid.nonzero()[1][:3]] = 0.1  # three free cells rejected
    fig = pc.probability_map(probability, valid, grid, threshold=0.5)
    assert (answers.answer_codes(probability >= 0.5, valid) == 3).sum() == 0
    assert len(marked_cells(fig, grid, "invalid kept (dangerous)")[0]) == 0
    cells, _ = marked_cells(fig, grid, "valid rejected")
    assert 1 <= len(cells) <= 3 and (probability[cells[:, 0], cells[:, 1]] < 0.5).all()
