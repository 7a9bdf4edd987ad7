"""The crossover figure shades what its verdicts call "network cheaper" and hatches what they call "can't tell"."""

from pathlib import Path

import numpy as np
from matplotlib.collections import PolyCollection

from toolkit.plots import alt
from toolkit.plots.alt import alt_text
from toolkit.plots.crossover import CALLS_LEGEND, CALLS_NAME, PAPER_LEGEND, PLANNER_CALLS, TICK_POINTS, TICKS, crossover
from toolkit.plots.tick_rows import SLANT
from toolkit.util.verdicts import CHEAPER, NEAR

SWEEP = {  # network / exact: 0.5 cheaper, 0.9 can't tell, 1.5 dearer, 0.7 cheaper (the band is 25 %)
    "label": "obstacles per workspace (unit blocks)",
    "values": [10, 100, 1000, 10000],
    "exact_us": [2.0, 1.0, 1.0, 1.0],
    "fcl_us": [9.0, 9.0, 9.0, 9.0],
    "learned_us": [1.0, 0.9, 1.5, 0.7],
    "crossing": {"exact": None, "fcl": None},
}


def shaded_spans(ax, verdict: str = CHEAPER) -> list[tuple[float, float]]:
    """The x-extent of each band of a panel drawn for ``verdict`` (shaded: "network cheaper"; hatched: "can't
    tell"), in data units, rounded."""
    bands = [c for c in ax.collections if isinstance(c, PolyCollection) and c.get_gid() == verdict]
    xs = [np.asarray(b.get_paths()[0].vertices)[:, 0] for b in bands]  # each band's outline, x only
    return [(round(float(x.min()), 3), round(float(x.max()), 3)) for x in xs]


def legend_texts(fig) -> list[str]:
    """The legend's entries, each as one line (reader r39g: beside the panels, an entry is wrapped to a few lines)."""
    return [" ".join(t.get_text().split("\n")) for t in fig.legends[0].get_texts()]


def test_only_the_points_whose_verdict_is_network_cheaper_are_shaded():
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": SWEEP}})
    ax = fig.axes[0]
    # a band round 10 (from 10 to sqrt(10 * 100)) and one round 10,000 (from sqrt(1e3 * 1e4) to 10,000): cut to the
    # values measured, and between the two curves (reader r36g: a band of the panel's height read as its background)
    assert shaded_spans(ax) == [(10.0, round(np.sqrt(1000), 3)), (round(np.sqrt(1e7), 3), 10000.0)]
    first = next(c for c in ax.collections if c.get_gid() == CHEAPER)
    heights = np.asarray(first.get_paths()[0].vertices)[:, 1]
    assert 0.99 * 0.5 <= heights.min() and heights.max() <= 2.0 * 1.01  # from the network's 1 µs to the exact 2 µs
    assert "shaded: network cheaper by > 25%" in legend_texts(fig)
    assert "shaded: network cheaper by > 25%;" in fig.get_suptitle()  # reader r23a: the rule, on the figure
    assert shaded_spans(ax, NEAR) == [(round(np.sqrt(10 * 100), 3), round(np.sqrt(100 * 1000), 3))]  # 0.9 at 100
    assert "hatched: within 25% of the exact check, can't tell" in legend_texts(fig)
    assert "hatched: within 25%, can't tell" in fig.get_suptitle()  # reader r24c: the can't-tell band drawn
    assert "3DC-9" in fig.get_suptitle()  # the site's name of the scenario, not its key
    zorder = {line.get_label(): line.get_zorder() for line in ax.lines}
    exact, learned = (next(k for k in zorder if k.startswith(w)) for w in ("exact, compiled", "the network"))
    assert zorder[exact] > zorder[learned]  # reader r23a: drawn over the network
    assert "mesh: our compiled mesh checker" in exact  # reader r24c: the mesh panel's checker named
    assert "cheaper by more than 25% at 10, 10,000." in alt_text(fig)


