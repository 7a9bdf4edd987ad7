"""The collision MLP's figures (notebook 03) show what they claim: the given probabilities, the exact
checker's C-obstacles, exactly the dangerous and conservative cells, hand-computed counts and ROC points."""

import re

import matplotlib as mpl
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection, PathCollection
from matplotlib.colors import to_hex, to_rgb, to_rgba
from matplotlib.contour import ContourSet

from toolkit.geometry import robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.learning import metrics
from toolkit.plots import alt, answers, cell_marks, slices
from toolkit.plots import classifier as pc
from toolkit.plots.answers import confusion_counts
from toolkit.plots.palette import COLORS, contrast

N = 24  # grid cells per axis


@pytest.fixture(scope="module")
def grid():
    return slices.slice_grid(robots.point_robot(), n=N)


@pytest.fixture(scope="module")
def valid(grid):
    """The exact checker's answers in a 31x31 workspace with one block [10, 20] x [5, 12], as a grid (N, N)."""
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    return grid.image(exact_checker(ws, robots.point_robot()).are_valid(grid.configs))


@pytest.fixture(scope="module")
def probability(grid):
    """A made-up P(valid) (N, N): rising along x, so mistakes of both kinds appear at a middle threshold."""
    x = (grid.axes[0] - grid.lower[0]) / (grid.upper[0] - grid.lower[0])
    return np.repeat(x[:, None], N, axis=1) * 0.8 + 0.1 * np.sin(np.arange(N))[None, :] + 0.1


def cell_centres(grid, mask):
    i, j = np.nonzero(mask)
    return {(x, y) for x, y in zip(grid.axes[0][i], grid.axes[1][j])}


def scatter_points(ax, label):
    (collection,) = [c for c in ax.collections if isinstance(c, PathCollection) and c.get_label() == label]
    return {tuple(p) for p in collection.get_offsets()}


def block_of_squares(fig, kind="squares") -> int:
    """How many cells each way one mark of ``kind`` (dangerous squares, conservative circles) stands for, as the
    figure's description says (1: one a cell)."""
    found = re.search(kind + r" \(one per (\d+) x \1 cells", alt.alt_text(fig))
    return int(found[1]) if found else 1


def boundary_of(ax) -> ContourSet:
    """The true C-obstacle boundary on a map: its one solid contour (the threshold's is dotted)."""
    (boundary,) = [
        c
        for c in ax.get_children()
        if isinstance(c, ContourSet) and not c.filled and c.get_linestyle()[0][1] is None  # type: ignore[index]
    ]
    return boundary


def test_a_probability_maps_c_obstacles_are_hatched_inside_their_outline(grid, probability, valid):
    """Reader r29c, chapter 03's yaw x joint slice: free corners the model calls colliding were as dark as the
    C-obstacle beside them. The true C-obstacles are hatched, nothing filled: the truth reads without the grey."""
    ax = pc.probability_map(probability, valid, grid, threshold=0.5).axes[0]
    (hatched,) = [c for c in ax.get_children() if isinstance(c, ContourSet) and c.filled]
    assert list(hatched.hatches) == ["//"] and list(hatched.levels) == [0.5, 1.5]
    inside = np.concatenate([p.vertices for p in hatched.get_paths()])  # (n, 2) the hatched region's outline
    x, y = inside.T
    i, j = np.nonzero(~valid)
    cell = grid.axes[0][1] - grid.axes[0][0]
    assert x.min() >= grid.axes[0][i.min()] - cell and x.max() <= grid.axes[0][i.max()] + cell
    assert y.min() >= grid.axes[1][j.min()] - cell and y.max() <= grid.axes[1][j.max()] + cell


def assert_squares_mark(ax, grid, mask, k, label="invalid kept (dangerous)"):
    """The marks named ``label`` (default: the dangerous squares) mark exactly the cells of ``mask``: one a cell (``k``
    1), or one per block of ``k x k`` cells, every such cell within its block of a mark and every mark beside one."""
    if k == 1:
        assert scatter_points(ax, label) == cell_centres(grid, mask)
        return
    cell = grid.axes[0][1] - grid.axes[0][0]
    dangerous = np.array(sorted(cell_centres(grid, mask)))  # (n, 2)
    centres = np.array(sorted(scatter_points(ax, label)))  # (m, 2)
    apart = np.max(np.abs(dangerous[:, None] - centres[None]), axis=-1) / cell  # (n, m) in cells, the larger axis
    assert (apart.min(axis=1) < k).all() and (apart.min(axis=0) < k).all()


def test_slice_grid_sweeps_two_dofs_over_cell_centres_and_fixes_the_rest():
    robot = robots.box_chain(1)
    fixed = np.array([5.5, 5.5, 5.5, 0.1, 0.2, 0.3, 0.4])
    grid = slices.slice_grid(robot, dofs=(0, 6), fixed=fixed, n=5)
    assert grid.shape == (5, 5) and grid.names == ("x", "joint1") and grid.configs.shape == (25, 7)
    assert grid.extent == (0.0, 11.0, -2.0, 2.0)
    np.testing.assert_allclose(grid.axes[0], [1.1, 3.3, 5.5, 7.7, 9.9])
    np.testing.assert_allclose(grid.axes[1], [-1.6, -0.8, 0.0, 0.8, 1.6], atol=1e-12)
    i, j = 3, 1
    row = grid.configs[i * 5 + j]
    assert row[0] == grid.axes[0][i] and row[6] == grid.axes[1][j]
    np.testing.assert_array_equal(row[1:6], fixed[1:6])
    assert grid.image(np.arange(25))[i, j] == i * 5 + j
    with pytest.raises(ValueError):
        slices.slice_grid(robot, dofs=(0, 0))


