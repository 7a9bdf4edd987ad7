"""The CAE figures (notebook 02) show the numbers they are given: curves, error cells, accuracies, points."""

import re

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_rgb
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from toolkit.learning.metrics import reconstruction_accuracy
from toolkit.plots import alt, latent
from toolkit.plots import cae as plots
from toolkit.plots.palette import COLORS, series_style
from toolkit.plots.wrong_cells import error_cells


@pytest.fixture
def grids_and_decoded(rng):
    """Two 6x5 grids of -1 / +1 and decoder outputs that get some cells wrong (one decodes exactly 0)."""
    grids = np.where(rng.random((2, 6, 5)) < 0.3, 1.0, -1.0)
    decoded = grids * rng.uniform(0.2, 1.0, grids.shape)
    flip = rng.random(grids.shape) < 0.15
    decoded[flip] *= -1
    decoded[1, 0, 0] = 0.0  # neither sign: wrong, as reconstruction_accuracy counts it
    return grids, decoded


def test_training_curves_plot_each_history_per_epoch():
    histories = {"lambda = 0": [5.0, 3.0, 2.5], "lambda = 1e-3": [6.0, 2.0, 1.0, 0.5]}
    fig = plots.training_curves(histories)
    assert isinstance(fig, Figure)
    ax = fig.axes[0]
    assert [line.get_label() for line in ax.get_lines()] == list(histories)
    for line, history in zip(ax.get_lines(), histories.values()):
        np.testing.assert_array_equal(line.get_xdata(), np.arange(1, len(history) + 1))
        np.testing.assert_array_equal(line.get_ydata(), history)
    assert ax.get_yscale() == "log" and ax.get_xlabel() == "epoch"


def test_training_curves_tick_the_log_axis_above_the_highest_start():
    """Reader r36b: λ = 0.961 starts at 3,830, and the axis had no tick above 2,000; ticks at 1, 2 and 4 of each
    power of ten put one at 4,000."""
    ax = plots.training_curves({"lambda 0.961": list(np.geomspace(3830.0, 40.0, 50))}).axes[0]
    low, high = ax.get_ylim()
    ticks = [t for t in ax.yaxis.get_majorticklocs() if low <= t <= high]
    assert 4000 in ticks and 2000 in ticks and max(ticks) == 4000
    assert high >= 1.2 * 3830 and low <= 40 / 1.2  # reader r41b: the first point sat clipped on the top frame


def test_error_cells_are_the_cells_whose_sign_differs(grids_and_decoded):
    grids, decoded = grids_and_decoded
    errors = error_cells(grids, decoded)
    assert errors[1, 0, 0]  # a zero output is an error
    np.testing.assert_allclose(1 - errors.reshape(2, -1).mean(axis=1), reconstruction_accuracy(decoded, grids))


def test_reconstructions_mark_exactly_the_error_cells_and_title_accuracy_vs_all_free(grids_and_decoded):
    grids, decoded = grids_and_decoded
    fig = plots.reconstructions(grids, decoded, ["seen 0", "unseen 3"])
    _key, *rows = fig.subfigs  # the legend's strip, then one row per workspace
    assert len(rows) == 2
    accuracy = reconstruction_accuracy(decoded, grids)
    for row, grid, out, acc, name in zip(rows, grids, decoded, accuracy, ["seen 0", "unseen 3"]):
        inputs, signs, errors = row.axes
        np.testing.assert_array_equal(inputs.images[0].get_array(), grid.T)
        np.testing.assert_array_equal(signs.images[0].get_array(), np.where(out > 0, 1.0, -1.0).T)
        marked = errors.images[-1].get_array()
        wrong = np.sign(out) != grid
        np.testing.assert_array_equal(~np.ma.getmaskarray(marked), wrong.T)  # marked cells = sign(decoded) != input
        np.testing.assert_array_equal(marked.compressed(), grid.T[wrong.T])  # red (+1) missed, blue (-1) invented
        title = row.get_suptitle()
        assert title.startswith(name) and f"{acc:.1%}" in title and f"all free: {np.mean(grid < 0):.1%}" in title
        assert f"{int(np.sum(wrong & (grid > 0)))} missed" in errors.get_title()
        assert f"{int(np.sum(wrong & (grid < 0)))} invented" in errors.get_title()


