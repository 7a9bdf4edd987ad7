"""Every figure function of :mod:`toolkit.plots`, drawn once from small data, against what a reader who cannot see
colours, or cannot see at all, needs (WCAG 2.1 AA):

- 1.1.1: a text alternative said from the data, with numbers, in plain words (never the fallback read from titles);
- 1.4.1: no colour from outside the palette (matplotlib's default cycle caught too);
- readable: every text at 8 points or more, every axis that shows numbers named, no two texts over each other.

The gallery below calls every public function that returns a Figure; a test fails when a new one is not in it.
"""

from __future__ import annotations

import importlib
import inspect
import io
import itertools
import re
from typing import Any

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import Collection, PolyCollection
from matplotlib.colors import to_hex
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import Patch
from matplotlib.text import Text
from PIL import Image

from toolkit import plots, scenarios
from toolkit.geometry import meshes, robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace, from_mesh
from toolkit.planning.prm import PlanStep
from toolkit.plots import (
    accuracy_panels,
    alt,
    answer,
    cae,
    classifier,
    cspace,
    latent,
    near_blocks,
    palette,
    planning,
    query_ratios,
    race,
    reproduction,
    robot_drawing,
    scenes,
    slices,
    timings,
    tutorials,
    verdict,
)

crossover = importlib.import_module("toolkit.plots.crossover")  # the package exports its function by that name
MODULES = (
    accuracy_panels,
    answer,
    cae,
    classifier,
    crossover,
    cspace,
    latent,
    near_blocks,
    planning,
    query_ratios,
    race,
    reproduction,
    robot_drawing,
    scenes,
    timings,
    tutorials,
    verdict,
)
PALETTE = {to_hex(c) for c in [*palette.COLORS.values(), *palette.OKABE_ITO.values(), *palette.CATEGORICAL]}
PALETTE |= {to_hex(c) for c in palette.LINE_COLORS}
DEFAULT_CYCLE = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"}
MIN_POINTS = 8.0


def figure_functions() -> set[str]:
    """``module.name`` of every public function of the figure modules that returns a Figure."""
    return {
        f"{module.__name__.rsplit('.', 1)[1]}.{name}"
        for module in MODULES
        for name, function in inspect.getmembers(module, inspect.isfunction)
        if function.__module__ == module.__name__ and not name.startswith("_")
        if inspect.signature(function).return_annotation in ("Figure", Figure)
    }


def _point_world():
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]], [[3.0, 20.0], [9.0, 27.0]]]))
    return ws, exact_checker(ws, robots.point_robot())


def _step(stage: str, path) -> PlanStep:
    nodes = np.array([[1.0, 1.0], [29.0, 29.0], [25.0, 15.0], [15.0, 20.0], [15.0, 8.0]])
    return PlanStep(
        round=1,
        stage=stage,
        nodes=nodes,
        edges=np.array([[0, 4], [4, 2], [2, 1], [0, 3], [3, 1]]),
        node_verified=np.array([True, True, True, False, False]),
        new_nodes=np.array([3, 4]),
        path=np.array(path),
        removed_nodes=np.array([4]) if stage == "repair" else np.array([], dtype=int),
        removed_edges=np.array([0, 1]) if stage == "repair" else np.array([], dtype=int),
    )


PLANNING: dict[str, dict[str, dict[str, Any]]] = {
    s: {
        m: {
            "total_s_median": t,
            "total_s_per_query": [0.8 * t, t, 1.3 * t],
            "total_s_q1": 0.8 * t,
            "total_s_q3": 1.3 * t,
            "sampling_s_median": t / 3,
            "sampling_s_q1": t / 4,
            "sampling_s_q3": t / 2,
            "sampling_s_share": 0.3,
            "connection_s_share": 0.5,
            "query_s_share": 0.1,
        }
        for m, t in (("without", 0.2 + 0.05 * i), ("with", 0.15 + 0.08 * i))
    }
    for i, s in enumerate(("BS", "OB", "G", "BT"))
}