def test_a_panel_where_the_network_is_never_cheaper_beyond_the_band_has_no_shading():
    close = {**SWEEP, "learned_us": [1.8, 0.9, 1.2, 1.1]}  # 0.9, 0.9, 1.2, 1.1: all within 25 %
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": close}})
    assert shaded_spans(fig.axes[0]) == []
    assert len(shaded_spans(fig.axes[0], NEAR)) == 4  # each point within the band, hatched
    assert "never cheaper by more than 25%." in alt_text(fig)
    legend = legend_texts(fig)
    assert not [t for t in legend if "shaded" in t or "nowhere" in t]  # reader r25c: no key to what is not drawn
    assert "shaded: network cheaper by > 25% (nowhere here);" in fig.get_suptitle()  # r23a: the rule, said above
    assert fig.axes[0].get_title() == "Obstacles"  # reader r25c: each panel titled


def test_the_text_alternative_says_when_the_sweep_was_measured_and_ticks_name_tenths_of_a_microsecond():
    """Reader r24c: the figure's date was in the caption alone, and no tick named the network's 0.27-0.43 µs. Readers
    r28f and r29f: the date in the title competed with the panels' titles; the caption says it, and so does the text
    alternative, and the title names the network's size in plain words."""
    fig = crossover(
        {"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": SWEEP}},
        measured="5 December 2026, 15:37 UTC",
    )
    assert "Measured 5 December 2026, 15:37 UTC." in alt_text(fig) and "measured" not in fig.get_suptitle().lower()
    assert "3DC-9, a paper-size network" in fig.get_suptitle()  # reader r30f: "paper-size network" in the title
    strong = crossover({"scenario": "3dc7", "preset": "strong", "quick": False, "variables": {"obstacles": SWEEP}})
    assert '3DC-7, the network at the "strong" preset\'s sizes' in strong.get_suptitle()
    low = {**SWEEP, "exact_us": [0.09, 0.1, 0.12, 0.14], "learned_us": [0.3] * 4, "fcl_us": [5, 50, 500, 900]}
    ax = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": low}}).axes[0]
    # reader r33g: on four decades and more, 1-2-5 below 1 crowded (1 / 0.5 / 0.2): decades named, 2 and 5 short ticks
    assert {"0.1", "1"} <= {t.get_text() for t in ax.get_yticklabels()}
    assert not {"0.2", "0.5"} & {t.get_text() for t in ax.get_yticklabels()}
    assert {0.2, 0.5} <= {round(t, 3) for t in ax.get_yticks(minor=True)}
    assert not any(t.get_text() for t in ax.get_yticklabels(minor=True))
    narrow = {**low, "fcl_us": [5, 6, 7, 8]}  # three decades: the network's few tenths named (reader r24c)
    ax = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": narrow}}).axes[0]
    assert {"0.1", "0.2", "0.5"} <= {t.get_text() for t in ax.get_yticklabels()}


def test_a_tick_label_that_would_touch_its_neighbour_is_left_out_and_the_last_is_always_named():
    """Labels at their places in pixels, digits 8 px wide: one kept where a digit and a half of white parts it from the
    one before (half a label's width each side of its tick), the last always named, its neighbour giving way."""
    from toolkit.plots.tick_rows import tick_labels as _tick_labels

    obstacles = np.array([10, 25, 50, 100, 200, 350, 500.0])
    at = np.array([0, 50, 90, 130, 160, 180, 200.0])  # 100 and 200 30 px apart: 36 needed for two 3-digit labels
    assert _tick_labels(obstacles, at, 8.0) == ["10", "25", "50", "100", "", "", "500"]
    batch = np.array([1, 10, 100, 1000, 10000.0])
    assert _tick_labels(batch, np.arange(5) * 50.0, 8.0) == ["1", "10", "100", "1k", "10k"]  # 1,000: 56 px needed
    assert _tick_labels(batch, np.arange(5) * 30.0, 8.0) == ["1", "10", "", "", "10k"]  # short, and still crowded
    assert _tick_labels(batch, np.arange(5) * 60.0, 8.0) == ["1", "10", "100", "1,000", "10,000"]


