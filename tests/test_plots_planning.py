"""Planning figures (notebook 04) draw what they are given: C-obstacles, samples, roadmaps, repairs, bar heights."""

import dataclasses
import io
import re

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import LineCollection
from matplotlib.colors import to_rgba, to_rgba_array
from matplotlib.contour import ContourSet
from matplotlib.figure import Figure
from PIL import Image

from toolkit import scenarios
from toolkit.experiments.queries import make_queries
from toolkit.geometry import robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.planning.paper_prm import PRM
from toolkit.planning.prm import PlanStep, plan
from toolkit.plots import alt, palette, planning, reproduction, timings
from toolkit.plots.palette import PAGE_WIDTH

SCENARIO = scenarios.get("2ds")


@pytest.fixture(scope="module")
def query():
    return make_queries(SCENARIO, seed=0, n_workspaces=1, per_workspace=1)[0]


@pytest.fixture(scope="module")
def exact(query):
    return exact_checker(query.workspace, SCENARIO.robot)


def is_color(colors, name) -> np.ndarray:
    """``(N,)`` whether each of ``colors`` (RGBA rows or a colour name) is the colour ``name``."""
    return np.all(np.isclose(to_rgba_array(colors), to_rgba(name)), axis=1)


def segments(ax) -> list[np.ndarray]:
    """Every line collection's segments, ``(S, 2, 2)`` each, in drawing order."""
    return [np.array(c.get_segments()).reshape(-1, 2, 2) for c in ax.collections if isinstance(c, LineCollection)]


def test_cspace_image_is_dark_exactly_on_the_grown_blocks(exact, query):
    fig = planning.samplers(exact, {"BS": np.zeros((0, 2))})
    image = fig.axes[0].images[0]
    blocked = np.asarray(image.get_array(), dtype=bool)  # (H, W), row = y
    robot = SCENARIO.robot
    assert image.get_extent() == [robot.lower[0], robot.upper[0], robot.lower[1], robot.upper[1]]
    cell = (robot.upper - robot.lower) / blocked.shape[::-1]  # (2,) pixel size along x, y
    xs, ys = (robot.lower[a] + (np.arange(blocked.shape[1 - a]) + 0.5) * cell[a] for a in (0, 1))
    X, Y = np.meshgrid(xs, ys)  # (H, W)
    half = robot.half_extents[0]
    inside, near_edge = np.zeros_like(blocked), np.zeros_like(blocked)
    for lo, hi in query.workspace.boxes:  # C-obstacle of an axis-aligned square: the block grown by its half size
        lo, hi = lo - half, hi + half
        inside |= (lo[0] <= X) & (hi[0] >= X) & (lo[1] <= Y) & (hi[1] >= Y)
        near_edge |= np.isclose(X, lo[0]) | np.isclose(X, hi[0]) | np.isclose(Y, lo[1]) | np.isclose(Y, hi[1])
    assert blocked.shape == (300, 300) and 0.05 < blocked.mean() < 0.6
    np.testing.assert_array_equal(blocked[~near_edge], inside[~near_edge])


def test_cspace_needs_a_2d_robot():
    scenario = scenarios.get("3dc7")
    ws = make_queries(scenario, seed=0, n_workspaces=1)[0].workspace
    with pytest.raises(ValueError, match="2-DoF"):
        planning.cspace_validity(exact_checker(ws, scenario.robot))


def test_samplers_one_panel_per_sampler_with_its_samples_over_the_blocks(exact, query, rng):
    samples = {name: rng.uniform(0, 31, size=(n, 2)) for name, n in (("BS", 40), ("OB", 7), ("G", 0), ("BT", 1))}
    fig = planning.samplers(exact, samples, attempts=200)
    assert isinstance(fig, Figure) and len(fig.axes) == 4
    for ax, (name, Q) in zip(fig.axes, samples.items()):
        (drawn,) = [c for c in ax.collections if not isinstance(c, ContourSet)]
        np.testing.assert_array_equal(drawn.get_offsets(), Q)
        assert ax.get_title().startswith(f"{name}:\n{len(Q)} sample{'' if len(Q) == 1 else 's'} of 200 attempts")
        blocks = [(p.get_xy(), p.get_width(), p.get_height()) for p in ax.patches[:-1]]  # the last: the bounds
        assert [
            (tuple(lo), w, h) for lo, (w, h) in zip(query.workspace.boxes[:, 0], np.ptp(query.workspace.boxes, axis=1))
        ] == [(tuple(xy), w, h) for xy, w, h in blocks]


