"""Marks kept wholly on their side of an outline (toolkit.plots.mark_sides; reader r32c, chapter 03's `strong` maps)."""

import numpy as np

from toolkit.geometry import robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.plots import answers, cell_marks, mark_sides, slices
from toolkit.plots import classifier as pc


def test_a_square_on_a_blocks_corner_cell_lies_inside_the_block_clear_of_its_outline_and_beside_its_cell():
    """Reader r32c: the `strong` map's dangerous cells are a block's corner cells; a square centred on one, 3.5 cells
    wide with its rings, lay mostly in the free space beside the block it was said to be inside. Each square now lies,
    rings included, inside the outline and clear of its line (r34c: a square on the line read as lying on it), and
    still touches the corner cell it stands for."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    i, j = np.nonzero(~valid)
    probability = np.where(valid, 0.9, 0.1)
    corners = [(i.min(), j.min()), (i.max(), j.max())]  # two corner cells kept: dangerous
    for a, b in corners:
        probability[a, b] = 0.9
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    (squares,) = [c for c in cell_marks.cell_marks(ax) if c.get_label() == "invalid kept (dangerous)"]
    first, cell = np.array([fine.axes[0][0], fine.axes[1][0]]), fine.axes[0][1] - fine.axes[0][0]
    at = (np.asarray(squares.get_offsets()) - first) / cell  # (2, 2) in cells
    half = (np.sqrt(squares.get_sizes()[0]) / 2 + cell_marks.RING) / cell_marks.cell_points(ax, fine)
    assert len(at) == 2 and half > 1  # wider than two cells: centred on a corner cell, most of it was outside
    for centre, corner in zip(sorted(at.tolist()), corners):
        gap = mark_sides.GAP / cell_marks.cell_points(ax, fine)  # cells: the outline's half width, rings included
        assert mark_sides.outside_area(np.array(centre), ~valid, half + gap) == 0.0  # inside, clear of the line
        assert np.max(np.abs(np.array(centre) - corner)) - 0.5 < half + gap  # its cell beside it, across the line
    assert (answers.answer_codes(probability >= 0.5, valid) == 3).sum() == 2


def test_inward_keeps_a_mark_in_place_where_it_already_lies_inside_and_apart_from_the_others():
    side = np.zeros((20, 20), dtype=bool)
    side[5:15, 5:15] = True
    deep = np.array([10.0, 10.0])
    np.testing.assert_array_equal(mark_sides.inward(deep, side, 1.7, 1.2, np.zeros((0, 2)), 0.0), deep)
    corner = np.array([5.0, 5.0])  # a corner cell: moved in, up to 1.2 cells each way
    moved = mark_sides.inward(corner, side, 1.7, 1.2, np.zeros((0, 2)), 0.0)
    np.testing.assert_allclose(moved, [6.2, 6.2])
    assert mark_sides.outside_area(moved, side, 1.7) == 0.0
    blocked = mark_sides.inward(corner, side, 1.7, 1.2, np.array([[7.0, 7.0]]), 3.0)  # no room beside another mark
    np.testing.assert_array_equal(blocked, corner)


def test_a_marks_area_beyond_the_maps_frame_counts_as_on_the_other_side():
    """Reader r34c: a circle in a strip too narrow for it was pushed beyond the frame, where nothing counted, then
    pulled back in onto the block beside the strip, the frame cutting it in half."""
    free = np.ones((10, 10), dtype=bool)
    assert mark_sides.outside_area(np.array([5.0, 5.0]), free, 1.0) == 0.0
    assert mark_sides.outside_area(np.array([0.0, 5.0]), free, 1.0) == 1.0  # half a cell of its 2-cell side beyond