def test_the_drawn_tick_labels_keep_apart():
    """docs/crossover.png's obstacle panel: its chosen counts named (reader r39g: all seven took two rows; reader
    r29f: 350 and 500 touched level), slanted where level labels would crowd (reader r10a: 100, 200 and 500
    crowded), each a line's height or more from the next."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    values = [10, 25, 50, 100, 200, 350, 500]
    sweep = {**SWEEP, "values": values, **{k: list(np.linspace(1, 2, 7)) for k in ("exact_us", "fcl_us")}}
    sweep["learned_us"] = list(np.linspace(1.5, 1.6, 7))
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": sweep}})
    fig.set_dpi(110)
    FigureCanvasAgg(fig).draw()
    ax = fig.axes[0]
    named = [t for t in ax.get_xticklabels() if t.get_text()]
    chosen = TICKS["obstacles"]
    assert [t.get_text() for t in named] == [f"{v}" for v in chosen]  # one row: no label a line lower
    if named[0].get_rotation() == 0:  # level: no two closer than a digit and a half
        boxes = [t.get_window_extent() for t in named]
        digit = 9 * 110 / 72 * 0.6
        assert all(right.x0 - left.x1 >= 1.5 * digit for left, right in zip(boxes, boxes[1:]))
    else:  # slanted, where level labels would crowd: a line's height apart along the axis or more
        line = named[0].get_fontsize() * 110 / 72
        at = sorted(ax.transData.transform([(v, 1) for v in chosen])[:, 0])
        assert all(right - left >= line for left, right in zip(at, at[1:]))
    assert sorted(ax.get_xticks()) == list(chosen) and not len(ax.get_xticks(minor=True))


def test_the_decade_where_curves_cross_has_numbers_and_a_crossing_says_what_it_counts():
    crossing = {**SWEEP, "exact_us": [0.2, 0.3, 0.5, 0.8], "learned_us": [0.6, 0.5, 0.45, 0.4]}
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": crossing}})
    ax = fig.axes[0]
    shown = {t.get_text() for t in ax.get_yticklabels()}
    assert {"0.2", "0.5", "1"} <= shown  # 0.2 to 0.8: the crossing's decade is labelled in plain numbers
    # log(exact / learned) is log(0.3 / 0.5) at 100 and log(0.5 / 0.45) at 1,000: 0 at 10 ** (2 + 0.8292), log-log
    t = np.log(0.6) / (np.log(0.6) - np.log(0.5 / 0.45))
    assert [t.get_text() for t in ax.texts] == [f"about {10 ** (2 + t):,.0f} obstacles"] == ["about 675 obstacles"]
    assert "the curves cross (dotted)" in legend_texts(fig)
    assert not any(line.get_clip_on() for line in ax.lines if line.get_marker() not in ("None", "")), "edge marks"


def test_every_crossing_is_marked_and_said_each_label_apart():
    """Reader r10a: the batch curves cross twice and one dotted line showed. The network's curve crosses the exact
    one between 10 and 100 (dearer, then cheaper) and again between 1,000 and 10,000: two dotted lines, two labels
    that do not overlap, both values in the description; python-fcl's curve, never crossed, has none."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    twice = {**SWEEP, "exact_us": [1.0, 1.0, 1.0, 1.0], "learned_us": [2.0, 0.5, 0.5, 2.0]}
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": twice}})
    FigureCanvasAgg(fig).draw()
    ax = fig.axes[0]
    dotted = [line.get_xdata()[0] for line in ax.lines if line.get_linestyle() == ":"]
    assert np.allclose(dotted, [10**1.5, 10**3.5])  # halfway, log-log, where log 2 meets log 0.5
    first, second = (t.get_window_extent() for t in ax.texts)
    assert [t.get_text() for t in ax.texts] == ["about 32 obstacles", "about 3,162 obstacles"]  # a count: whole
    assert first.y1 <= second.y0 or second.y1 <= first.y0 or first.x1 <= second.x0 or second.x1 <= first.x0
    assert "crosses the exact, default (compiled) one at 31.6 and at 3,160." in str(alt.details(fig))  # short names