def test_reconstructions_mark_flipped_cells_as_their_own_kind_not_as_missed_or_invented():
    clean = -np.ones((1, 6, 5))  # an all-free grid with one block cell at (0, 0)
    clean[0, 0, 0] = 1.0
    noisy = clean.copy()
    noisy[0, 2, 2] = noisy[0, 4, 1] = 1.0  # two cells flipped to occupied
    flipped = noisy != clean
    decoded = clean.copy()  # the decoder ignores the flip at (2, 2), copies the one at (4, 1) ...
    decoded[0, 4, 1] = 1.0
    decoded[0, 0, 0] = -1.0  # ... and misses the real block: one other cell wrong
    fig = plots.reconstructions(noisy, decoded, ["w"], flipped=flipped)
    errors = fig.subfigs[1].axes[2]
    assert errors.get_title() == "1 of 2 flips ignored; other cells: 1 missed (x), 0 invented (o)"  # r37b: a key
    # r29b: scored against the clean grid, an ignored flip is right: 2 cells of 30 differ (the copied flip, the block)
    assert fig.subfigs[1].get_suptitle() == "w: 93.3% of cells as in the clean grid (all free: 96.7%)"
    others, ignored = errors.images[1].get_array(), errors.images[2].get_array()
    assert [tuple(c) for c in np.argwhere(~np.ma.getmaskarray(others).T)] == [(0, 0)]  # the missed block only
    assert [tuple(c) for c in np.argwhere(~np.ma.getmaskarray(ignored).T)] == [(2, 2)]  # the ignored flip
    marks = sorted((line.get_marker(), *xy) for line in errors.get_lines() for xy in line.get_xydata().tolist())
    assert marks == [("s", 2, 2), ("s", 4, 1), ("x", 0, 0)]  # both flips squared, the missed block crossed
    labels = [t.get_text() for t in fig.subfigs[0].legends[0].get_texts()]
    assert labels == [
        "missed cell (x)",
        "invented cell (o)",
        "flipped cell, flip ignored (square on green)",
        "flipped cell, flip copied (square)",
        "occupied in the input (faded)",  # reader r31b: a seen grid's all-grey panel read as empty
    ]


def test_a_reconstructions_regions_count_flips_as_its_title_does():
    """Review r14c: with flipped cells, the title said "3 missed, 0 invented" while the regions of its description
    summed to 25 and 8: they counted every ignored flip as missed or invented. The regions now sum to the title."""
    rng = np.random.default_rng(4)
    clean = np.where(rng.random((1, 12, 12)) < 0.3, 1.0, -1.0)  # (1, 12, 12)
    flipped = np.zeros_like(clean, dtype=bool)
    flipped[0].flat[rng.choice(144, 20, replace=False)] = True  # 20 flips
    noisy = np.where(flipped, -clean, clean)
    decoded = clean * np.where(rng.random(clean.shape) < 0.1, -1.0, 1.0)  # mostly the clean grid: flips ignored
    fig = plots.reconstructions(noisy, decoded, ["w"], flipped=flipped)
    title = fig.subfigs[1].axes[2].get_title()
    said = [
        int(v)
        for v in re.fullmatch(
            r"(\d+) of (\d+) flips ignored; other cells: (\d+) missed \(x\), (\d+) invented \(o\)", title
        ).groups()
    ]
    (part,) = alt.details(fig)
    cells = [cell for row in part["rows"] for cell in row[1:]]
    pattern = r".*; (\d+) of (\d+) flips ignored; other cells: (\d+) missed, (\d+) invented"
    summed = np.sum([[int(v) for v in re.fullmatch(pattern, cell).groups()] for cell in cells], axis=0).tolist()
    wrong = (np.sign(decoded) != noisy)[0]
    expected = [
        int((wrong & flipped[0]).sum()),
        20,
        int((wrong & ~flipped[0] & (noisy[0] > 0)).sum()),
        int((wrong & ~flipped[0] & (noisy[0] < 0)).sum()),
    ]
    assert summed == said == expected and expected[0] > 0 and sum(expected[2:]) > 0


def test_reconstructions_refuse_mismatched_inputs(grids_and_decoded):
    grids, decoded = grids_and_decoded
    with pytest.raises(ValueError):
        plots.reconstructions(grids, decoded[:1], ["a", "b"])
    with pytest.raises(ValueError):
        plots.reconstructions(grids, decoded, ["only one name"])