def test_sample_sets_marks_accepted_samples_that_are_truly_in_collision(exact, rng):
    S = SCENARIO.robot.sample(rng, 300)
    accepted = rng.random(300) < 0.7  # a checker that accepts at random
    truth = exact.are_valid(S)
    ax = planning.sample_sets(exact, S, accepted).axes[0]
    rejected, kept, wrong = ax.collections
    within = planning.OVERLAP * float(np.linalg.norm(SCENARIO.robot.upper - SCENARIO.robot.lower))
    for drawn, mask in ((rejected, ~accepted), (kept, accepted & truth), (wrong, accepted & ~truth)):
        np.testing.assert_array_equal(drawn.get_offsets(), planning.merged(S[mask], within)[0])
        assert sum(planning.merged(S[mask], within)[1]) == mask.sum()
    assert len(S[accepted & ~truth]) > 0 and is_color(wrong.get_edgecolors(), planning.REPAIR_COLOR).all()
    assert len(wrong.get_facecolors()) == 0  # rings: reader r45d, item 1: no cross, chapter 04's fast checker's marker
    fig = ax.figure
    said = [t.get_text() for t in fig.legends[0].texts]
    assert f"S', truly in collision (rings): {(accepted & ~truth).sum()}" in said
    assert (
        f"rejected (dashes): {(~accepted).sum()}" in said and f"S' (accepted, dots): {(accepted & truth).sum()}" in said
    )
    handles = fig.legends[0].legend_handles  # no marker of chapter 04's checkers (diamond, cross, hexagon, plus)
    shapes = [h.get_paths()[0].vertices.shape for h in handles]
    assert len(set(shapes)) == 2 and all(len(h.get_paths()) == 1 for h in handles)  # the dash, and circles
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    assert not fig.legends[0].get_window_extent(renderer).overlaps(ax.get_window_extent(renderer))  # hides no sample
    assert not any(c.get_clip_on() for c in (rejected, kept, wrong))  # a sample on the C-space's edge drawn whole
    assert rejected.get_sizes()[0] >= 20 and palette.contrast("rejected", "c_obstacle") >= 4.5  # seen on a block


def test_sample_sets_counts_markers_that_lie_on_one_another(exact):
    """Review r24a: two rejected attempts at one spot read as one cross beside the legend's count; review r32d: a "2×"
    beside two crosses still apart read as three, so the two are drawn once, at their centre, with their count."""
    shown, counts = planning.merged(np.array([[1.0, 1.0], [5.0, 5.0], [1.1, 1.0]]), 0.5)
    np.testing.assert_allclose(shown, [[1.05, 1.0], [5.0, 5.0]])
    assert counts == [2, 1]
    S = np.array([[20.0, 20.0], [20.1, 20.05], [5.0, 25.0]])
    ax = planning.sample_sets(exact, S, np.zeros(3, bool)).axes[0]
    assert [t.get_text() for t in ax.texts] == ["(2)"]
    assert len(ax.collections[0].get_offsets()) == 2  # two crosses drawn: one of them the "(2)"
    assert ax.texts[0].xyann == (6, 6)  # up and right, where no other marker is
    beside = np.vstack([S, [[21.5, 21.2]]])  # a third cross up and right of the two: the count moves aside
    ax = planning.sample_sets(exact, beside, np.zeros(4, bool)).axes[0]
    assert [t.get_text() for t in ax.texts] == ["(2)"] and ax.texts[0].xyann != (6, 6)


def a_repair_step() -> PlanStep:
    """Five nodes in a row from start (0) to goal (1); the path 0-2-3-4-1; the repair removes node 3 and edge 1."""
    nodes = np.array([[2.0, 2.0], [12.0, 2.0], [4.0, 3.0], [6.0, 3.0], [9.0, 3.0]])
    edges = np.array([[0, 2], [2, 3], [3, 4], [1, 4], [0, 1]])
    return PlanStep(
        "repair",
        2,
        nodes,
        np.array([True, True, True, False, False]),
        edges,
        np.zeros(0, int),
        np.array([0, 2, 3, 4, 1]),
        np.array([3]),
        np.array([1]),
    )