def test_the_recorded_crossover_names_every_measured_value():
    """docs/crossover.json drawn as docs/crossover.png: every panel names every value it measured (reader r20d: the
    1,280-triangle point had no number), but the obstacles' its chosen ones (reader r29f: 350 touched 500), the rest
    no tick (reader r30f), slanted where level labels would crowd."""
    import json

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    recorded = json.loads((Path(__file__).resolve().parents[1] / "docs" / "crossover.json").read_text())
    fig = crossover(recorded)
    fig.set_dpi(110)
    FigureCanvasAgg(fig).draw()
    slanted = two_rows = 0
    for ax, (key, sweep) in zip(fig.axes, recorded["variables"].items()):
        named = [t for t in ax.get_xticklabels() if t.get_text()]
        for row in (0, 1):  # reader r36g: level in two rows where one crowds; on each row no two labels touch
            boxes = [t.get_window_extent() for t in named if t.get_text().count("\n") == row]
            assert all(right.x0 > left.x1 for left, right in zip(boxes, boxes[1:])), (sweep["label"], row)
        two_rows += any(t.get_text().startswith("\n") for t in named)
        assert len(named) == len(TICKS.get(key, sweep["values"])), sweep["label"]
        assert len(ax.get_xticks()) + len(ax.get_xticks(minor=True)) == len(named)  # no tick without a name
        slanted += named[0].get_rotation() == SLANT
        low, high = np.log10(ax.get_ylim())  # reader r27f: the 20-triangle network point sat half on the lower frame
        costs = np.log10([v for k in ("exact_us", "fcl_us", "learned_us") for v in sweep[k]])
        assert low + 0.1 <= costs.min() and costs.max() <= high - 0.1, sweep["label"]
    # reader r39g: the chosen ticks on one level row each (two rows looked misplaced; r36g: slanted, they read as one)
    assert two_rows == 0 and slanted == 0
    title = fig.get_suptitle()  # reader r27f: no hatching named where none is drawn; the network's size named
    assert "hatched" not in title and "a paper-size network" in title
    # reader r40g: the legend inside the figure, in larger type than the ticks; the shading's one panel named in it;
    # every panel names its y axis. Reader r42g: above the panels, under the title (below them, the top panels sat a
    # screen before their key)
    assert "shaded: network cheaper by > 25% (mesh panel only)" in legend_texts(fig)
    legend = fig.legends[0].get_window_extent()
    assert legend.y0 > max(ax.get_tightbbox().y1 for ax in fig.axes) and legend.width <= fig.bbox.width
    assert legend.y1 < fig._suptitle.get_window_extent().y0  # under the title, not over it
    assert fig.legends[0].get_texts()[0].get_fontsize() > TICK_POINTS
    assert {ax.get_ylabel() for ax in fig.axes} == {"µs per configuration"}


def test_a_3dc_sweep_marks_where_the_paper_s_scenes_sit():
    """Reader r29f: nothing marked the paper's 110-125 blocks or its chains of 2 and 4 links; a grey strip now does,
    on a 3DC scenario's obstacle and link panels, and only where the sweep reaches them."""
    links = {**SWEEP, "label": "links of the robot (box chain)", "values": [2, 4, 6, 10]}
    sweeps = {"obstacles": {**SWEEP, "values": [10, 100, 200, 500]}, "links": links}

    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": sweeps})
    legend = legend_texts(fig)
    assert PAPER_LEGEND in legend and "Plain grey strips mark the paper's 3DC scenes" in alt_text(fig)
    spans = [(p.get_x(), p.get_x() + p.get_width()) for ax in fig.axes for p in ax.patches]  # each strip's x-extent
    assert [(round(low * 1.05), round(high / 1.05)) for low, high in spans] == [(110, 125), (2, 2), (4, 4)]
    plain = crossover({"scenario": "2ds", "preset": "paper", "quick": False, "variables": sweeps})
    assert not [p for ax in plain.axes for p in ax.patches] and "Grey strips" not in alt_text(plain)
    short = crossover({"scenario": "3dc7", "preset": "paper", "quick": False, "variables": {"obstacles": SWEEP}})
    assert len([p for ax in short.axes for p in ax.patches]) == 1  # 10 to 10,000 blocks: the strip inside