SLOW_QUERY = {
    s: {
        m: row | {"total_s_q3": 20 * row["total_s_median"]} if (s, m) == ("OB", "with") else row
        for m, row in modes.items()
    }
    for s, modes in PLANNING.items()
}  # a whisker cut at the top


def gallery() -> dict[str, Figure]:
    """One figure of every figure function, from small made-up or quickly computed data."""
    rng = np.random.default_rng(0)
    _, exact = _point_world()
    grids = np.where(rng.random((2, 12, 12)) < 0.3, 1.0, -1.0)
    decoded = grids * np.where(rng.random(grids.shape) < 0.1, -1.0, 1.0)
    grid = slices.slice_grid(robots.point_robot(), n=24)
    valid = grid.image(exact.are_valid(grid.configs))
    probability = np.clip(valid * 0.8 + 0.3 * rng.random(valid.shape) - 0.05, 0, 1)
    office = scenarios.get("3do").make_workspace(np.random.default_rng(1))
    chain = scenarios.get("3dc7")
    clutter = chain.make_workspace(np.random.default_rng(2))
    chain_exact = exact_checker(clutter, chain.robot)
    Q = chain.robot.sample(rng, 3)
    near = near_blocks.configuration_near_blocks(chain_exact, np.random.default_rng(0), n=500)  # valid; moved into
    touching = near_blocks.nudged_into_a_block(chain_exact, near)  # block: chapter 01's figure of one check
    path = chain.robot.interpolate(Q[0], Q[1], np.linspace(0, 1, 12))
    samples = {"BS": rng.uniform(0, 31, (30, 2)), "G": rng.uniform(0, 31, (20, 2))}
    S = rng.uniform(0, 31, (60, 2))
    sweep = {
        "label": "configurations per call",
        "values": [1, 10, 100, 1000],
        "exact_us": [1.0, 0.5, 0.4, 0.4],
        "fcl_us": [3.0, 3.0, 3.0, 3.0],
        "learned_us": [50.0, 5.0, 0.6, 0.1],
        "crossing": {"exact": {"value": 150.0, "learned_wins_above": True}, "fcl": None},
    }
    mesh_ws = from_mesh(
        meshes.mesh_of_boxes(np.array([[[1.0, 1.0, 0.0], [3.0, 2.0, 1.0]]])), lower=np.zeros(3), upper=np.full(3, 6.0)
    )
    return {
        "cae.training_curves": cae.training_curves({"lambda 0": [5.0, 3, 2, 1.5], "lambda 1e-3": [6.0, 2, 1, 0.5]}),
        "cae.reconstructions": cae.reconstructions(grids, decoded, ["seen 0", "unseen 1"]),
        "cae.accuracy_vs_all_free": cae.accuracy_vs_all_free(
            {"seen": (np.array([0.7, 0.8]), np.array([0.9, 0.85])), "unseen": (np.array([0.75]), np.array([0.7]))}
        ),
        "accuracy_panels.accuracy_panels": accuracy_panels.accuracy_panels(
            {  # three groups, as chapter 02 draws: two a row, the legend in the fourth slot (reader r30b)
                "30 grids: unseen": (np.array([0.7, 0.8]), np.array([0.9, 0.85])),
                "many": (np.array([0.75]), np.ones(1)),
                "many: training": (np.array([0.8]), np.array([0.9])),
            }
        ),
        "cae.contraction": cae.contraction(
            {"paper": rng.random(5), "strong": rng.random(5) * 2},
            flips=np.array([1, 5, 10]),
            latent_shift={"paper": rng.random((3, 4)), "strong": rng.random((3, 4))},
            decoded_change={"paper": rng.random((3, 4)) * 10, "strong": rng.random((3, 4)) * 10},
        ),
        "latent.latent_scatter": latent.latent_scatter(
            {"seen": rng.random((5, 2)), "unseen": rng.random((8, 2))},
            color={"seen": rng.random(5), "unseen": rng.random(8)},
            color_label="occupied share",
            highlight="seen",
        ),
        "classifier.probability_map": classifier.probability_map(probability, valid, grid, threshold=0.5),
        "classifier.probability_maps": classifier.probability_maps(
            {"paper": probability, "strong": probability**2}, valid, grid
        ),
        "classifier.path_map": classifier.path_map(
            probability,
            valid,
            grid,
            threshold=0.5,
            path=np.array([[1.0, 1.0], [25.0, 15.0], [29.0, 29.0]]),
            nodes=np.array([[1.0, 1.0], [25.0, 15.0], [29.0, 29.0], [15.0, 8.0]]),
            nodes_valid=np.array([True, True, True, False]),
        ),
        "classifier.metrics_bars": classifier.metrics_bars(
            {"paper": {"acc": 0.8, "tpr": 0.9, "tnr": 0.6}, "always valid": {"acc": 0.7, "tpr": 1.0, "tnr": 0.0}}
        ),
        "classifier.roc_curve": classifier.roc_curve(
            {"paper": (probability, valid, 0.5), "strong": (probability, valid, 0.7)}
        ),
        "classifier.threshold_view": classifier.threshold_view(probability, valid, grid, threshold=0.5, title="paper"),
        "crossover.crossover": crossover.crossover(
            {"scenario": "2ds", "preset": "paper", "quick": True, "variables": {"batch": sweep, "other": sweep}}
        ),
        "cspace.workspace_figure": cspace.workspace_figure(office),
        "race.race_medians": race.race_medians(
            {
                s: {"ours: RRT-Connect": 1.3 * (i + 1), "OMPL RRTConnect": 9.3, "OMPL PRM": 130.0}
                for i, s in enumerate("AB")
            },
            {s: {"OMPL RRTConnect": 2.2, "OMPL PRM": 19.0} for s in "AB"},
            seed=9300,
        ),
        "cspace.occupancy_figure": cspace.occupancy_figure(office, layers=[0, 1, 2, 3, 4]),
        "robot_drawing.robot_figure": robot_drawing.robot_figure(
            chain.robot, Q, clutter, labels=["joint2 low", "joint2 middle", "joint2 high"]
        ),
        "verdict.verdict_figure": verdict.verdict_figure(chain_exact, np.stack([near, touching])),
        "cspace.cspace_image": cspace.cspace_image(exact, resolution=100),
        "cspace.cspace_slice": cspace.cspace_slice(chain_exact, Q[0], (3, 4), resolution=20),
        "planning.samplers": planning.samplers(exact, samples, attempts=60),
        "planning.sample_sets": planning.sample_sets(exact, S, rng.random(60) < 0.6),
        "planning.roadmap": planning.roadmap(exact, _step("candidate", [0, 3, 1]), title="a candidate"),
        "planning.roadmap_steps": planning.roadmap_steps(
            exact,
            [
                _step(stage, p)
                for stage, p in [("candidate", [0, 4, 2, 1]), ("repair", [0, 4, 2, 1]), ("path", [0, 3, 1])]
            ]
            * 2,
        ),
        "timings.stage_times": timings.stage_times({"2DS": SLOW_QUERY, "3DC-7": PLANNING}),
        "answer.answer_ratios": answer.answer_ratios(
            {
                "2DS, the paper's Table 3": {"BS": 0.5, "OB": 0.8, "G": 1.2, "BT": 0.9},
                "2DS, ours": {"BS": 1.5, "OB": 1.1, "G": 1.3, "BT": 1.2},
            },
            tie=0.1,
            spans={"2DS, ours": {"BS": (1.2, 1.8), "OB": (0.9, 1.3), "G": (1.1, 1.5), "BT": (1.0, 1.4)}},
            means={"2DS, ours": {"BS": 1.4, "OB": 1.0, "G": 1.2, "BT": 0.85}},  # two panels: means, then medians
            floor=(0.84, 1.24),  # reader r34d: the means floor hatched in the means panel
        ),
        "query_ratios.own_ratios": query_ratios.own_ratios(
            {
                "2DS": {"BS": (1.13, 0.77, 1.59), "OB": (0.85, 0.7, 0.95)},
                "3DC-7": {"BS": (1.03, 0.98, 1.1), "OB": (1.5, 1.2, 1.7)},
            },
            title="each query's own ratio",
        ),
        "query_ratios.means_grid": query_ratios.means_grid(
            {
                "2DS: total time, means": {
                    "the paper": {"BS": 0.8, "OB": 0.8, "G": 0.9, "BT": 0.9},
                    "ours": {"BS": 1.3, "OB": 1.5, "G": 1.3, "BT": 0.8},
                },
                "3DC-7: total time, means": {"the paper": {"BS": 1.0, "OB": 0.9, "G": 1.1, "BT": 0.5}},
            },
            ylim=(0.4, 2.2),
            ticks=(0.9, 1.1),  # as docs/results.md's Figure 2 (review r24c): the tie band's edges labelled
            row_height=2.9,
        ),
        "timings.throughputs": timings.throughputs(
            {"2DS": {"exact": 9e7, "learned": 3e6}, "3DC-7": {"exact": 2e5, "learned": 2.5e6}}
        ),
        "reproduction.cae_reconstruction": reproduction.cae_reconstruction(
            {"seen": grids[0], "unseen": grids[1]}, {"seen": decoded[0], "unseen": decoded[1]}
        ),
        "reproduction.planning_times": reproduction.planning_times(SLOW_QUERY),
        "reproduction.threshold_sweep": reproduction.threshold_sweep(probability, valid, 0.5),
        "scenes.path_frame": scenes.path_frame(
            chain.robot,
            path,
            4,
            workspace=clutter,
            valid=chain_exact.are_valid(path),
            clearance=np.linspace(0.5, 0.1, 12),
            probability=np.linspace(0.9, 0.3, 12),
        ),
        "scenes.scene_still": scenes.scene_still(
            chain.robot,
            clutter,
            {"start": path[0], "goal": path[-1]},
            valid={"start": True, "goal": False},
            samples=(rng.uniform(0, 11, (40, 3)), {"valid": np.arange(40) < 30, "in collision": np.arange(40) >= 30}),
            trace=chain.robot.link_boxes(path)[0][:, 0],
        ),
        "tutorials.mesh_and_grid": tutorials.mesh_and_grid(mesh_ws, title="one box"),
        "tutorials.samplers_in_a_passage": tutorials.samplers_in_a_passage(exact, samples, ((9.0, 12.0), (20.0, 20.0))),
    }