def test_accuracy_vs_all_free_has_one_point_per_workspace_and_the_diagonal():
    groups = {
        "seen": (np.array([0.88, 0.9, 0.85]), np.array([1.0, 0.99, 1.0])),
        "unseen": (np.array([0.87, 0.91]), np.array([0.86, 0.9])),
    }
    fig = plots.accuracy_vs_all_free(groups)
    ax = fig.axes[0]
    points = [c for c in ax.collections if not c.get_gid().endswith(": mean")]
    assert len(points) == 2
    for collection, (all_free, accuracy) in zip(points, groups.values()):
        np.testing.assert_allclose(collection.get_offsets(), np.column_stack([all_free, accuracy]))
    means = {c.get_gid(): c.get_offsets()[0] for c in ax.collections if c.get_gid().endswith(": mean")}
    assert means.keys() == {"seen: mean", "unseen: mean"}  # each group's mean drawn large, behind every point
    np.testing.assert_allclose(means["unseen: mean"], [0.89, 0.88])
    # reader r51b: as section 7's panels draw theirs; behind the points (r20b: a filled mean on top hid points at
    # 1.00), so none hides under it; reader r54b: hollow, in the group's colour, so a point under it shows
    filled = [c for c in ax.collections if c.get_gid().endswith(": mean")]
    assert all(len(c.get_facecolor()) == 0 or np.all(c.get_facecolor()[:, 3] == 0) for c in filled)
    for k, mean in enumerate(filled):
        assert np.allclose(mean.get_edgecolor()[0, :3], to_rgb(series_style(k)["color"]))
    (diagonal,) = ax.get_lines()  # reader r51b: no dashed lines from the means, read as a second diagonal
    np.testing.assert_allclose(diagonal.get_xdata(), diagonal.get_ydata())
    (legend,) = fig.legends  # below the axes, over no point
    assert "99.7%" in legend.get_texts()[0].get_text()  # the seen group's mean accuracy
    assert points[0].get_zorder() > points[1].get_zorder()  # the smaller group drawn on top
    assert max(m.get_zorder() for m in filled) < min(p.get_zorder() for p in points)  # r27b: a mean hid a grid
    assert (
        legend.get_texts()[-1].get_text()
        == "thin cross-hair, open at its centre, in the group's colour: the group's mean"
    )
    assert legend.get_texts()[0].get_text() == "seen: mean 99.7% vs 87.7%"  # r27b: once "seen (trained on) (mean"


def test_contraction_shows_each_models_norms_and_mean_responses():
    flips = np.array([1, 3, 10])
    norms = {"lambda = 0": np.array([2.0, 3.0, 4.0]), "lambda = 1 (strong)": np.array([0.5, 0.7, 0.6])}
    shift = {"lambda = 0": np.array([[0.1, 0.3], [0.2, 0.4], [0.5, 0.7]]), "lambda = 1 (strong)": np.full((3, 2), 0.05)}
    change = {"lambda = 0": np.array([[1, 1], [3, 2], [9, 11]]), "lambda = 1 (strong)": np.zeros((3, 2))}
    fig = plots.contraction(norms, flips=flips, latent_shift=shift, decoded_change=change)
    ax_j, ax_z, ax_x = fig.axes
    assert [t.get_text().replace("\n", " ") for t in ax_j.get_xticklabels()] == list(norms)
    medians = [
        line.get_ydata()[0]
        for line in ax_j.get_lines()
        if line.get_xdata().size == 2 and line.get_ydata()[0] == line.get_ydata()[1]
    ]
    assert 3.0 in medians and 0.6 in medians  # each box's median
    for ax, data in ((ax_z, shift), (ax_x, change)):
        lines = {line.get_label(): line for line in ax.get_lines()}
        for name, values in data.items():
            np.testing.assert_array_equal(lines[name].get_xdata(), flips)
            np.testing.assert_allclose(lines[name].get_ydata(), values.mean(axis=1))
    np.testing.assert_array_equal({l.get_label(): l for l in ax_x.get_lines()}["as many as flipped"].get_ydata(), flips)