def test_roadmap_draws_every_edge_and_the_repair_in_red(exact):
    step = a_repair_step()
    ax = planning.roadmap(exact, step, title="a repair").axes[0]
    kept, removed = segments(ax)
    assert len(kept) + len(removed) == len(step.edges)
    np.testing.assert_array_equal(removed, step.nodes[step.edges[[1]]])
    lines = [c for c in ax.collections if isinstance(c, LineCollection)]
    assert [is_color(c.get_colors(), planning.REPAIR_COLOR).all() for c in lines] == [False, True]
    points = [c for c in ax.collections if not isinstance(c, LineCollection)]
    confirmed, unconfirmed, on_confirmed, on_unconfirmed, removed_nodes = (points[i].get_offsets() for i in range(5))
    np.testing.assert_array_equal(confirmed, step.nodes[:3])
    np.testing.assert_array_equal(unconfirmed, step.nodes[3:])
    # reader r47d: the path's own nodes again, over its line, filled where confirmed (0, 2, 1), hollow where not (3, 4)
    np.testing.assert_array_equal(on_confirmed, step.nodes[[0, 2, 1]])
    np.testing.assert_array_equal(on_unconfirmed, step.nodes[[3, 4]])
    np.testing.assert_array_equal(removed_nodes, step.nodes[[3]])
    assert is_color(points[4].get_facecolors(), planning.REPAIR_COLOR).all()
    (path,) = ax.lines
    assert points[2].get_zorder() > path.get_zorder() and points[3].get_zorder() > path.get_zorder()
    assert points[2].get_path_effects() and not points[3].get_path_effects()  # r49d, item 5: no bold ring when hollow
    np.testing.assert_array_equal(np.c_[path.get_xdata(), path.get_ydata()], step.nodes[step.path])
    assert ax.get_title() == "round 2, repair:\n5 nodes, 5 edges"


def test_roadmap_of_a_real_plan_draws_as_many_edges_as_the_roadmap_has(exact, query):
    trace = []
    result = plan(
        exact,
        query.start,
        query.goal,
        sampler="G",
        planner=PRM(n_samples=100),
        rng=np.random.default_rng(0),
        trace=trace,
    )
    ax = planning.roadmap(exact, trace[-1]).axes[0]
    kept, removed = segments(ax)
    assert len(kept) == len(result.roadmap.edges) > 0 and len(removed) == 0
    assert is_color(ax.lines[0].get_color(), planning.PATH_STYLES["path"][0]).all()
    assert ax.lines[0].get_linestyle() == "-"  # the returned path solid, a candidate dashed


def test_roadmap_names_every_mark_and_draws_start_and_goal_whole_and_large(exact):
    step = a_repair_step()
    fig = planning.roadmap(exact, step)
    ax = fig.axes[0]
    named = [t.get_text() for t in fig.legends[0].texts]
    assert {"edge removed by a repair", "node removed by a repair", "start", "goal"} <= set(named)
    rings = [c for c in ax.collections if not isinstance(c, LineCollection) and len(c.get_facecolors()) == 0]
    assert len(rings) == 1  # reader r61d, item 6: one ring, the removed node; an edge's entry point is a triangle
    nodes, *_, start, goal = [c for c in ax.collections if not isinstance(c, LineCollection)]
    assert [start.get_clip_on(), goal.get_clip_on()] == [False, False]  # whole where they lie on the edge
    assert goal.get_sizes()[0] >= 10 * nodes.get_sizes()[0] and start.get_sizes()[0] >= 4 * nodes.get_sizes()[0]
    lower, upper = exact.workspace.lower, exact.workspace.upper  # review r19a: a start square half outside the frame
    for (low, high), lo, hi in zip((ax.get_xlim(), ax.get_ylim()), lower, upper):
        assert low <= lo - 0.03 * (hi - lo) and high >= hi + 0.03 * (hi - lo)  # a margin round the C-space


def test_roadmap_steps_one_panel_per_step(exact):
    steps = [a_repair_step()] * 4
    fig = planning.roadmap_steps(exact, steps, columns=3)
    visible = [ax for ax in fig.axes if ax.axison]
    assert len(fig.axes) == 6 and len(visible) == 4