@pytest.fixture(scope="module")
def drawn() -> dict[str, Figure]:
    figures = gallery()
    for fig in figures.values():
        FigureCanvasAgg(fig).draw()  # texts and 3D projections take their places when drawn
    return figures


def test_the_gallery_holds_every_figure_function(drawn):
    assert figure_functions() == set(drawn)


def test_every_figure_is_described_from_its_data_in_plain_words(drawn):
    for name, fig in drawn.items():
        text = alt.alt_text(fig)
        assert not alt.is_fallback(text), f"{name}: {text}"
        assert not any(mark in text for mark in alt.TEX), f"{name}: TeX in {text}"
        assert any(ch.isdigit() for ch in text) and len(text) > 60, f"{name}: no numbers in {text}"


COMPLEX = {  # figures of one panel whose short text cannot carry their data: maps, 3D views, a step, curves
    "classifier.probability_map",
    "classifier.path_map",
    "cspace.cspace_image",
    "cspace.workspace_figure",
    "planning.roadmap",
}


def test_every_complex_figure_has_a_longer_description_from_its_data(drawn):
    for name, fig in drawn.items():
        parts = alt.details(fig)
        if alt.panels(fig) > 1 or name in COMPLEX:
            assert parts, f"{name}: {alt.panels(fig)} panels and no longer description"
        assert not any(alt.is_fallback(p["name"]) for p in parts), f"{name}: {parts}"
        tables = [cell for p in parts for row in p["rows"] for cell in row]
        assert not parts or any(ch.isdigit() for cell in tables for ch in cell), f"{name}: no numbers in {parts}"