def test_mistakes_near_boundary_counts_the_wrong_cells_beside_the_other_truth():
    truth = np.ones((7, 8), dtype=bool)
    truth[1:3, 1:4] = False  # a C-obstacle of 2 x 3 cells
    predicted = truth.copy()
    predicted[1, 1] = True  # inside it, but beside free cells: a boundary mistake
    predicted[2, 4] = False  # free, beside it: a boundary mistake
    predicted[5, 6] = False  # free, away from it and from the map's edge
    predicted[6, 7] = False  # free, in the map's corner: where the region's walls are
    assert answers.mistakes_near_boundary(predicted, truth) == (4, pytest.approx(3 / 4))
    # (5, 6): 2 steps from the wall past (5, 7)
    assert answers.mistakes_near_boundary(predicted, truth, cells=2) == (4, 1.0)
    assert answers.mistakes_near_boundary(truth, truth) == (0, 0.0)
    with pytest.raises(ValueError, match="a map of predictions"):
        answers.mistakes_near_boundary(predicted.ravel(), truth.ravel())
    with pytest.raises(ValueError, match="cells must be 1 or more"):
        answers.mistakes_near_boundary(predicted, truth, cells=0)


def test_answer_codes_and_counts_by_hand():
    predicted = np.array([True, True, False, False, True, True])
    truth = np.array([True, False, True, False, False, True])
    np.testing.assert_array_equal(answers.answer_codes(predicted, truth), [0, 3, 1, 2, 3, 0])
    assert answers.confusion_counts(predicted, truth) == {
        "valid kept": 2,
        "valid rejected": 1,
        "invalid rejected": 1,
        "invalid kept (dangerous)": 2,
    }


def test_roc_points_are_fpr_and_tpr_at_each_threshold(probability, valid):
    thresholds = [0.0, 0.3, 0.5, 0.71, 1.0]
    ts, fpr, tpr = answers.roc_points(probability, valid, thresholds)
    np.testing.assert_array_equal(ts, thresholds)
    for t, f, r in zip(thresholds, fpr, tpr):
        rates = metrics.classification((probability >= t).ravel(), valid.ravel())
        assert r == pytest.approx(rates["tpr"]) and f == pytest.approx(1 - rates["tnr"])
    ts, fpr, tpr = answers.roc_points(probability, valid)  # every distinct probability, then +inf: (1, 1) ... (0, 0)
    np.testing.assert_array_equal(ts, np.append(np.unique(probability), np.inf))
    assert (fpr[0], tpr[0], fpr[-1], tpr[-1]) == (1, 1, 0, 0)
    assert np.all(np.diff(fpr) <= 0) and np.all(np.diff(tpr) <= 0)
    with pytest.raises(ValueError):
        answers.roc_points(probability, np.ones_like(valid))


def test_best_balanced_is_the_highest_tpr_plus_tnr_over_thresholds():
    """Reader r49c: the best balanced accuracy any threshold reaches, and where."""
    p = np.array([0.1, 0.2, 0.3, 0.6, 0.7, 0.8])
    valid = np.array([False, False, True, True, True, False])
    balanced, threshold = answers.best_balanced(p, valid)
    assert threshold == 0.3 and balanced == pytest.approx((1 + 2 / 3) / 2)  # keeps all 3 valid, rejects 2 of 3
    assert answers.best_balanced([0.5, 0.5], [True, False]) == (0.5, 0.5)  # nothing to tell apart: a coin flip


def test_probability_map_shows_the_probabilities_the_boundary_and_exactly_the_mistakes(grid, probability, valid):
    threshold = 0.45
    ax = pc.probability_map(probability, valid, grid, threshold=threshold).axes[0]
    image, tint = ax.images  # P(valid), then its wrong cells tinted (reader r36c: circles alone hid 64 % wrong)
    np.testing.assert_array_equal(image.get_array(), probability.T)  # origin lower: row = second DoF
    assert image.origin == "lower" and tuple(image.get_extent()) == grid.extent
    dangerous, conservative = (probability >= threshold) & ~valid, (probability < threshold) & valid
    tinted = np.asarray(tint.get_array()).transpose(1, 0, 2)  # (nx, ny, RGBA)
    np.testing.assert_array_equal(tinted[..., 3] > 0, dangerous | conservative)
    np.testing.assert_allclose(tinted[conservative][:, :3], np.tile(to_rgb(pc.CONSERVATIVE), (conservative.sum(), 1)))
    np.testing.assert_allclose(tinted[dangerous][:, :3], np.tile(to_rgb(pc.DANGEROUS), (dangerous.sum(), 1)))
    assert dangerous.sum() > 0 and conservative.sum() > 0  # the test means something
    legend = " ".join(t.get_text() for t in ax.figure.legends[0].get_texts())  # r60c: the cell, not the circle
    assert "(circles; its cell filled\nsky blue if P(valid) < 0.25)" in legend and "where dark" not in legend
    assert_squares_mark(ax, grid, dangerous, block_of_squares(ax.figure))
    assert_squares_mark(ax, grid, conservative, block_of_squares(ax.figure, "circles"), label="valid rejected")
    marks = {c.get_label(): len(c.get_offsets()) for c in cell_marks.cell_marks(ax)}  # r34c: marks counted too
    k = {"squares": block_of_squares(ax.figure), "circles": block_of_squares(ax.figure, "circles")}
    assert f"{(dangerous.sum() + conservative.sum()) / dangerous.size:.0%} of the map wrong\n" in ax.get_title()
    assert ax.get_title().endswith(
        f"{dangerous.sum()} dangerous cells: {marks['invalid kept (dangerous)']} squares, 1 per {k['squares']} x "
        f"{k['squares']}-cell tile\n{conservative.sum()} conservative cells: {marks['valid rejected']} circles, 1 per "
        f"{k['circles']} x {k['circles']}-cell tile"
    ) or (max(k.values()) == 1 and ax.get_title().endswith("conservative (circles)"))
    # the boundary runs midway between the exact checker's free and blocked cells, around the one block
    blocked = np.argwhere(~valid)
    step = grid.axes[0][1] - grid.axes[0][0]
    x0, x1 = grid.axes[0][blocked[:, 0].min()] - step / 2, grid.axes[0][blocked[:, 0].max()] + step / 2
    y0, y1 = grid.axes[1][blocked[:, 1].min()] - step / 2, grid.axes[1][blocked[:, 1].max()] + step / 2
    contour = boundary_of(ax)
    vertices = np.concatenate([p.vertices for p in contour.get_paths()])
    x, y = vertices.T
    on_side = np.isclose(x, x0) | np.isclose(x, x1) | np.isclose(y, y0) | np.isclose(y, y1)
    inside = (x >= x0 - 1e-9) & (x <= x1 + 1e-9) & (y >= y0 - 1e-9) & (y <= y1 + 1e-9)
    assert len(vertices) > 4 and on_side.all() and inside.all()