MEDIANS = {  # sampler -> mode -> seconds of each stage and the total of a typical query
    s: {
        m: {
            "sampling_s": 0.01 * (i + 1) * f,
            "connection_s": 0.1 * f,
            "query_s": 0.02 * f,
            "total_s": (0.01 * (i + 1) + 0.12 + 0.005) * f,
        }
        for m, f in (("without", 1.0), ("with", 0.5))
    }
    for i, s in enumerate(("BS", "OB", "G", "BT"))
}
PER_QUERY = {"without": [1.0, 1.0, 1.0], "with": [0.5, 0.6, 1.2]}  # 3 queries' totals, in a typical query's without
PLANNING = {  # as queries.summarize writes it: median totals, quartiles 20 % below and 50 % above, stage shares
    s: {
        m: {
            "total_s_median": row["total_s"],
            "total_s_per_query": [f * modes["without"]["total_s"] for f in PER_QUERY[m]],
            "total_s_q1": 0.8 * row["total_s"],
            "total_s_q3": 1.5 * row["total_s"],
            **{f"{key}_share": row[key] / row["total_s"] for key in ("sampling_s", "connection_s", "query_s")},
        }
        for m, row in modes.items()
    }
    for s, modes in MEDIANS.items()
}


def test_stage_times_one_stacked_bar_per_sampler_and_mode_with_the_given_heights():
    ax = timings.stage_times({"2DS": PLANNING}).axes[0]
    bars = {c.get_label(): [p.get_height() for p in c.patches] for c in ax.containers if hasattr(c, "patches")}
    assert [t.get_text() for t in ax.figure.legends[0].texts] == [*bars, "total: quartiles"]
    assert list(bars) == [timings.STAGE_LABELS[k] for k in ("sampling_s", "connection_s", "query_s", "other_s")]
    order = [(s, m) for s in ("BS", "OB", "G", "BT") for m in ("without", "with")]
    for key in ("sampling_s", "connection_s", "query_s"):  # in ms
        np.testing.assert_allclose(bars[timings.STAGE_LABELS[key]], [1e3 * MEDIANS[s][m][key] for s, m in order])
    np.testing.assert_allclose(np.sum(list(bars.values()), axis=0), [1e3 * MEDIANS[s][m]["total_s"] for s, m in order])
    (whiskers,) = ax.collections  # the total's quartiles, one vertical segment a bar: never below zero
    ring = whiskers.get_path_effects()[0]  # a white ring under the black line: seen on the black "other" segment
    assert ring._gc["foreground"] == palette.COLORS["free"] and len(whiskers.get_path_effects()) == 2
    spans = np.array([segment[:, 1] for segment in whiskers.get_segments()])  # (bars, 2): q1, q3
    np.testing.assert_allclose(
        spans, [[800 * MEDIANS[s][m]["total_s"], 1500 * MEDIANS[s][m]["total_s"]] for s, m in order]
    )
    stacks = ax.containers[0].patches  # review r25a: beside its bar (r17a, r23a) a whisker read as the next bar's;
    for segment, bar in zip(whiskers.get_segments(), stacks):  # now on its own bar's centre, a white ring round it
        assert np.isclose(segment[0, 0], bar.get_x() + bar.get_width() / 2)
        assert all(not b.get_x() <= segment[0, 0] <= b.get_x() + b.get_width() for b in stacks if b is not bar)
    # above each pair the median of the queries' own ratios (0.5, 0.6, 1.2), not the ratio of the median totals (0.5)
    assert [t.get_text() for t in ax.texts] == ["0.60x"] * 4  # reader r40d: one ratio a pair
    assert "the bars' own ratio 0.50x" in alt.alt_text(ax.figure)  # the bars' quotient in the figure's words
    assert [t.get_text() for t in ax.get_xticklabels()][:2] == ["BS\nwithout", "BS\nwith"]
    assert ax.get_ylim()[1] > 1500 * MEDIANS["BT"]["without"]["total_s"]  # every whisker within 2x the bars: whole