def test_a_reconstructions_regions_count_every_wrong_cell():
    rng = np.random.default_rng(3)
    grids = np.where(rng.random((1, 10, 10)) < 0.3, 1.0, -1.0)  # (1, 10, 10)
    decoded = grids * np.where(rng.random(grids.shape) < 0.15, -1.0, 1.0)
    ((part,),) = [alt.details(cae.reconstructions(grids, decoded, ["w"]))]
    wrong = [re.match(r".*; (\d+) missed, (\d+) invented", cell) for row in part["rows"] for cell in row[1:]]
    missed = int(np.sum((grids > 0) & (decoded < 0)))
    invented = int(np.sum((grids < 0) & (decoded > 0)))
    assert missed + invented > 0
    assert sum(int(m[1]) for m in wrong) == missed and sum(int(m[2]) for m in wrong) == invented
    # 10 cells in 4 regions, edges 0 2 5 8 10; reader r53b: each range's last cell said, not the next one's first
    assert len(part["rows"]) == 4 and part["columns"][1:] == [
        "x cells 0–1",
        "x cells 2–4",
        "x cells 5–7",
        "x cells 8–9",
    ]
    assert [row[0] for row in part["rows"]] == ["y cells 8–9", "y cells 5–7", "y cells 2–4", "y cells 0–1"]