def pixels_of(fig, ax, color: str, tolerance: float = 0.08) -> int:
    """How many pixels of ``ax``, as ``fig`` renders, are within ``tolerance`` (per channel, 0-1) of ``color``."""
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    image = np.asarray(canvas.buffer_rgba())[..., :3] / 255  # (H, W, 3), the top row first
    box = ax.get_window_extent()
    height = image.shape[0]
    inside = image[int(height - box.y1) : int(height - box.y0), int(box.x0) : int(box.x1)]
    return int(np.sum(np.all(np.abs(inside - to_rgb(color)) < tolerance, axis=-1)))


def test_contraction_shows_a_line_that_another_covers_exactly():
    """Reader r8b: the lambda = 0 line lay under lambda = 1e-3, hidden. The first line is drawn wider, under the later
    ones: where two models respond alike, the first still shows at the second's edges."""
    flips = np.array([1, 3, 10, 30])
    same = np.array([[0.01], [0.03], [0.1], [0.3]])  # (F, 1): one trial
    names = ["lambda = 0", "lambda = 1e-3"]
    fig = plots.contraction(
        {n: np.array([1.0, 2.0, 3.0]) for n in names},
        flips=flips,
        latent_shift=dict.fromkeys(names, same),
        decoded_change=dict.fromkeys(names, same * 100),
        series=(4, 1),
    )
    ax_j, ax_z, ax_x = fig.axes
    first, second = (series_style(k)["color"] for k in (4, 1))
    for ax in (ax_z, ax_x):
        under, over = (line for line in ax.get_lines() if line.get_label() in names)
        assert under.get_linewidth() > over.get_linewidth() + 2
        assert (under.get_color(), over.get_color()) == (first, second)  # the series asked for
        assert under.get_linestyle() != over.get_linestyle()  # told apart without colour
        assert under.get_zorder() < over.get_zorder()
        assert pixels_of(fig, ax, first) > 0.5 * pixels_of(fig, ax, second) > 0  # the line beneath shows
    (legend,) = [ax_j.get_legend()]  # the box plot's marks named: the star is the mean
    named = dict(zip([t.get_text() for t in legend.get_texts()], legend.legend_handles))
    assert named["mean"].get_marker() == "*" and "median" in named
    # reader r50b: markers stand for groups of grids on the page, so the models' lines have none; and no box mark
    # is a circle or triangle (reader r48b: the mean was a triangle)
    models = {line.get_marker() for ax in (ax_z, ax_x) for line in ax.get_lines() if line.get_label() in names}
    assert models <= {"", "None", None}
    assert not {named[mark].get_marker() for mark in named if mark != "median"} & {"o", "^", "s"}


def test_latent_scatter_has_one_point_per_workspace_at_its_coordinates(rng):
    points = {"seen": rng.normal(size=(30, 2)), "generated": rng.normal(size=(200, 2))}
    fig = latent.latent_scatter(points)
    assert len(fig.axes) == 2  # one panel a group, the others grey behind it: one cloud or two, read by eye
    for ax, (name, xy), other in zip(fig.axes, points.items(), ("generated", "seen")):
        rest, own = ax.collections
        np.testing.assert_allclose(own.get_offsets(), xy)
        np.testing.assert_allclose(rest.get_offsets(), points[other])
        assert own.get_label() == f"{name} ({len(xy)})"
        few = len(points[other]) <= plots.FEW  # a few dozen grey points on top, larger, not buried (reader r13b)
        assert (rest.get_zorder() > own.get_zorder()) == few and (rest.get_sizes()[0] > own.get_sizes()[0]) == few
        assert ax.get_xlim() == fig.axes[0].get_xlim() and ax.get_ylim() == fig.axes[0].get_ylim()  # shared axes
    assert (fig.axes[0].get_xlabel(), fig.axes[0].get_ylabel()) == ("PC 1", "PC 2")


