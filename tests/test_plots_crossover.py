"""The crossover figure shades what its verdicts call "network cheaper", and nothing the list calls "can't tell"."""

import numpy as np
from matplotlib.collections import PolyCollection

from toolkit.plots.alt import alt_text
from toolkit.plots.crossover import crossover

SWEEP = {  # network / exact: 0.5 cheaper, 0.9 can't tell, 1.5 dearer, 0.7 cheaper (the band is 25 %)
    "label": "obstacles per workspace (unit blocks)",
    "values": [10, 100, 1000, 10000],
    "exact_us": [2.0, 1.0, 1.0, 1.0],
    "fcl_us": [9.0, 9.0, 9.0, 9.0],
    "learned_us": [1.0, 0.9, 1.5, 0.7],
    "crossing": {"exact": None, "fcl": None},
}


def shaded_spans(ax) -> list[tuple[float, float]]:
    """The x-extent of each shaded band of a panel (in data units, rounded)."""
    bands = [c for c in ax.collections if isinstance(c, PolyCollection)]
    xs = [np.asarray(b.get_paths()[0].vertices)[:, 0] for b in bands]  # each band's outline, x only
    return [(round(float(x.min()), 3), round(float(x.max()), 3)) for x in xs]


def test_only_the_points_whose_verdict_is_network_cheaper_are_shaded():
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": SWEEP}})
    ax = fig.axes[0]
    # a band round 10 (from 10 / sqrt(10) to sqrt(10 * 100)) and one round 10,000 (from sqrt(1e3 * 1e4) on)
    assert shaded_spans(ax) == [
        (round(10 / np.sqrt(10), 3), round(np.sqrt(1000), 3)),
        (round(np.sqrt(1e7), 3), round(1e4 * np.sqrt(10), 3)),
    ]
    assert [t.get_text() for t in fig.legends[0].get_texts()][-1] == "network cheaper by > 25%"
    assert "cheaper by more than 25% at 10, 10,000." in alt_text(fig)


def test_a_panel_where_the_network_is_never_cheaper_beyond_the_band_has_no_shading():
    close = {**SWEEP, "learned_us": [1.8, 0.9, 1.2, 1.1]}  # 0.9, 0.9, 1.2, 1.1: all within 25 %
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": close}})
    assert shaded_spans(fig.axes[0]) == []
    assert "never cheaper by more than 25%." in alt_text(fig)


def test_a_tick_label_that_would_touch_its_neighbour_is_left_out_and_the_last_is_always_named():
    from toolkit.plots.crossover import _tick_labels

    assert _tick_labels(np.array([10, 25, 50, 100, 200, 350, 500.0])) == ["10", "25", "50", "100", "200", "", "500"]
    assert _tick_labels(np.array([1, 10, 100, 1000, 10000.0])) == ["1", "10", "100", "1,000", "10,000"]


def test_the_decade_where_curves_cross_has_numbers_and_a_crossing_says_what_it_counts():
    crossing = {**SWEEP, "exact_us": [0.2, 0.3, 0.5, 0.8], "learned_us": [0.6, 0.5, 0.45, 0.4]}
    crossing["crossing"] = {"exact": {"value": 243.0}, "fcl": None}
    fig = crossover({"scenario": "3dc9", "preset": "paper", "quick": False, "variables": {"obstacles": crossing}})
    ax = fig.axes[0]
    shown = {t.get_text() for t in ax.get_yticklabels()}
    assert {"0.2", "0.5", "1"} <= shown  # 0.2 to 0.8: the crossing's decade is labelled in plain numbers
    assert [t.get_text() for t in ax.texts] == ["243 obstacles"]  # a number with what it counts
    assert "the curves cross (dotted)" in [t.get_text() for t in fig.legends[0].get_texts()]
    assert not any(line.get_clip_on() for line in ax.lines if line.get_marker() not in ("None", "")), "edge marks"