def test_a_fine_maps_dangerous_squares_stay_large_enough_to_see():
    """On a 100-cell map (chapter 03 at full size) a cell is about 2 points wide: one square then marks each block of
    k x k cells holding a dangerous one, at least MIN_MARK points a side, over the boundary (readers r10b, r11: under
    its ringed line a square next to it was cut in two, or hidden); every dangerous cell lies in a square's block,
    every square beside a dangerous cell, and the description says k."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    x = (fine.axes[0] - fine.lower[0]) / (fine.upper[0] - fine.lower[0])  # (100,)
    probability = np.repeat(x[:, None], 100, axis=1)  # rising along x: the block's right part is kept
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    (squares,) = [c for c in cell_marks.cell_marks(ax) if c.get_label() == "invalid kept (dangerous)"]
    boundary = boundary_of(ax)
    assert np.sqrt(squares.get_sizes()[0]) >= cell_marks.MIN_MARK and squares.get_zorder() > boundary.get_zorder()
    k = block_of_squares(fig)
    assert k > 1 and len(squares.get_offsets()) < ((probability >= 0.5) & ~valid).sum() / k
    assert_squares_mark(ax, fine, (probability >= 0.5) & ~valid, k)


def test_blocked_cells_are_the_grown_block(grid, valid):
    """The truth the maps draw is the C-obstacle: the block grown by the robot's half width, 0.25."""
    x, y = grid.configs.T
    inside = (x >= 9.75) & (x <= 20.25) & (y >= 4.75) & (y <= 12.25)
    np.testing.assert_array_equal(~valid, grid.image(inside))


def test_probability_maps_side_by_side_each_with_its_own_threshold(grid, probability, valid):
    maps = {"paper": probability, "strong": 1 - probability}
    fig = pc.probability_maps(maps, valid, grid, thresholds={"paper": 0.3, "strong": 0.6})
    axes = [ax for ax in fig.axes if ax.images and ax.get_label() != "<colorbar>"]
    assert [ax.get_title().split("\n")[0].split(", ")[:2] for ax in axes] == [  # then the share wrong (r36c)
        ["paper: P(valid)", "threshold 0.30"],
        ["strong: P(valid)", "threshold 0.60"],
    ]
    for ax, p, t in zip(axes, maps.values(), (0.3, 0.6)):
        np.testing.assert_array_equal(ax.images[0].get_array(), p.T)
        assert_squares_mark(ax, grid, (p >= t) & ~valid, block_of_squares(fig))


def test_each_map_has_its_own_colour_bar_with_its_threshold_drawn_across_it(grid, probability, valid):
    """Review r16b: side by side, the one colour bar beside the strong map read as that map's alone; each map now has
    its own, and a line on it at its threshold tells a grey just below it from one just above."""
    fig = pc.probability_maps(
        {"paper": probability, "strong": 1 - probability}, valid, grid, thresholds={"paper": 0.3, "strong": 0.6}
    )
    bars = [ax for ax in fig.axes if ax.get_label() == "<colorbar>"]
    assert len(bars) == 2
    for bar, t in zip(bars, (0.3, 0.6)):
        assert bar.get_ylabel() == f"P(valid); the line: threshold {t:.2f}"
        assert [tuple(line.get_ydata()) for line in bar.get_lines()] == [(t, t)]
    maps = [ax for ax in fig.axes if ax.images and ax.get_label() != "<colorbar>"]
    assert maps[0].get_position().y0 > maps[1].get_position().y1  # one above the other, each as wide as the page