def test_a_pair_whose_taller_bar_says_the_other_way_is_starred_and_told():
    """Review r13a: "0.80x" over a pair whose bar with prediction was the taller (7.64 ms against 7.42). The number
    is the median of each query's ratio, not the bars' quotient; where the two fall on opposite sides of 1 it
    carries a "‡" that the title explains (reader r35d: not "*", chapter 04's timing noise; r48d: nor its tables'
    †), and the description says which bar is taller."""
    planning = {s: {m: dict(row) for m, row in modes.items()} for s, modes in PLANNING.items()}
    taller = 1.03 * planning["OB"]["without"]["total_s_median"]  # its queries' own ratios still 0.5, 0.6, 1.2
    planning["OB"]["with"].update(total_s_median=taller, total_s_q1=0.8 * taller, total_s_q3=1.5 * taller)
    fig = timings.stage_times({"2DS": planning})
    ax = fig.axes[0]
    assert [t.get_text() for t in ax.texts] == [
        "0.60x",
        "0.60x‡",
        *["0.60x"] * 2,
    ]
    assert "median of each query's ratio" in ax.get_title() and "‡: the bars say the other way" in ax.get_title()
    assert "0.60x; the bars' own ratio 1.03x, though the bar with prediction is the taller" in alt.alt_text(fig)
    fig = timings.stage_times({"2DS": planning}, band=(0.5, 0.7))  # reader r48d: * as chapter 04's tables mark it
    assert [t.get_text() for t in fig.axes[0].texts] == ["0.60x*", "0.60x*‡", *["0.60x*"] * 2]
    assert "\n(*: inside the noise band; ‡: the bars say the other way)" in fig.axes[0].get_title()
    buffer = io.BytesIO()  # reader r62d: the marks' note on its own line keeps the figure at the column's width
    fig.savefig(buffer, format="png", dpi=100, bbox_inches="tight")
    assert Image.open(buffer).size[0] <= 100 * PAGE_WIDTH + 20
    assert "query's ratio 0.60x, inside the noise band; the bars' own ratio" in alt.alt_text(fig)
    assert "*" not in timings.stage_times({"2DS": planning}, band=(0.7, 1.3)).axes[0].get_title()
    # reader r54d, item 4: the bars' own ratio is the quotient of the heights the description prints (4.23 / 2.85 =
    # 1.48), not of the unrounded medians (1.49)
    odd = {s: {m: dict(row) for m, row in modes.items()} for s, modes in PLANNING.items()}
    odd["OB"]["without"].update(total_s_median=0.0028451, total_s_q1=0.002, total_s_q3=0.004)
    odd["OB"]["with"].update(total_s_median=0.0042349, total_s_q1=0.003, total_s_q3=0.006)
    said = alt.alt_text(timings.stage_times({"2DS": odd}))
    assert "OB 2.85 ms without, 4.23 ms with" in said and "the bars' own ratio 1.48x" in said
    untold = timings.stage_times({"2DS": PLANNING}).axes[0].get_title()
    assert "‡" not in untold and "other way" not in untold  # reader r31d: no mark promised where none is drawn
    wide = {s: {m: dict(row) for m, row in modes.items()} for s, modes in PLANNING.items()}
    base = wide["BS"]["without"]["total_s_per_query"]  # BS's queries: 0.5, 0.6, 1.5: the middle half 0.55-1.05
    wide["BS"]["with"]["total_s_per_query"] = [f * t for f, t in zip((0.5, 0.6, 1.5), base, strict=True)]
    fig = timings.stage_times({"2DS": wide}, band=(0.4, 0.55))  # reader r49d, item 4: the table's † drawn too
    assert [t.get_text() for t in fig.axes[0].texts][:2] == ["0.60x†", "0.60x"]
    assert "(†: middle half across the tie band)" in fig.axes[0].get_title()
    assert "query's ratio 0.60x, its middle half across the tie band; the bars'" in alt.alt_text(fig)
    assert "†" not in timings.stage_times({"2DS": wide}).axes[0].get_title()  # no band: chapter 04's marks off


def test_a_whisker_far_above_the_bars_is_cut_at_the_top_with_its_end_written():
    """One slow query's spread (OB with: a third quartile 20 times its bar) must not flatten the panel's bars: the
    axis stops near the tallest bar, the whisker ends there in a triangle and its value, in ms, is written beside it
    and in the figure's description."""
    planning = {s: {m: dict(row) for m, row in modes.items()} for s, modes in PLANNING.items()}
    planning["OB"]["with"]["total_s_q3"] = 20 * planning["OB"]["with"]["total_s_median"]
    fig = timings.stage_times({"2DS": planning})
    ax = fig.axes[0]
    end = 1e3 * planning["OB"]["with"]["total_s_q3"]  # ms
    tallest = 1e3 * max(row["total_s_median"] for modes in planning.values() for row in modes.values())
    top = ax.get_ylim()[1]
    assert tallest < top < 2 * tallest < end  # the bars fill most of the panel
    (whiskers,) = ax.collections
    assert np.max([segment[:, 1] for segment in whiskers.get_segments()]) == pytest.approx(top)
    (triangle,) = [line for line in ax.lines if line.get_marker() == "^"]
    assert list(triangle.get_xdata()) == [pytest.approx(1.22)] and list(triangle.get_ydata()) == [top]  # OB, with
    assert f"{end:.0f}" in [t.get_text() for t in ax.texts]
    assert f"OB with to {end:.0f} ms" in alt.alt_text(fig)
    assert "quartile off the scale (its value written)" in [t.get_text() for t in fig.legends[0].texts]