def test_the_crossover_curves_are_in_a_table_at_their_measured_values():
    sweep = {
        "label": "blocks",
        "values": [10, 100],
        "exact_us": [2.0, 8.0],
        "fcl_us": [3.0, 30.0],
        "learned_us": [4.0, 4.0],
        "crossing": {"exact": {"value": 50.0}, "fcl": None},
    }
    (part,) = alt.details(crossover.crossover({"scenario": "3do", "preset": "paper", "variables": {"b": sweep}}))
    assert part["rows"] == [["10", "2", "3", "4", "2.00"], ["100", "8", "30", "4", "0.50"]]
    # read from the curves, log-log: exact 2 to 8 meets 4 at 10 ** 1.5; python-fcl 3 to 30 at 10 ** (1 + log10(4 / 3))
    assert part["text"].endswith(
        "cheaper by more than 25% at 100. The network's curve crosses the exact, default (compiled) one at 31.6, "
        "the exact, python-fcl one at 13.3."
    )


def test_a_description_refuses_tex():
    with pytest.raises(ValueError, match="not TeX"):
        alt.describe(Figure(), r"the norm $\|z\|$")


def data_colours(fig: Figure) -> set[str]:
    """The colours of every line, patch and collection a figure's axes draw (colour-mapped ones aside)."""
    found = set()
    for ax in fig.axes:
        for artist in [*ax.lines, *ax.patches, *ax.collections]:
            if isinstance(artist, Line2D):
                colours = [artist.get_color()] if artist.get_linestyle() not in ("None", "", " ") else []
                if artist.get_marker() not in (None, "None", "", " "):
                    colours.append(artist.get_markeredgecolor())
                    if MarkerStyle(artist.get_marker()).is_filled() and artist.get_fillstyle() != "none":
                        colours.append(artist.get_markerfacecolor())
            elif isinstance(artist, Collection):
                if artist.get_array() is not None and not hasattr(artist, "levels"):
                    continue  # colour-mapped: its colours come from a colour map of the palette module
                colours = [*artist.get_facecolor(), *artist.get_edgecolor()]
            else:
                assert isinstance(artist, Patch)
                if artist is ax.patch:
                    continue
                colours = [artist.get_facecolor(), artist.get_edgecolor()]
            found |= {to_hex(c) for c in colours if not (isinstance(c, str) and c == "none") and np.ravel(c)[-1:] != 0}
    return found


def test_the_default_colour_finder_finds_the_default_cycle():
    fig = Figure()
    fig.subplots().plot([0, 1], [0, 1])
    assert data_colours(fig) == {"#1f77b4"}