def test_latent_scatter_colors_each_workspace_by_its_value(rng):
    points = {"seen": rng.normal(size=(5, 2)), "unseen": rng.normal(size=(7, 2))}
    occupied = {"seen": rng.uniform(0.05, 0.2, 5), "unseen": rng.uniform(0.1, 0.3, 7)}
    fig = latent.latent_scatter(points, color=occupied, color_label="occupied share", highlight="seen")
    *panels, bar = fig.axes
    owns = [ax.collections[-1] for ax in panels]
    assert owns[0].get_sizes()[0] > owns[1].get_sizes()[0]  # the highlighted group stands out
    for collection, name in zip(owns, points):
        np.testing.assert_allclose(collection.get_offsets(), points[name])
        np.testing.assert_allclose(collection.get_array(), occupied[name])
        assert collection.get_clim() == (
            min(occupied["seen"].min(), occupied["unseen"].min()),
            max(occupied["seen"].max(), occupied["unseen"].max()),
        )
    assert bar.get_ylabel() == "occupied share"
    # reader r40b: chapter 02's two maps, each a figure of its own, on one colour scale when given one
    fig = latent.latent_scatter(points, color=occupied, color_range=(0.0, 0.5))
    assert {ax.collections[-1].get_clim() for ax in fig.axes[:-1]} == {(0.0, 0.5)}


def test_the_boxes_long_names_wrap_apart():
    """Chapter 02's three models side by side under their boxes: each name wrapped at its spaces so that no two tick
    labels touch (once '(paper)(mean reading)' ran together), each line whole words, at 8 points or more; models all
    named by λ ticked by their λ alone, under the axis name "λ" (reader r31b: a name wrapped to four lines)."""
    names = ["λ = 0", "λ = 1e-3, CAE-long", "λ = 0.961 (mean reading)"]
    norms = {n: np.array([2.9, 3.0, 3.2]) for n in names}
    responses = {n: np.ones((2, 3)) for n in names}
    fig = plots.contraction(norms, flips=np.array([1, 30]), latent_shift=responses, decoded_change=responses)
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    labels = fig.axes[0].get_xticklabels()
    assert [t.get_text().replace("\n", " ") for t in labels] == ["0", "1e-3, CAE-long", "0.961"]
    assert fig.axes[0].get_xlabel() == "λ" and max(t.get_text().count("\n") for t in labels) <= 1
    boxes = [t.get_window_extent(renderer) for t in labels]
    assert all(left.x1 + 2 < right.x0 for left, right in zip(boxes, boxes[1:]))  # pixels apart
    assert min(t.get_fontsize() for t in labels) >= 8


def test_a_training_curve_under_another_stays_visible():
    """Two histories that coincide: the one drawn first is wider, and their markers fall on different epochs."""
    same = list(np.linspace(5.0, 1.0, 40))
    ax = plots.training_curves({"lambda 0": same, "lambda 1e-3": same}).axes[0]
    under, over = ax.get_lines()
    assert under.get_linewidth() >= over.get_linewidth() + 2 and over.get_zorder() > under.get_zorder()
    marked = [set(np.arange(40)[line.get_markevery()[0] :: line.get_markevery()[1]]) for line in (under, over)]
    assert marked[0] and marked[1] and not marked[0] & marked[1]


def test_training_curves_in_panels_give_each_line_its_own_on_one_y_axis():
    """Reader r39b: λ = 0 hid under λ = 1e-3 on one axes; a panel each, one y axis, the name above its panel."""
    same = list(np.linspace(5.0, 1.0, 40))
    fig = plots.training_curves({"lambda 0": same, "lambda 1e-3": same, "lambda 0.961": [9.0] * 40}, panels=True)
    assert [len(ax.get_lines()) for ax in fig.axes] == [1, 1, 1]
    # reader r50b: no markers (they stand for groups of grids on the page): each line its colour and line style
    lines = [ax.get_lines()[0] for ax in fig.axes]
    assert {line.get_marker() for line in lines} <= {"", "None", None}
    assert len({line.get_color() for line in lines}) == len({line.get_linestyle() for line in lines}) == 3
    assert fig.axes[0].get_lines()[0].get_color() == series_style(0)["color"]
    coloured = plots.training_curves({"a": same, "b": same}, panels=True, series=(4, 1))
    assert [ax.get_lines()[0].get_color() for ax in coloured.axes] == [series_style(k)["color"] for k in (4, 1)]
    assert [ax.get_title() for ax in fig.axes] == ["lambda 0", "lambda 1e-3", "lambda 0.961"]
    assert len({ax.get_ylim() for ax in fig.axes}) == 1 and fig.axes[0].get_ylabel().startswith("loss of Eq. (1)")
    assert all(ax.get_yscale() == "log" and ax.get_xlabel() == "epoch" for ax in fig.axes)
    parts = alt.details(fig)  # several panels: each line in words and as a table, never the guard's from titles
    assert [p["name"] for p in parts] == ["lambda 0", "lambda 1e-3", "lambda 0.961"]
    assert parts[0]["rows"][0] == ["1", "5"] and parts[2]["rows"][-1] == ["40", "9"]