def test_a_fine_maps_marks_stand_apart_and_a_one_cell_strip_of_mistakes_is_marked():
    """Review r18b, chapter 03 at full size: the dangerous squares, one per block of a few cells, merged into a pile
    that could not be counted, and the conservative cells' hatch hid the grey of P(valid). Each kind's marks are now
    at least its pitch apart (a block of ``k`` cells is that wide), the conservative circles sparser than the squares,
    and a strip of conservative cells one cell wide (review r16b: it caught no dot of the old hatch) still carries
    circles: every cell of it within a block of one."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    strip = np.zeros_like(valid)
    strip[:, np.nonzero(~valid.all(axis=0))[0].max() + 1] = True  # the row of cells just above the block
    probability = np.where(strip, 0.2, 0.9)  # right everywhere but that one-cell strip, rejected though free
    probability[:30, :20] = 0.2  # and a corner of free space rejected, obstacle cells there kept
    probability[40:60, 40:60] = 0.9  # and the block's middle kept: dangerous
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    side = cell_marks.cell_points(ax, fine)  # points
    for label, kind, code in (("valid rejected", "circles", 1), ("invalid kept (dangerous)", "squares", 3)):
        k = block_of_squares(fig, kind)
        assert k * side >= pc.PITCH[code] and 100 % k == 0  # that far apart, and a block divides the map (r29c)
        assert k == cell_marks.block_side(int(np.ceil(pc.PITCH[code] / side - 1e-9)), pc.BLOCKS[code], (100, 100))
        mask = answers.answer_codes(probability >= 0.5, valid) == code
        assert_squares_mark(ax, fine, mask, k, label=label)
    assert block_of_squares(fig, "circles") > block_of_squares(fig, "squares")  # the circles sparser
    (squares,) = [c for c in cell_marks.cell_marks(ax) if c.get_label() == "invalid kept (dangerous)"]
    at = ax.transData.transform(squares.get_offsets()) * 72 / fig.dpi  # (m, 2) points
    apart = np.max(np.abs(at[:, None] - at[None]), axis=-1) + np.diag(np.full(len(at), np.inf))  # (m, m)
    assert apart.min() >= np.sqrt(squares.get_sizes()[0]) + cell_marks.CLEAR - 1e-6  # their rings never touch
    cell = fine.axes[0][1] - fine.axes[0][0]
    strip_cells = np.array(sorted(cell_centres(fine, strip & valid)))  # (n, 2)
    circles = np.array(sorted(scatter_points(ax, "valid rejected")))  # (m, 2)
    apart = np.max(np.abs(strip_cells[:, None] - circles[None]), axis=-1) / cell  # (n, m) in cells
    assert (apart.min(axis=1) < block_of_squares(fig, "circles")).all()  # every cell of the strip beside a circle


def test_each_mark_sits_on_a_mistake_of_its_kind():
    """Reader r26c, chapter 03: a block's mistakes on two edges of a C-obstacle averaged into its inside, so that a
    circle ("rejected, free") sat in the obstacle and others on the kept side of the threshold. Each mark now covers
    one of its block's mistakes of its kind, centred on it (reader r42c: moved towards the truth's side of the outline,
    squares sat where the model rejects): here a ring of free cells rejected around the block, and the block's left
    and right edges kept (dangerous), at both pitches."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    i, j = np.nonzero(~valid)
    ring = np.zeros_like(valid)
    ring[i.min() - 2 : i.max() + 3, j.min() - 2 : j.max() + 3] = True
    probability = np.where(valid & ~ring, 0.9, 0.1)  # a ring two cells wide of free cells rejected
    probability[[i.min(), i.max()], j.min() : j.max() + 1] = 0.9  # the block's left and right edges kept
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    codes = answers.answer_codes(probability >= 0.5, valid)
    first, cell = np.array([fine.axes[0][0], fine.axes[1][0]]), fine.axes[0][1] - fine.axes[0][0]
    for label, code in (("valid rejected", 1), ("invalid kept (dangerous)", 3)):
        (mark,) = [c for c in cell_marks.cell_marks(ax) if c.get_label() == label]
        at = (np.asarray(mark.get_offsets()) - first) / cell  # (m, 2) the marks' centres, in cells
        kind = np.argwhere(codes == code)  # (n, 2) the mistakes of its kind
        under = np.max(np.abs(at[:, None] - kind[None]), axis=2) < 1e-6  # (m, n) a mark centred on a mistake
        assert len(at) and under.any(axis=1).all(), label
    assert block_of_squares(fig, "circles") > 1 and block_of_squares(fig, "squares") > 1  # merged into blocks


def test_a_maps_circles_lie_over_its_outlines_and_every_mark_inside_its_frame():
    """Reader r19b, chapter 03's 3DC-7 slices at full size: a top row of marks sat on the map's frame, half outside it;
    reader r29c: circles under the outlines were half hidden. On a P(valid) map the circles lie over the outlines, the
    squares over both, and every mark, its rings included, lies inside the frame."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (100, 100)
    probability = np.where(valid, 0.2, 0.9)  # every answer wrong: circles out to the map's edges, squares in the block
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    marks = {c.get_label(): c for c in cell_marks.cell_marks(ax)}
    circles, squares = marks["valid rejected"], marks["invalid kept (dangerous)"]
    assert boundary_of(ax).get_zorder() < circles.get_zorder() < squares.get_zorder()
    frame = np.array(ax.bbox.extents) * 72 / fig.dpi  # (4,) x0, y0, x1, y1 in points
    for mark in (circles, squares):
        at = ax.transData.transform(mark.get_offsets()) * 72 / fig.dpi  # (m, 2) points
        inside = np.minimum(at - frame[:2], frame[2:] - at).min()  # the least distance from a centre to the frame
        assert inside >= np.sqrt(mark.get_sizes()[0]) / 2 + cell_marks.RING - 1e-6


def test_the_threshold_line_lies_under_the_outlines_and_hides_where_it_runs_along_them():
    """Reader r20b, chapter 03's `strong` map: where the model is sharp its dotted threshold line runs along the
    C-obstacle's outlines; r31c: drawn over them it made the outline look beaded; r44c: drawn under them but wider,
    its dots stuck out a cell on each side and read as running through the cells beside the outline. It is drawn
    under them, exactly as wide as the ringed outline: it shows only where the model's answer leaves the truth."""
    fine = slices.slice_grid(robots.point_robot(), n=60)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (60, 60)
    ax = pc.probability_map(np.where(valid, 0.9, 0.1), valid, fine, threshold=0.5).axes[0]
    contours = [c for c in ax.get_children() if isinstance(c, ContourSet) and not c.filled]
    (cut,) = [c for c in contours if c is not boundary_of(ax)]
    (squares,) = [c for c in cell_marks.cell_marks(ax) if c.get_label() == "invalid kept (dangerous)"]
    assert cut.get_zorder() < boundary_of(ax).get_zorder() < squares.get_zorder()
    ringed = boundary_of(ax).get_linewidths()[0] + 2 * 1.6  # the outline with its black and white rings
    assert max(cut.get_linewidths()) + 1.6 <= ringed + 1e-9  # the line with its dark ring: no wider (r44c)
    assert min(cut.get_linewidths()) >= 2.5  # still bold where it shows (r15c)
    cut_paths = np.concatenate([p.vertices for p in cut.get_paths()])  # on the cells' edges, as the outline
    x0, x1, y0, y1 = fine.extent
    edges = np.stack([x0 + (x1 - x0) * np.arange(61) / 60, y0 + (y1 - y0) * np.arange(61) / 60], axis=1)  # (61, 2)
    on_edge = np.isclose(cut_paths[:, None, :], edges[None]).any(axis=1).any(axis=1)  # (m,) x or y on a cell edge
    assert on_edge.all() and len(on_edge) > 10