def test_every_colour_drawn_comes_from_the_palette(drawn):
    outside = {name: sorted(data_colours(fig) - PALETTE) for name, fig in drawn.items()}
    assert {name: colours for name, colours in outside.items() if colours} == {}
    assert not any(data_colours(fig) & DEFAULT_CYCLE for fig in drawn.values())


def visible_texts(fig: Figure) -> list[Text]:
    renderer = fig.canvas.get_renderer()  # type: ignore[attr-defined]  # the Agg canvas's (headless)
    texts = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip()]
    return [t for t in texts if t.get_window_extent(renderer).width > 0 and _shown(t)]


def _shown(artist) -> bool:
    """Whether the artist and every parent it hangs from is visible (a hidden axes hides its texts)."""
    axes = getattr(artist, "axes", None)
    return axes is None or _axes_shown(axes)


def _axes_shown(ax) -> bool:
    """Whether ``ax`` draws its axes (mplot3d turns the 2D ones off and draws its own)."""
    return ax.get_visible() and (ax.axison or getattr(ax, "_axis3don", False))


def test_every_text_is_at_least_8_points(drawn):
    small = {
        name: sorted({f"{t.get_text()[:30]!r} {t.get_fontsize():g} pt" for t in visible_texts(fig)})
        for name, fig in drawn.items()
    }
    small = {name: [s for s in found if float(s.rsplit(" ", 2)[-2]) < MIN_POINTS] for name, found in small.items()}
    assert {name: found for name, found in small.items() if found} == {}


def test_every_axis_that_shows_numbers_is_named(drawn):
    unnamed = {}
    for name, fig in drawn.items():
        for ax in fig.axes:
            if not _axes_shown(ax):
                continue
            axes = {"x": ax.xaxis, "y": ax.yaxis, **({"z": ax.zaxis} if hasattr(ax, "zaxis") else {})}
            for letter, axis in axes.items():
                numbers = [t for t in axis.get_ticklabels() if t.get_visible() and t.get_text().strip()]
                if numbers and not axis.get_label_text().strip():
                    unnamed.setdefault(name, []).append(f"{ax.get_title()[:30]!r}: {letter}")
    assert unnamed == {}


def test_no_two_titles_or_legends_lie_over_each_other(drawn):
    overlapping = {}
    for name, fig in drawn.items():
        renderer = fig.canvas.get_renderer()
        titles = [t for t in visible_texts(fig) if t in _titles(fig)]
        boxes = [(t.get_text()[:25], t.get_window_extent(renderer)) for t in titles]
        boxes += [(f"legend {i}", legend.get_window_extent(renderer)) for i, legend in enumerate(_legends(fig))]
        for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2):
            if box_a.overlaps(box_b) and box_a.intersection(box_a, box_b).width > 2:
                overlapping.setdefault(name, []).append(f"{a!r} / {b!r}")
    assert overlapping == {}


def test_no_two_tick_labels_of_an_axis_lie_over_each_other(drawn):
    crowded = {}
    for name, fig in drawn.items():
        renderer = fig.canvas.get_renderer()
        for ax in fig.axes:
            if not _axes_shown(ax):
                continue
            for axis in [ax.xaxis, ax.yaxis, *([ax.zaxis] if hasattr(ax, "zaxis") else [])]:
                boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in _tick_labels(axis)]
                for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2):
                    if box_a.overlaps(box_b) and box_a.intersection(box_a, box_b).width > 1:
                        crowded.setdefault(name, []).append(f"{axis.axis_name}: {a!r} / {b!r}")
    assert crowded == {}


def _tick_labels(axis) -> list[Text]:
    """The tick labels an axis drew (mplot3d places its ticks' own labels, not those ``get_ticklabels`` returns)."""
    low, high = sorted(axis.get_view_interval())
    ticks = [t for t in axis.get_major_ticks() if low - 1e-9 <= t.get_loc() <= high + 1e-9]
    return [t.label1 for t in ticks if t.label1.get_visible() and t.label1.get_text().strip()]