def test_reconstructions_wrong_cells_carry_marks_one_can_read_at_the_sites_width():
    """31 x 31 grids as chapter 02 draws them: x and o at least 5 px across where the site shows the figure (the
    figure is no wider than the page), rings not dots, in the legend too."""
    rng = np.random.default_rng(0)
    grids = np.where(rng.random((2, 31, 31)) < 0.3, 1.0, -1.0)
    decoded = grids * np.where(rng.random(grids.shape) < 0.05, -1.0, 1.0)
    fig = plots.reconstructions(grids, decoded, ["seen", "unseen"])
    assert fig.get_figwidth() <= plots.PAGE_WIDTH
    for row in fig.subfigs[1:]:  # the first, the legend's strip
        marks = row.axes[2].get_lines()
        assert {m.get_marker() for m in marks} == {"x", "o"}
        assert all(m.get_markersize() * 100 / 72 >= 5 and m.get_fillstyle() == "none" for m in marks)  # px at 100 dpi
    (legend,) = fig.subfigs[0].legends
    shown = [m for m in legend.findobj(Line2D) if m.get_marker() in ("x", "o")]  # what the legend draws
    assert sorted(m.get_marker() for m in shown) == ["o", "x"] and {m.get_fillstyle() for m in shown} == {"none"}
    # reader r50b: vermillion and blue are CAEs or groups of grids elsewhere on the page; the key says what they mean
    assert legend.get_title().get_text() == "the colours here: kinds of cell, not models or groups of grids"
    fig.canvas.draw()  # r27b: the legend above the first grid, not a screen below it under the last
    first = fig.subfigs[1]._suptitle.get_window_extent()  # the first workspace's title
    assert legend.get_window_extent().y0 >= first.y1 and not fig.legends


def test_a_count_axis_has_a_tick_below_its_lowest_count_and_at_the_copy_lines_end():
    """Review r26b: a mean of 0.61 decoded cells sat below the lowest tick (1); the copy line's end (30) had none."""
    assert plots._count_ticks(0.61, 30.0, end=30) == [0, 1, 2, 5, 10, 30]
    assert plots._count_ticks(1.0, 120.0, end=30) == [1, 2, 5, 10, 30, 100]


def test_contraction_reads_one_flip_as_well_as_thirty_and_its_legend_covers_no_curve():
    """Reader r10b: the reconstruction panel ran to 30 on a linear axis, the values at 1 flip squashed at its foot;
    r11b: the latent panel's legend lay on its curves. Both counts are on log scales (a linear stretch from 0 to 1
    below, so that a change of 0 cells still shows), ticked in plain numbers at the flips measured; one legend, above
    the panels (reader r31b: under them it lay a screen below the top right one), names the lines."""
    flips = np.array([1, 2, 3, 5, 10, 20, 30])
    names = ["lambda = 0", "lambda = 1"]
    change = {names[0]: np.array([[1.1], [1.5], [1.9], [2.4], [3.2], [4.4], [9.6]]), names[1]: np.zeros((7, 1))}
    fig = plots.contraction(
        {n: np.array([1.0, 2.0]) for n in names},
        flips=flips,
        latent_shift=dict.fromkeys(names, np.linspace(0.02, 0.14, 7)[:, None]),
        decoded_change=change,
    )
    ax_j, ax_z, ax_x = fig.axes
    assert ax_x.get_yscale() == ax_x.get_xscale() == ax_z.get_xscale() == "symlog"
    assert [t.get_text() for t in ax_x.get_xticklabels()] == ["1", "2", "3", "5", "10", "20", "30"]
    # r26b: the copy line's end, 30, is a tick (20 too close beside it)
    assert [t.get_text() for t in ax_x.get_yticklabels()] == ["0", "1", "2", "5", "10", "30"]
    low, high = ax_x.get_ylim()
    assert low < 0 and high > 30  # every count drawn, the copy line's 30 too
    to_px = ax_x.transData.transform
    one, two, thirty = (to_px((1, v))[1] for v in (1.1, 2.2, 30.0))  # a doubling near 1 as tall as one near 15
    assert two - one == pytest.approx(to_px((1, 30.0))[1] - to_px((1, 15.0))[1], rel=0.01) and thirty > two
    assert ax_z.get_legend() is None and ax_x.get_legend() is None
    (legend,) = [legend for part in fig.subfigs for legend in part.legends]
    assert [t.get_text() for t in legend.get_texts()] == [*names, "as many as flipped"]
    assert legend.get_title().get_text() == "the lines of the two panels below"  # r41b: not the boxes' key
    FigureCanvasAgg(fig).draw()
    box = legend.get_window_extent()
    assert all(box.y0 >= ax.get_window_extent().y1 for ax in (ax_z, ax_x))  # r31b: above the line panels, beside none
    assert box.y1 <= ax_j.get_window_extent().y0  # reader r33b: the boxes a row of their own above it