def test_throughputs_a_point_per_scenario_and_checker_on_a_log_axis_labelled_at_1_2_5():
    """Points, not bars: on a log axis a bar's length means nothing (a bar from a floor near the slowest rate
    was a sliver); each rate written beside its point, the axis labelled often enough to read one between two."""
    rates = {"2DS": {"exact": 1.2e8, "learned": 3e6}, "3DC-7": {"exact": 2e5, "learned": 2.5e6}}
    ax = timings.throughputs(rates).axes[0]
    assert not ax.patches and not ax.containers and ax.get_yscale() == "log"
    exact, learned = ax.lines
    np.testing.assert_allclose(exact.get_ydata(), [1.2e8, 2e5])
    np.testing.assert_allclose(learned.get_ydata(), [3e6, 2.5e6])
    assert exact.get_marker() != learned.get_marker() and exact.get_linestyle() == "None"  # not by colour alone
    assert [t.get_text() for t in ax.get_xticklabels()] == ["2DS", "3DC-7"]
    assert [t.get_text() for t in ax.texts] == ["120M/s", "200k/s", "3M/s", "2.5M/s"]
    ticks = [t.get_text() for t in ax.get_yticklabels()]
    assert {"200k", "500k", "1M", "2M", "5M", "10M", "20M", "50M", "100M"} <= set(ticks)  # 100M, not 1e+02M
    lo, hi = ax.get_ylim()
    assert lo < 2e5 and hi > 1.2e8  # every point inside the frame


def test_a_rejected_candidate_and_a_fresh_one_differ_in_line_style_not_only_in_shade(exact):
    rejected = a_repair_step()
    fresh = dataclasses.replace(rejected, stage="candidate", removed_nodes=np.zeros(0, int))
    lines = [planning.roadmap(exact, step).axes[0].lines[0] for step in (rejected, fresh)]
    assert [line.get_linestyle() for line in lines] == [":", "--"]  # dotted against dashed, as dash-dot was not
    assert is_color(lines[0].get_color(), planning.REPAIR_COLOR).all()  # reader r50d, item 3: not two light blues
    assert not is_color(lines[1].get_color(), planning.REPAIR_COLOR).all()
    (unconfirmed,) = [
        c
        for c in planning.roadmap(exact, fresh).axes[0].collections
        if "confirmed (" in c.get_label() and "not" in c.get_label()
    ]  # reader r50d, item 3: filled, so a ring marks only what collides
    assert is_color(unconfirmed.get_facecolors(), planning.EDGE_COLOR).all()
    assert "dotted path" in planning.step_in_words(rejected) and "dashed path" in planning.step_in_words(fresh)


def test_a_steps_words_count_what_it_holds_in_the_right_number(exact):
    """Reader r44d, item 8: the alt text said "a repair removed 0 nodes and 0 edges" on every panel, and "1 edges"."""
    repair = a_repair_step()
    said = planning.step_in_words(repair)
    nodes, edges = len(repair.removed_nodes), len(repair.removed_edges)
    assert (nodes or edges) and "0 nodes" not in said and "0 edges" not in said and "1 edges" not in said
    words = [f"{n} {w}{'s' * (n != 1)}" for n, w in ((nodes, "node"), (edges, "edge")) if n]
    assert said.endswith(f"; the exact checker rejected {' and '.join(words)}, removed next.")
    one = dataclasses.replace(
        repair,
        stage="candidate",
        edges=repair.edges[:1],
        removed_nodes=np.zeros(0, int),
        removed_edges=np.zeros(0, int),
    )
    assert " and 1 edge over the C-obstacles" in planning.step_in_words(one)
    assert "rejected" not in planning.step_in_words(one) and "removed" not in planning.step_in_words(one)