def test_the_mesh_panel_of_a_3dc_sweep_says_the_paper_s_scenes_hold_no_mesh():
    """Reader r32g: the whole mesh panel is shaded and nothing said the paper's scenes hold no mesh."""
    mesh = {**SWEEP, "label": "triangles of the mesh obstacle"}
    both = {"obstacles": {**SWEEP, "values": [10, 100, 200, 500]}, "triangles": mesh}
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": both})
    assert fig.axes[1].get_title() == "Mesh (paper scenes: no mesh)" and "they hold no mesh" in alt_text(fig)
    plain = crossover({"scenario": "2ds", "preset": "paper", "quick": False, "variables": {"triangles": mesh}})
    assert "paper scenes" not in plain.axes[0].get_title()


def test_the_call_size_panel_marks_our_planners_calls():
    """Reader r30f: the text says a planner asks for tens to a few hundred configurations a call; the call-size panel
    of a 3DC sweep now shows where (:data:`PLANNER_CALLS`, a grey strip named at its top), and says it in words."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    batch = {**SWEEP, "label": "configurations per call", "values": [1, 10, 100, 1000, 10000]}
    batch.update({k: [1.0, 1.0, 1.0, 1.0, 1.0] for k in ("exact_us", "fcl_us")}, learned_us=[2.0] * 5)
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"batch": batch}})
    ax = fig.axes[0]
    assert [(p.get_x(), p.get_x() + p.get_width()) for p in ax.patches] == [PLANNER_CALLS]
    assert CALLS_NAME in [t.get_text() for t in ax.texts]
    assert CALLS_LEGEND in legend_texts(fig)
    # reader r31f: two grey strips of one colour meant two things; the planner calls' is dotted, said in its legend
    assert ax.patches[0].get_hatch() == ".." and CALLS_LEGEND.startswith("dotted strip")
    # reader r32g: the strip's name sat on its dots; the strip stops below the name now
    FigureCanvasAgg(fig).draw()
    name = next(t for t in ax.texts if t.get_text() == CALLS_NAME).get_window_extent()
    assert name.y0 >= ax.patches[0].get_window_extent().y1
    assert PAPER_LEGEND.startswith("plain grey strip") and "a dotted strip marks a round's samples" in alt_text(fig)
    low, high = PLANNER_CALLS
    assert f"{CALLS_NAME} in 3DC, the calls a network answers: {low} to {high} configurations" in alt_text(fig)
    assert CALLS_NAME in CALLS_LEGEND and (low, high) == (50, 400)  # reader r34g: no RRT-Connect sizes, one name
    plain = crossover({"scenario": "2ds", "preset": "paper", "quick": False, "variables": {"batch": batch}})
    assert not plain.axes[0].patches and CALLS_NAME not in alt_text(plain)


def test_the_recorded_figure_names_only_decades_on_its_widest_panels():
    """Reader r33g: the mesh panel's 1 / 0.5 / 0.2 and the call-size panel's 0.2 / 0.1 / 0.05 crowded; those two panels
    (four decades and more) name only decades now, the obstacles' and the links' (under 3.5) keep 0.2 and 0.5; the
    network's triangles are no larger than the compiled check's circles, so they hide no value."""
    import json

    from toolkit.plots.crossover import MARKS

    recorded = json.loads((Path(__file__).resolve().parents[1] / "docs" / "crossover.json").read_text())
    fig = crossover(recorded)
    named = {ax.get_title(): {t.get_text() for t in ax.get_yticklabels()} for ax in fig.axes if ax.get_visible()}
    wide = [title for title, labels in named.items() if not {"0.2", "0.5"} & labels]
    assert sorted(wide) == ["Call size", "Mesh (paper scenes: no mesh)"], named
    assert MARKS["learned"]["markersize"] <= MARKS["exact"]["markersize"]