def test_large_groups_interleave_so_that_none_hides_under_another():
    """Reader r10b: chapter 02's 500 unseen workspaces (triangles) hid under the 500 training grids (squares) drawn over
    them. Large groups are drawn in turns, a slice of each at a time: every point once, each group's slices spread
    through the stack (one of each near the top), the small group of a few dozen still over them all."""
    rng = np.random.default_rng(0)
    groups = {
        name: (rng.uniform(0.8, 0.95, n), rng.uniform(0.8, 1.0, n))
        for name, n in (("seen", 30), ("training grids", 500), ("unseen", 500))
    }
    ax = plots.accuracy_vs_all_free(groups).axes[0]
    for name, (all_free, accuracy) in groups.items():
        drawn = [c for c in ax.collections if c.get_gid() == name]
        points = np.concatenate([c.get_offsets() for c in drawn])
        assert sorted(map(tuple, points)) == sorted(zip(all_free, accuracy))  # each workspace once
    stack = sorted((c for c in ax.collections if ": mean" not in c.get_gid()), key=lambda c: c.get_zorder())
    assert [c.get_gid() for c in stack[-3:]] == ["training grids", "unseen", "seen"]  # both large groups near the top
    order = [c.get_gid() for c in stack if c.get_gid() != "seen"]
    assert order[:4] == ["training grids", "unseen", "training grids", "unseen"]  # in turns
    assert len([c for c in stack if c.get_gid() == "seen"]) == 1


def test_large_groups_are_hollow_and_coinciding_means_nest():
    """Review r14c: chapter 02's 1000-grid clouds (training squares, unseen triangles) buried each other, and their two
    mean markers lay one over the other. Hundreds of points are outlines in their group's colour (a cloud under
    another shows through, told by its shape); a few dozen stay filled. Each later mean is smaller and on top."""
    rng = np.random.default_rng(1)
    groups = {
        name: (rng.uniform(0.85, 0.9, n), rng.uniform(0.9, 0.95, n))
        for name, n in (("few", 20), ("a", 300), ("b", 300))
    }
    groups["b"] = groups["a"]  # the same mean as "a"
    ax = plots.accuracy_vs_all_free(groups).axes[0]
    for k, name in enumerate(groups):
        drawn = [c for c in ax.collections if c.get_gid() == name]
        faces = np.concatenate([c.get_facecolor() for c in drawn])
        edges = np.concatenate([c.get_edgecolor() for c in drawn])
        if name == "few":
            assert np.all(faces[:, 3] > 0) and np.allclose(edges[:, :3], to_rgb(COLORS["ink"]))
            # reader r50b: a point on a mean's outline read as hidden in it; a white ring sets each point apart
            (ring, *_) = drawn[0].get_path_effects()
            assert all(c.get_zorder() > 3 for c in drawn) and to_rgb(ring._gc["foreground"]) == (1.0, 1.0, 1.0)
        else:
            assert faces.size == 0 or np.all(faces[:, 3] == 0)  # hollow
            assert np.allclose(edges[:, :3], to_rgb(series_style(k)["color"]))
    means = [next(c for c in ax.collections if c.get_gid() == f"{name}: mean") for name in groups]
    sizes, orders = [m.get_sizes()[0] for m in means], [m.get_zorder() for m in means]
    assert sizes == sorted(sizes, reverse=True) and len(set(sizes)) == 3 and orders == sorted(orders)
    assert sizes[-1] <= 0.6 * sizes[-2]  # the smaller square inside the larger: both edges show