def test_the_paper_style_times_stack_their_panels_and_cut_a_far_whisker_too():
    """reproduction.planning_times (the paper's Figures 5-7 as medians): a row of sampling panels above a row of
    totals, one panel per sampler, as wide as the page, in ms, the bars named as the paper names them; a sampling
    whisker 20 times its bar is cut at its panel's top, written over it."""
    planning = {s: {m: dict(row) for m, row in modes.items()} for s, modes in PLANNING.items()}
    for s, modes in planning.items():
        for m, row in modes.items():
            row |= {f"sampling_s_{k}": f * MEDIANS[s][m]["sampling_s"] for k, f in (("median", 1), ("q1", 0.8))}
            row["sampling_s_q3"] = (20 if (s, m) == ("BT", "with") else 1.5) * MEDIANS[s][m]["sampling_s"]
    fig = reproduction.planning_times(planning)
    FigureCanvasAgg(fig).draw()
    sampling, total = fig.axes[:4], fig.axes[4:]
    assert len(fig.axes) == 8 and fig.get_figwidth() <= PAGE_WIDTH
    assert min(ax.get_window_extent().y0 for ax in sampling) > max(ax.get_window_extent().y1 for ax in total)
    for ax, s in zip(sampling, MEDIANS):
        heights = [p.get_height() for p in ax.patches]
        np.testing.assert_allclose(heights, [1e3 * MEDIANS[s][m]["sampling_s"] for m in ("without", "with")])
        assert [t.get_text().split()[0] for t in ax.get_xticklabels()] == [s, s + "F"]
    bt = sampling[3]
    end = 1e3 * planning["BT"]["with"]["sampling_s_q3"]
    assert bt.get_ylim()[1] < end and [t.get_text() for t in bt.texts] == [f"{end:.3g}"]
    assert f"BTF to {end:.3g} ms" in alt.alt_text(fig) and not any(ax.texts for ax in total)  # the totals all fit


QUARTILES = (("median", 1.0), ("q1", 0.8), ("q3", 1.5))


def stats_of(medians) -> dict:
    """sampler -> mode -> the median and quartiles of both times, in seconds, from ``medians`` (as MEDIANS)."""
    return {
        s: {
            m: {f"{key}_{stat}": row[key] * f for key in ("sampling_s", "total_s") for stat, f in QUARTILES}
            for m, row in modes.items()
        }
        for s, modes in medians.items()
    }


def test_planning_times_names_each_bar_and_its_median_under_it_in_milliseconds():
    """BS / BSF and the bar's median under it, not over it where the quartile whiskers end; times in ms."""
    fig = reproduction.planning_times(stats_of(MEDIANS))
    for row, key in ((fig.axes[:4], "sampling_s"), (fig.axes[4:], "total_s")):
        for ax, s in zip(row, MEDIANS):
            ms = [1000 * MEDIANS[s][m][key] for m in ("without", "with")]
            names = [f"{name}\n{timings.ms_text(t)}" for name, t in zip((s, s + "F"), ms)]
            assert [t.get_text() for t in ax.get_xticklabels()] == names
            bars = sorted(ax.patches, key=lambda p: p.get_x())
            np.testing.assert_allclose(ax.get_xticks(), [p.get_x() + p.get_width() / 2 for p in bars])
            np.testing.assert_allclose([p.get_height() for p in bars], ms)
            assert ax.get_ylabel() == "ms" and not ax.texts


def test_planning_times_draws_a_fast_samplers_pair_on_its_own_scale():
    """A sampler 60 times faster than another still shows its two bars (chapter 04's 3DC-7 sampling: BS and G
    0.09-0.4 ms beside a few ms): each panel's axis is set by its own pair, from zero."""
    medians = {s: {m: dict(row) for m, row in modes.items()} for s, modes in MEDIANS.items()}
    medians["BS"] = {"without": {"sampling_s": 1.2e-4, "total_s": 2e-3}, "with": {"sampling_s": 3e-4, "total_s": 3e-3}}
    medians["OB"]["with"]["sampling_s"] = 6e-3
    fig = reproduction.planning_times(stats_of(medians))
    bs = fig.axes[0]
    bottom, top = bs.get_ylim()
    assert bottom == 0 and 0.3 < top < 0.3 * 1.5 * 1.2  # ms: the taller bar, BSF's, and its whisker fill the panel
    assert min(p.get_height() for p in bs.patches) / top > 0.2  # BS without: a fifth of the panel, not a hair