def _titles(fig: Figure) -> list[Text]:
    figures = [fig, *fig.subfigs]
    return [ax.title for ax in fig.axes] + [t for f in figures if (t := getattr(f, "_suptitle", None)) is not None]


def _legends(fig: Figure) -> list:
    return [
        *[f for sub in [fig, *fig.subfigs] for f in sub.legends],
        *[ax.get_legend() for ax in fig.axes if ax.get_legend()],
    ]


def test_the_plots_package_exports_figures_that_are_described(drawn):
    assert {"crossover", "cae_reconstruction", "planning_times", "threshold_sweep"} <= set(plots.__all__)


HALOED = {  # figure function: (its entry in palette.MARKS_ON, the panels its marks lie on)
    "classifier.probability_map": ("classifier probability", slice(0, 1)),
    "classifier.path_map": ("classifier probability", slice(0, 1)),
    "classifier.threshold_view": ("classifier answers", slice(0, 1)),
    "planning.roadmap_steps": ("roadmap figure", slice(None)),
    "planning.sample_sets": ("sampler figure", slice(None)),
    "tutorials.samplers_in_a_passage": ("narrow passage", slice(None)),
    "crossover.crossover": ("crossover", slice(None)),
    "scenes.path_frame": ("scene frame", slice(0, 1)),
}


def test_every_mark_the_palette_outlines_is_drawn_with_its_outline(drawn):
    """The marks ``palette.MARKS_ON`` gives an outline (lines, points, outlines; not shaded areas) carry it."""
    bare = {}
    for name, (entry, panels) in HALOED.items():
        outlined = {to_hex(palette.COLORS[m]) for m, rings in palette.MARKS_ON[entry][1].items() if rings}
        marks = [a for ax in drawn[name].axes[panels] for a in [*ax.lines, *ax.collections, *ax.patches]]
        marks = [a for a in marks if not isinstance(a, PolyCollection) and a is not a.axes.patch]
        found = [a for a in marks if _mark_colours(a) & outlined]
        assert found, f"{name}: no mark in {outlined}"
        bare[name] = [type(a).__name__ for a in found if len(a.get_path_effects()) < 2]
    assert {name: kinds for name, kinds in bare.items() if kinds} == {}


def _mark_colours(artist) -> set[str]:
    if isinstance(artist, Line2D):
        return {to_hex(artist.get_color())}
    colours = [*np.atleast_2d(artist.get_facecolor()), *np.atleast_2d(artist.get_edgecolor())]
    return {to_hex(c) for c in colours if len(c) and c[-1] > 0}


SITE_PIXELS = 750  # the widest a chapter's figure is shown on the course site (its content column), in pixels
CHAPTER_FIGURES = (  # the figures chapters 02 to 05 show, read on the site at its width (issue 45)
    "accuracy_panels.accuracy_panels",
    "cae.contraction",
    "classifier.probability_map",
    "crossover.crossover",
    "planning.samplers",
    "planning.roadmap_steps",
    "timings.stage_times",
    "planning.sample_sets",
    "answer.answer_ratios",
    "reproduction.planning_times",
    "scenes.path_frame",
    "scenes.scene_still",
)


def test_the_chapters_figures_keep_8_points_at_the_sites_width(drawn):
    """A figure wider than the site's column shrinks, and its text with it: every text of these figures is at
    least 8 pt as the site shows it (saved as the notebook saves it: 100 dpi, cropped to what is drawn)."""
    small = {}
    for name in CHAPTER_FIGURES:
        fig = drawn[name]
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=100, bbox_inches="tight")
        width = Image.open(buffer).size[0]  # pixels
        shown = min(1.0, SITE_PIXELS / width)
        found = sorted(
            {
                f"{t.get_text()[:25]!r} {t.get_fontsize() * shown:.1f} pt"
                for t in visible_texts(fig)
                if t.get_fontsize() * shown < MIN_POINTS
            }
        )
        if found:
            small[f"{name} ({width} px)"] = found
    assert small == {}