def test_accuracy_panels_draw_each_group_alone_on_shared_axes():
    """Review r15c: in one axes the 1000-grid CAE's unseen workspaces (triangles) buried its training grids (squares),
    however layered. Each group has a panel of its own, every workspace once, on axes shared with the others, the
    diagonal and the group's mean in each."""
    from toolkit.plots.accuracy_panels import accuracy_panels

    rng = np.random.default_rng(2)
    groups = {name: (rng.uniform(0.7, 0.95, n), rng.uniform(0.7, 1.0, n)) for name, n in (("a", 30), ("b", 500))}
    fig = accuracy_panels(groups)
    assert len(fig.axes) == 2 and fig.axes[0].get_shared_y_axes().joined(*fig.axes)
    for ax, (name, (all_free, accuracy)) in zip(fig.axes, groups.items()):
        (points,) = [c for c in ax.collections if c.get_gid() == name]
        np.testing.assert_allclose(points.get_offsets(), np.column_stack([all_free, accuracy]))
        (mean,) = [c for c in ax.collections if c.get_gid() == f"{name}: mean"]
        np.testing.assert_allclose(mean.get_offsets()[0], [all_free.mean(), accuracy.mean()])
        (diagonal,) = ax.get_lines()
        np.testing.assert_allclose(diagonal.get_xdata(), diagonal.get_ydata())
        assert f"mean {accuracy.mean():.1%} vs {all_free.mean():.1%}" in ax.get_title()
    assert "b: 500 workspaces" in alt.alt_text(fig)


def test_accuracy_panels_of_three_groups_go_two_a_row_the_legend_in_the_spare_slot():
    """Reader r30b: three panels a row were 150 px wide at the site's width, 500 points one blob. Two a row, the
    points light enough to show where they crowd, the legend whole in the fourth slot."""
    from toolkit.plots.accuracy_panels import accuracy_panels

    rng = np.random.default_rng(3)
    groups = {name: (rng.uniform(0.7, 0.95, 50), rng.uniform(0.7, 1.0, 50)) for name in "abc"}
    fig = accuracy_panels(groups)
    drawn, spare = fig.axes[:3], fig.axes[3]
    assert len(fig.axes) == 4 and not spare.axison and spare.get_legend() is not None and not fig.legends
    assert drawn[0].get_position().y0 == drawn[1].get_position().y0 > drawn[2].get_position().y0  # two, then one
    for ax, name in zip(drawn, groups):
        (points,) = [c for c in ax.collections if c.get_gid() == name]
        assert points.get_alpha() <= 0.3
        (mean,) = [c for c in ax.collections if c.get_gid() == f"{name}: mean"]
        assert len(mean.get_facecolor()) == 0 or mean.get_facecolor()[0][3] == 0  # hollow, as cae.py's (r54b)
    said = " ".join(t.get_text() for t in spare.get_legend().get_texts()).replace("\n", " ")
    assert "thin cross-hair" in said and "mean" in said  # the legend says which (lead, wave 31 item 4)


def test_training_curves_keep_the_highest_point_clear_of_the_frame():
    """Reader r49b: at full size λ = 0.961's first point (3.83e3) touched the top frame, a 1.3x margin being few pixels
    on a log axis down to a loss of a few: its marker's centre now lies more than its size from the frame, as drawn."""
    histories = {
        "lambda 0": list(np.geomspace(2800.0, 2.0, 500)),  # 6 px from the frame with the 1.3x margin, 8 px a marker
        "lambda 0.961": [3830.0, *np.geomspace(3000, 1200, 499)],
    }
    fig = plots.training_curves(histories, panels=True)
    FigureCanvasAgg(fig).draw()
    ax = fig.axes[1]
    line = ax.get_lines()[0]
    top = ax.transData.transform((0, line.get_ydata()[0]))[1]
    frame = ax.transAxes.transform((0, 1))[1]
    assert frame - top > line.get_markersize() * fig.dpi / 72