def test_a_c_obstacle_against_the_maps_edge_is_outlined_along_the_frame():
    """Reader r44c, chapter 03's z = 5.5 slice: blocks on the bottom row had no outline along the frame and read as
    cut off by it. The outline runs along the frame exactly where obstacle cells touch it, one segment a run."""
    grid = slices.slice_grid(robots.point_robot(), n=10)
    valid = np.ones(grid.shape, dtype=bool)
    valid[2:5, 0:2] = False  # a block on the bottom edge, cells 2-4 along x
    valid[9, 6:8] = False  # a strip on the right edge, cells 6-7 along y
    ax = pc.probability_map(valid.astype(float), valid, grid, threshold=0.5).axes[0]
    (frame,) = [c for c in ax.collections if c.get_gid() == cell_marks.FRAME]
    x0, x1, y0, y1 = grid.extent
    cells = [((s - [x0, y0]) / [(x1 - x0) / 10, (y1 - y0) / 10]).round(6) for s in frame.get_segments()]
    segments = sorted(tuple(map(tuple, s)) for s in cells)  # in cells from the map's lower left corner
    assert segments == [((2.0, 0.0), (5.0, 0.0)), ((10.0, 6.0), (10.0, 8.0))]
    assert not frame.get_clip_on() and frame.get_linewidths()[0] == boundary_of(ax).get_linewidths()[0]
    angles = slices.slice_grid(robots.box_chain(1), dofs=(3, 6), n=10)  # alpha x joint: no wall at either's ends
    ax = pc.probability_map(valid.astype(float), valid, angles, threshold=0.5).axes[0]
    assert all(len(c.get_segments()) == 0 for c in ax.collections if c.get_gid() == cell_marks.FRAME)


def test_the_conservative_tint_leaves_the_grey_of_p_valid_readable():
    """Reader r44c: on the `paper` map, where most cells are conservative mistakes, the sky-blue tint hid the grey of
    P(valid). Laid over a mid grey, it moves the grey's lightness by under 3 % and each channel by under 0.05."""
    grey = np.full(3, 0.47)  # the `paper` map's grey, about
    tinted = (1 - pc.TINT[1]) * grey + pc.TINT[1] * np.array(to_rgb(pc.CONSERVATIVE))
    lightness = np.array([0.2126, 0.7152, 0.0722])
    assert abs(tinted @ lightness - grey @ lightness) < 0.03 and np.abs(tinted - grey).max() < 0.05
    assert pc.TINT[1] > 0 and pc.TINT[3] > pc.TINT[1]  # still tinted; the dangerous ones stronger


def test_threshold_view_colours_each_cell_by_its_answer_and_counts_them(grid, probability, valid):
    threshold = 0.55
    ax_map, ax_counts, ax_roc = pc.threshold_view(probability, valid, grid, threshold=threshold).axes
    predicted = probability >= threshold
    np.testing.assert_array_equal(ax_map.images[0].get_array(), answers.answer_codes(predicted, valid).T)
    heights = [bar.get_height() for bar in ax_counts.patches]
    assert heights == [
        np.sum(predicted & valid),
        np.sum(~predicted & valid),
        np.sum(~predicted & ~valid),
        np.sum(predicted & ~valid),
    ]
    on_bars = {line.get_marker(): (line.get_xdata()[0], line.get_ydata()[0]) for line in ax_counts.get_lines()}
    assert on_bars == {"o": (1, heights[1]), "s": (3, heights[3])}  # r19b: a bar of a few cells showed nothing
    (point,) = [
        line for line in ax_roc.get_lines() if line.get_marker() == "v"
    ]  # r45c, r51c: no mistake's or sweep's mark
    rates = metrics.classification(predicted.ravel(), valid.ravel())
    assert point.get_xdata()[0] == pytest.approx(1 - rates["tnr"])
    assert point.get_ydata()[0] == pytest.approx(rates["tpr"])


@pytest.mark.parametrize("n", [N, 100])  # a mark a cell; a mark per block of cells (chapter 03 at full size)
def test_threshold_views_mistakes_are_marked_at_a_size_one_sees_circles_sparse_over_the_boundary(n):
    """Reader r8b: the decision map's mistakes lay under the boundary's ringed line, invisible. Each kind has its own
    mark (circles conservative, squares dangerous) over every cell of that kind, at least ``MIN_MARK`` points wide, in
    the kind's colour: as many of its pixels show as the marks' area, about. Reader r27c: a circle a block of cells
    made a carpet that hid the cells' colour and the outlines; the circles are now as sparse as on a P(valid) map, and
    (reader r29c: half hidden under the outlines) over them, the squares over both."""
    robot = robots.point_robot()
    grid = slices.slice_grid(robot, n=n)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = grid.image(exact_checker(ws, robot).are_valid(grid.configs))
    x = (grid.axes[0] - grid.lower[0]) / (grid.upper[0] - grid.lower[0])
    probability = np.repeat(x[:, None], n, axis=1) * 0.8 + 0.1 * np.sin(np.arange(n))[None, :] + 0.1
    fig = pc.threshold_view(probability, valid, grid, threshold=0.55)
    ax_map = fig.axes[0]
    k = {"valid rejected": block_of_squares(fig, "circles"), "invalid kept (dangerous)": block_of_squares(fig)}
    assert 1 < k["valid rejected"] >= k["invalid kept (dangerous)"]  # the circles sparse at every size
    codes = answers.answer_codes(probability >= 0.55, valid)
    boundary = boundary_of(ax_map)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    image = np.asarray(canvas.buffer_rgba())[..., :3] / 255  # (H, W, 3), the top row first
    box = ax_map.get_window_extent()
    shown = image[int(image.shape[0] - box.y1) : int(image.shape[0] - box.y0), int(box.x0) : int(box.x1)]
    for code, label, marker in ((1, "valid rejected", "o"), (3, "invalid kept (dangerous)", "s")):
        assert np.any(codes == code)
        assert_squares_mark(ax_map, grid, codes == code, k[label], label=label)
        (marks,) = [c for c in ax_map.collections if c.get_label() == label]
        assert marks.get_zorder() > boundary.get_zorder()  # r29c: circles too, not half hidden under the outlines
        side = np.sqrt(marks.get_sizes()[0])  # points
        assert side >= cell_marks.MIN_MARK
        colour = to_rgba(pc.ANSWER_COLORS[code])[:3]
        seen = np.sum(np.all(np.abs(shown - colour) < 0.08, axis=-1))  # pixels of the kind's colour on the map
        area = len(marks.get_offsets()) * (side * fig.dpi / 72) ** 2 * (np.pi / 4 if marker == "o" else 1)
        assert seen >= 0.5 * area  # at least half of the marks' area, in their colour (their cells add to it)
    legend = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "valid rejected: conservative\nmistake (circles)" in legend  # r39c: section 1's table's names
    assert "invalid kept: dangerous\nmistake (squares)" in legend