def test_samplers_say_how_many_samples_lie_near_a_c_obstacle_or_a_wall():
    """The G panel "gathers near obstacles" in numbers: a panel's title counts the samples within ``near`` of a
    C-obstacle and of a wall, the title above gives the free space's own shares (what a uniform sampler finds), and a
    dashed line is drawn at that distance; all against the distances worked out by hand for one block (not a square:
    x and y swapped would give other answers)."""
    robot = robots.point_robot()  # its centre in [0.25, 30.75]^2, half a side 0.25
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 5.0], [20.0, 12.0]]]))
    exact = exact_checker(ws, robot)  # the C-obstacle: [9.75, 20.25] x [4.75, 12.25]
    Q = np.array([[22.25, 8.0], [25.25, 8.0], [15.0, 1.25], [15.0, 30.0]])  # 2, 5, 3.5 and 17.75 from it
    fig = planning.samplers(exact, {"G": Q}, attempts=10, near=3.0)  # the last two 1 and 0.75 from a wall
    ax = fig.axes[0]
    assert ax.get_title() == "G:\n4 samples of 10 attempts\nnear: 25% a C-obstacle, 50% a wall"
    (w, h), band = (10.5, 7.5), 3.0  # the free space near the C-obstacle: a band round it, its corners rounded
    free = 30.5**2 - w * h
    by_hand = ((2 * (w + h) * band + np.pi * band**2) / free, (30.5**2 - (30.5 - 2 * band) ** 2) / free)  # 16, 39 %
    said = [float(v) for v in re.findall(r"(\d+)% (?:lies )?near a", fig.get_suptitle())]
    np.testing.assert_allclose(said, 100 * np.array(by_hand), atol=1.0)
    (dashed,) = [c for c in ax.collections if isinstance(c, ContourSet)]
    points = np.concatenate([path.vertices for path in dashed.get_paths()])  # (P, 2)
    outside = np.maximum(np.maximum((9.75, 4.75) - points, points - (20.25, 12.25)), 0.0)  # (P, 2) how far out
    np.testing.assert_allclose(np.linalg.norm(outside, axis=1), band, atol=0.15)  # within a pixel and a half
    dots = [c for c in ax.collections if not isinstance(c, ContourSet)]  # reader r46d: the line above the dots
    assert dots and dashed.get_zorder() > max(c.get_zorder() for c in dots)


def test_segment_table_gives_the_bars_segments_in_ms():
    """Review r23a: the chapter's code cell that built this table moved here; its rows are the figure's segments."""
    lines = timings.segment_table({"2DS": PLANNING}).splitlines()
    assert lines[0] == "| scenario, sampler | sampling | connection | query | other |"
    assert len(lines) == 2 + len(PLANNING) and lines[2].startswith(f"| 2DS, {next(iter(PLANNING))} | ")
    bars = timings._stage_table(PLANNING, list(PLANNING))
    assert lines[2].split(" | ")[1] == f"{bars['sampling_s'][0, 0]:.1f} / {bars['sampling_s'][0, 1]:.1f}"


def test_roadmap_steps_titles_number_each_step_and_leave_the_ring_to_the_legend(exact):
    """Reader r40d: "round 1, repair: ... where the removed edge enters a C-obstacle" ran over its neighbours' titles;
    now "step 2: repair" and its counts on a second line, the ring named in the legend only. Reader r45d: a panel is
    named by its step in the trace, and its description names it once."""
    fig = planning.roadmap_steps(exact, [a_repair_step()] * 3, columns=2)
    titles = [ax.get_title() for ax in fig.axes if ax.axison]
    assert titles == [f"step {k}: repair\n5 nodes, 5 edges, round 2" for k in (1, 2, 3)]
    fig = planning.roadmap_steps(exact, [a_repair_step()] * 2, columns=2, of=6, at=[3, 6])
    titles = [ax.get_title() for ax in fig.axes if ax.axison]
    assert titles == [f"step {k}: repair\n5 nodes, 5 edges, round 2" for k in (3, 6)]
    assert " Step 3: Round 2, repair: a roadmap" in alt.alt_text(fig)
    parts = alt.parts_of(fig)
    assert [p.name for p in parts] == ["Step 3, repair", "Step 6, repair"]
    assert all(p.text.startswith("a roadmap of 5 nodes") for p in parts)  # named once, not "Round 2, repair: ..."
