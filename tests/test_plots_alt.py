"""Text alternatives of figures (:mod:`toolkit.plots.alt`): said from the data, read from titles otherwise, and
attached to a displayed figure as Jupyter's ``image/png`` ``alt`` metadata."""

from __future__ import annotations

import numpy as np
import pytest
from IPython.core.interactiveshell import InteractiveShell
from matplotlib.figure import Figure

from toolkit.geometry import robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.planning.prm import PlanStep
from toolkit.plots import alt, cspace, planning, slices


@pytest.fixture
def one_block():
    """A 20 x 20 world with one 4 x 4 block, and the point robot."""
    ws = Workspace(np.zeros(2), np.full(2, 20.0), np.array([[[8.0, 8.0], [12.0, 12.0]]]), family="test")
    return exact_checker(ws, robots.point_robot())


def test_a_description_is_kept_and_a_figure_without_one_is_read_from_its_titles():
    fig = Figure()
    ax = fig.subplots()
    ax.set(title="validity", xlabel="x", ylabel="y")
    fig.suptitle("two panels")
    assert alt.alt_text(fig) == "Figure with 1 panel(s): two panels; validity, x: x, y: y"
    assert alt.alt_text(alt.describe(fig, "  the  picture\n of a square ")) == "the picture of a square"
    assert alt.metadata(fig) == ({}, {"image/png": {"alt": "the picture of a square"}})
    with pytest.raises(ValueError, match="must say something"):
        alt.describe(fig, " ")


def test_the_cspace_image_says_what_share_is_in_collision(one_block):
    fig = cspace.cspace_image(one_block, resolution=200)
    _, _, Q = slices.slice_configs(one_block.robot, one_block.robot.lower, (0, 1), resolution=200)  # (n, n, 2)
    share = 1 - one_block.are_valid(Q.reshape(-1, 2)).mean()
    assert 0 < share < 1
    assert alt.alt_text(fig) == (
        f"Configuration space of the 2D point robot in the test workspace: {share:.0%} of configurations in "
        "collision, drawn dark; the workspace's blocks outlined inside them."
    )


def test_a_roadmap_step_is_said_in_words(one_block):
    nodes = np.array([[1.0, 1.0], [18.0, 18.0], [10.0, 10.0]])
    step = PlanStep(
        round=1,
        stage="candidate",
        nodes=nodes,
        edges=np.array([[0, 2], [2, 1]]),
        node_verified=np.array([True, True, False]),
        new_nodes=np.array([], dtype=int),
        path=np.array([0, 2, 1]),
        removed_nodes=np.array([], dtype=int),
        removed_edges=np.array([], dtype=int),
    )
    text = alt.alt_text(planning.roadmap(one_block, step))
    assert text == (
        "Round 1, candidate: a roadmap of 3 nodes (2 confirmed exactly) and 2 edges over the C-obstacles; a dashed "
        "path through 3 nodes."
    )


def test_a_displayed_figure_carries_its_alt_text_in_ipython():
    shell = InteractiveShell.instance()
    try:
        assert alt.register()
        fig = alt.describe(Figure(), "an empty figure")
        _, metadata = shell.display_formatter.format(fig)
        assert metadata["image/png"] == {"alt": "an empty figure"}
    finally:
        InteractiveShell.clear_instance()
    assert not alt.register()  # no shell, nothing to register with


def test_a_map_is_read_region_by_region_top_row_first():
    values = np.arange(16.0).reshape(4, 4)  # [x, y]: x across, y up
    part = alt.map_part("m", "a map", values.shape, ("a", 0, 8), ("b", -1, 1), lambda r: f"{values[r].sum():g}", 2)
    assert part.columns == ("rows: b, top first; columns: a", "a 0 to 4", "a 4 to 8")
    # the top row holds y = 2, 3 (b 0 to 1): x = 0, 1 there sum 2 + 3 + 6 + 7, x = 2, 3 sum 10 + 11 + 14 + 15
    assert part.rows == (("b 0 to 1", "18", "50"), ("b -1 to 0", "10", "42"))


def test_a_part_is_plain_words_and_a_whole_table():
    with pytest.raises(ValueError, match="not TeX"):
        alt.Part("norm", r"$\|z\|$")
    with pytest.raises(ValueError, match="one cell per column"):
        alt.Part("t", "", ("a", "b"), (("1",),))


def test_labelled_lines_become_a_table_at_the_first_lines_x_values():
    fig = Figure()
    ax = fig.subplots()
    ax.plot([1, 2, 3], [10, 20, 30], label="one")
    ax.plot([1, 3], [5, 7], label="two")  # read at its nearest x
    ax.plot([1, 3], [0, 0], label="_hidden")
    ax.set(xlabel="cells flipped", ylabel="moved")
    part = alt.lines_part(ax, "moves")
    assert part == alt.Part(
        "moves",
        "moved against cells flipped",
        ("cells flipped", "one", "two"),
        (("1", "10", "5"), ("2", "20", "5"), ("3", "30", "7")),
    )


def test_a_figure_of_several_panels_without_a_longer_description_gets_the_guards():
    fig = Figure()
    left, right = fig.subplots(1, 2)
    left.set_title("input")
    right.set_title("decoded")
    alt.describe(fig, "two grids, 3 cells apart")
    (guard,) = alt.details(fig)
    assert alt.is_fallback(guard["name"]) and guard["text"] == "input; decoded"
    one = Figure()
    one.colorbar(one.subplots().imshow(np.eye(2)))  # a colour bar is no panel
    assert alt.panels(one) == 1 and alt.details(one) == []
    part = alt.Part("input", "3 blocks")
    alt.describe(fig, "two grids, 3 cells apart", [part])
    assert alt.metadata(fig) == (
        {},
        {
            "image/png": {
                "alt": "two grids, 3 cells apart",
                "details": [dict(name="input", text="3 blocks", columns=[], rows=[])],
            }
        },
    )


def test_a_still_picture_carries_its_alt_and_its_longer_description_under_it():
    fig = Figure()
    fig.subplots(1, 2)
    alt.describe(fig, "two grids", [alt.Part("left", "3 <blocks>", ("block", "x"), (("1", "2"),))])
    shown = alt.figure_html(fig, "iVBORw0KGgo=", style="max-width:100%")
    assert shown.startswith(
        f'<img src="data:image/png;base64,iVBORw0KGgo=" alt="two grids {alt.DESCRIBED_BELOW}" style="max-width:100%">'
        f'\n<details class="figure-described"><summary>{alt.DESCRIBED}</summary>'
    )
    assert '<p><strong>left</strong>: 3 &lt;blocks&gt;</p><div class="figure-described-table" role="region"' in shown
    assert '<table><caption>left</caption><thead><tr><th scope="col">block</th>' in shown
    assert (
        alt.figure_html(alt.describe(Figure(), "a point"), "AA==")
        == '<img src="data:image/png;base64,AA==" alt="a point">'
    )