def test_roc_curve_draws_every_curve_and_its_operating_point(probability, valid):
    curves = {"a": (probability, valid, 0.5), "b": (probability**2, valid, 0.2)}
    ax = pc.roc_curve(curves).axes[0]
    lines = [line for line in ax.get_lines() if line.get_label() != "chance"]
    assert len(lines) == 4
    for (curve, point), (p, truth, t) in zip(zip(lines[::2], lines[1::2]), curves.values()):
        _, fpr, tpr = answers.roc_points(p, truth)
        np.testing.assert_array_equal(curve.get_xdata(), fpr)
        np.testing.assert_array_equal(curve.get_ydata(), tpr)
        kept = p >= t
        assert point.get_xdata()[0] == pytest.approx(np.mean(kept[~truth]))
        assert point.get_ydata()[0] == pytest.approx(np.mean(kept[truth]))
    mistakes = {to_rgba(COLORS["dangerous"]), to_rgba(COLORS["conservative"])}  # r45c: vermillion squares, blue circles
    assert not {to_rgba(line.get_color()) for line in lines} & mistakes
    assert not {line.get_marker() for line in lines} & {"s", "o"}
    assert len({(line.get_color(), line.get_linestyle()) for line in lines[::2]}) == 2  # two curves told apart
    assert all(point.get_markersize() >= 10 and point.get_markeredgewidth() >= 1.5 for point in lines[1::2])  # r52c
    legend = ax.get_legend()  # r55c: the dash-dot curve's handle drew solid, its period longer than the handle
    names = {"-": None, "--": "dashed", "-.": "dashdot", ":": "dotted"}
    for curve in lines[::2]:
        name = names[curve.get_linestyle()]
        period = sum(mpl.rcParams[f"lines.{name}_pattern"]) * curve.get_linewidth() if name else 0.0  # in points
        assert period < legend.handlelength * legend.prop.get_size_in_points(), curve.get_linestyle()


def test_path_map_draws_the_path_and_marks_the_nodes_in_collision(grid, probability, valid):
    path = np.array([[1.0, 2.0], [5.0, 3.0], [25.0, 28.0]])
    nodes = np.array([[1.0, 1.0], [15.0, 8.0], [3.0, 4.0], [12.0, 6.0]])
    nodes_valid = np.array([True, False, True, False])
    edges = np.array([[0, 2]])  # reader r29c: drawn, so that a node in collision visibly has none
    ax = pc.path_map(
        probability, valid, grid, threshold=0.5, path=path, nodes=nodes, nodes_valid=nodes_valid, edges=edges
    ).axes[0]
    (drawn,) = [
        c
        for c in ax.collections
        if isinstance(c, LineCollection) and not isinstance(c, ContourSet) and c.get_gid() != cell_marks.FRAME
    ]
    np.testing.assert_array_equal(drawn.get_segments()[0], nodes[[0, 2]])
    lines = {line.get_label(): np.column_stack([line.get_xdata(), line.get_ydata()]) for line in ax.get_lines()}
    np.testing.assert_array_equal(lines["returned path (checked exactly)"], path)
    np.testing.assert_array_equal(lines[pc.COLLIDING], nodes[~nodes_valid])
    np.testing.assert_array_equal(lines["roadmap node, valid"], nodes[nodes_valid])
    np.testing.assert_array_equal(ax.images[0].get_array(), probability.T)
    path_line = next(line for line in ax.get_lines() if line.get_label() == "returned path (checked exactly)")
    assert path_line.get_linestyle() == "--" and path_line.get_marker() == "D"  # not the boundary's solid line
    squares = next(line for line in ax.get_lines() if line.get_label() == pc.COLLIDING)
    assert squares.get_zorder() > path_line.get_zorder()
    # w41c: a node in collision in the dangerous colour, but no square (a map's tile of dangerous cells) nor the start's
    assert (squares.get_marker(), to_hex(squares.get_color())) == ("P", COLORS["dangerous"])
    assert next(line for line in ax.get_lines() if line.get_label() == "start").get_marker() != "s"
    assert to_hex(drawn.get_colors()[0]) == COLORS["ink"]  # the edges: ink, seen on the light and the mid greys
    # readers r12b, r13b, r15c: a cross among the map's dangerous squares hid there; the map's mistakes go unmarked
    assert [c.get_label() for c in ax.collections if c.get_label() in answers.ANSWERS] == []
    (cut,) = [
        c for c in ax.collections if isinstance(c, ContourSet) and not c.filled and c.get_linestyle()[0][1]
    ]  # the dotted one
    assert min(cut.get_linewidths()) >= 2.5  # bold: followed across the map (r15c found it faint at 1.5)
    assert [t.xy for t in ax.texts] == [tuple(n) for n in nodes[~nodes_valid]]  # each "in collision" label
    # r39c: where the node is, exactly, in its label; r40c: no cross-hair in the square, which read as edges reaching it
    assert [t.get_text() for t in ax.texts] == ["in collision\n(15.0, 8.0)", "in collision\n(12.0, 6.0)"]
    assert squares.get_markerfacecolor() != "none" and "_hair" not in [line.get_label() for line in ax.get_lines()]
    assert ax.figure.axes[1].get_ylabel() == "P(valid); the line: threshold 0.50"  # r40c: the value, as the maps'
    # r41c: the label's leader line, dashed vermillion unlike an edge's ink, stops short of the square it names
    leader = ax.texts[0].arrow_patch
    assert to_hex(leader.get_edgecolor()) == COLORS["dangerous"] and leader.get_linestyle() == "--"
    assert leader.shrinkB > 0


