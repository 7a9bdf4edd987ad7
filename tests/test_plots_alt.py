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
        "path through 3 nodes; a repair removed 0 nodes and 0 edges."
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