def test_path_maps_in_collision_label_lies_on_free_cells_not_over_the_block():
    """Reader r39c: the label of a node just inside a block's top edge sat inside the block, hiding its hatching."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[8.0, 8.0], [24.0, 20.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))
    node = np.array([[16.0, 19.5]])  # just inside the block's top edge: below it, the label would lie on the block
    fig = pc.path_map(
        np.full(fine.shape, 0.4),
        valid,
        fine,
        threshold=0.5,
        path=np.array([[2.0, 2.0], [28.0, 28.0]]),
        nodes=node,
        nodes_valid=np.array([False]),
    )
    ax = fig.axes[0]
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    (label,) = [t for t in ax.texts if t.get_text().startswith("in collision")]
    box = label.get_bbox_patch().get_window_extent(renderer).transformed(ax.transData.inverted())  # data units
    corners = np.array([[box.x0, box.y0], [box.x0, box.y1], [box.x1, box.y0], [box.x1, box.y1]])
    assert exact_checker(ws, robots.point_robot()).are_valid(corners).all()


def test_conservative_circles_leave_the_grey_of_p_valid_to_read_and_show_on_every_grey():
    """Review r18b: where the `paper` model rejects most of the free space, a hatch of dots over it hid the grey the
    text asks the reader to read. Marked with sparse circles, a map whose every cell is a conservative mistake keeps
    most of its area bare; each circle is ringed ink, then white (on any grey one of the two stands 3:1 apart), and the
    threshold's dotted contour bounds the region the circles mark."""
    fine = slices.slice_grid(robots.point_robot(), n=100)
    valid = np.ones(fine.shape, dtype=bool)
    probability = np.tile(np.linspace(0.0, 0.4, 100)[:, None], (1, 100))  # below the threshold everywhere: all rejected
    probability[-10:] = 0.9  # but a band on the right, kept: the threshold's contour runs between
    fig = pc.probability_map(probability, valid, fine, threshold=0.5)
    ax = fig.axes[0]
    (circles,) = cell_marks.cell_marks(ax)[:1]
    assert circles.get_label() == "valid rejected" and circles.get_paths()[0] is not None
    box = ax.get_window_extent()  # pixels
    outer = np.sqrt(circles.get_sizes()[0]) + 2 * (pc.MARK_RING + 3.2) / 2  # points: the circle and its rings
    covered = len(circles.get_offsets()) * np.pi / 4 * (outer * fig.dpi / 72) ** 2
    assert covered < 0.25 * box.width * box.height  # three quarters of the map's grey, bare
    rings = [e._gc["foreground"] for e in circles.get_path_effects() if "foreground" in getattr(e, "_gc", {})]
    assert [to_hex(r) for r in rings] == [COLORS["free"], COLORS["ink"]]  # the white ring outside, then the ink one
    for level in np.linspace(0, 1, 101):  # every grey of the map
        grey = to_hex((level, level, level))
        assert max(contrast("ink", grey), contrast("free", grey)) >= 3.0
    (cut,) = [
        c for c in ax.collections if isinstance(c, ContourSet) and not c.filled and c.get_linestyle()[0][1]
    ]  # the dotted one
    x = np.concatenate([p.vertices for p in cut.get_paths()])[:, 0]
    assert np.allclose(x, x.mean(), atol=fine.axes[0][1] - fine.axes[0][0])  # between the rejected and the kept band


def test_threshold_views_count_bars_are_the_counts_and_keep_them_inside_the_frame(grid, probability, valid):
    """The counts panel: a bar per kind of answer, its height the count (the dangerous one in its own colour, last),
    each count written below the frame's top edge."""
    predicted = probability >= 0.5
    fig = pc.threshold_view(probability, valid, grid, threshold=0.5)
    ax_counts = fig.axes[1]  # the map, the counts, the ROC
    expected = list(confusion_counts(predicted, valid).values())
    assert [bar.get_height() for bar in ax_counts.patches] == expected and sum(expected) == valid.size
    assert ax_counts.patches[3].get_facecolor()[:3] == to_rgba(COLORS["dangerous"])[:3]
    names = [t.get_text() for t in ax_counts.get_xticklabels()]  # r39c: the bars named as section 1's table names them
    assert names[1] == "conservative\nmistake" and names[3] == "dangerous\nmistake"
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    frame = ax_counts.get_window_extent(renderer)
    assert all(frame.y1 - t.get_window_extent(renderer).y1 >= 2 for t in ax_counts.texts)


def test_metrics_bars_one_group_per_model():
    scores = {"paper": {"acc": 0.57, "tpr": 0.29, "tnr": 0.85}, "always valid": {"acc": 0.85, "tpr": 1.0, "tnr": 0.0}}
    ax = pc.metrics_bars(scores).axes[0]
    # reader r30c: each group's balanced accuracy printed under it; r41c: no dashed line at it through the bars' values
    assert [t.get_text() for t in ax.get_xticklabels()] == ["paper\nbal. acc. 0.57", "always valid\nbal. acc. 0.50"]
    offset = {(round(t.xy[0]), t.xy[1]): t.xyann[1] for t in ax.texts}  # (group, the bar's top): points above it
    assert offset[0, 0.57] <= 2 and offset[1, 0.85] <= 2  # each value on its bar's top
    assert not ax.collections and not ax.lines  # the balanced accuracy is read under each group, nothing drawn across
    heights = [bar.get_height() for bar in ax.patches]  # drawn measure by measure: acc of each, then tpr, then tnr
    assert heights == [0.57, 0.85, 0.29, 1.0, 0.85, 0.0]
    from matplotlib.colors import to_hex

    from toolkit.plots.palette import COLORS

    shades = [to_hex(bar.get_facecolor()) for bar in ax.patches]  # reader r47c: TNR in the maps' conservative sky blue
    assert COLORS["conservative"] not in shades and COLORS["dangerous"] not in shades and len(set(shades)) == 3


def test_maps_refuse_arrays_of_another_shape(grid, probability, valid):
    with pytest.raises(ValueError, match="grid"):
        pc.probability_map(probability[:-1], valid, grid)
    with pytest.raises(ValueError):
        pc.threshold_view(probability, valid.T[:, :-1], grid, threshold=0.5)


def test_figures_are_never_pyplot_figures(grid, probability, valid):
    import matplotlib.pyplot as plt

    before = plt.get_fignums()
    pc.threshold_view(probability, valid, grid, threshold=0.5)
    assert plt.get_fignums() == before


def test_path_map_marks_start_and_goal_whole_on_the_maps_edge(grid, probability, valid):
    path = np.array([[grid.lower[0], 2.0], [5.0, 3.0], [grid.upper[0], 28.0]])  # from the left edge to the right
    fig = pc.path_map(probability, valid, grid, threshold=0.5, path=path, nodes=path, nodes_valid=np.ones(3, bool))
    ax = fig.axes[0]
    ends = {line.get_label(): line for line in ax.get_lines() if line.get_label() in ("start", "goal")}
    assert [tuple(np.ravel(ends[n].get_xydata())) for n in ("start", "goal")] == [tuple(path[0]), tuple(path[-1])]
    drawn = [*ends.values(), next(line for line in ax.get_lines() if line.get_marker() == "D")]
    assert not any(line.get_clip_on() for line in drawn)  # an end's marker drawn whole, not cut by the frame
    # reader r10b saw the start square cut at the frame: its white edge vanished on the white beyond it, and the path's
    # diamond peeked out from under it. Each end: a white edge, then a black ring (its shape shows on any side of the
    # frame); the path's diamonds lie between the ends only
    for end in ends.values():
        assert end.get_markeredgecolor() == COLORS["free"]
        (ring,) = [e for e in end.get_path_effects() if hasattr(e, "_gc")]
        assert to_rgba(ring._gc["foreground"]) == to_rgba(COLORS["ink"])
    assert drawn[-1].get_markevery() == [1]
    assert {"start", "goal"} <= {t.get_text() for t in fig.legends[0].get_texts()}


def test_path_map_leaves_out_a_diamond_that_would_touch_an_end(grid, probability, valid):
    """Reader r20b: the path's second configuration, 1.6 of 30 above the start at the map's edge, sat its diamond on
    the start square. A configuration within END_CLEAR of the map's width of an end has no diamond; the rest do."""
    start = np.array([30.2, 24.2])
    path = np.array([start, start + [0.0, 1.6], [20.0, 27.0], [12.0, 14.0], [10.5, 10.2], [9.0, 9.0]])  # (6, 2)
    ax = pc.path_map(probability, valid, grid, threshold=0.5, path=path, nodes=path, nodes_valid=np.ones(6, bool)).axes[
        0
    ]
    (line,) = [line for line in ax.get_lines() if line.get_marker() == "D"]
    assert line.get_markevery() == [2, 3]  # not 1 (beside the start) nor 4 (beside the goal)
    np.testing.assert_array_equal(line.get_xydata(), path)  # the dashed line passes through every one


def test_an_angle_swept_on_a_map_is_labelled_in_radians(grid, probability, valid):
    angles = slices.CSpaceSlice((2, 6), ("yaw", "joint1"), grid.axes, grid.lower, grid.upper, grid.configs)
    ax = pc.probability_map(probability, valid, angles).axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("yaw (rad)", "joint1 (rad)")
    ax = pc.probability_map(probability, valid, grid).axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x", "y")  # a position: the workspace's units, as the axes say


def test_the_threshold_sweeps_legend_lies_below_its_curves(probability, valid):
    from toolkit.plots.reproduction import threshold_sweep

    fig = threshold_sweep(probability, valid, 0.5)
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    (legend,) = fig.legends
    assert legend.get_window_extent(renderer).y1 <= fig.axes[0].get_window_extent(renderer).y0  # over no curve
    # reader r30c: TPR was a vermillion line of squares, chapter 03's mark of "invalid kept"; no curve is now
    assert not any(
        to_hex(line.get_color()) == COLORS["dangerous"] or line.get_marker() == "s" for line in fig.axes[0].get_lines()
    )


def test_the_outline_runs_on_the_cells_edges_so_a_corner_cells_mark_lies_inside_it():
    """Reader r27c, chapter 03's `strong` maps: the outline, a contour through the cells' centres, rounded off a block's
    corner cells, and a dangerous square on one seemed to lie in free space. It runs on the cells' edges now: every
    obstacle cell's centre, the corners' included, lies inside it, every free cell's outside."""
    fine = slices.slice_grid(robots.point_robot(), n=31)
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    valid = fine.image(exact_checker(ws, robots.point_robot()).are_valid(fine.configs))  # (31, 31)
    ax = pc.probability_map(np.where(valid, 0.9, 0.1), valid, fine, threshold=0.5).axes[0]
    (path,) = [p for p in boundary_of(ax).get_paths() if len(p.vertices)]
    centres = np.stack(np.meshgrid(*fine.axes, indexing="ij"), axis=-1).reshape(-1, 2)  # (31 * 31, 2)
    np.testing.assert_array_equal(path.contains_points(centres), ~valid.ravel())
