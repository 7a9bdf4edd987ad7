"""A still's close-up of the robot (notebook 05): seen across the plane the chain spreads in, its links opaque over
faded blocks, its joints marked where two links meet, the blocks near it darker; overview marks large enough to
tell a circle from a diamond as the site shows them."""

import numpy as np
import pytest
from matplotlib.figure import Figure
from matplotlib.markers import MarkerStyle

from toolkit import scenarios
from toolkit.geometry.workspace import Workspace
from toolkit.plots import still_panels
from toolkit.plots.alt import alt_text
from toolkit.plots.robot_drawing import VALID_COLOR

CHAIN7, CHAIN9 = scenarios.get("3dc7").robot, scenarios.get("3dc9").robot


def _camera(ax) -> np.ndarray:
    """``(3,)`` the unit direction from the scene to the 3D axes' camera, from its elevation and azimuth."""
    e, a = np.deg2rad([ax.elev, ax.azim])
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def _close_up(robot, q, workspace, **kwargs):
    ax = Figure().add_subplot(projection="3d")
    near, angles = still_panels.close_up(ax, robot, np.asarray(q, float), workspace, color=VALID_COLOR, **kwargs)
    return ax, near, angles


EMPTY = Workspace(np.zeros(3), np.full(3, 11.0), np.zeros((0, 2, 3)), family="3dc")


def test_a_chain_bent_in_a_vertical_plane_is_seen_square_to_that_plane():
    """3DC-9 turned a quarter about x (gamma = pi/2), its two joints about the links' z bent, the one about y
    straight: the chain bends in the world's x-z plane, whose normal is y. The camera looks along y, as low as the
    close-up lets it (15 degrees up)."""
    q = np.array([5.0, 5.0, 5.0, 0.0, 0.0, np.pi / 2, 1.0, 0.0, 1.0])
    centres = CHAIN9.link_boxes(q[None])[0][0]  # (4, 3)
    assert np.allclose(centres[:, 1], 5.0)  # every link in the plane y = 5: the premise
    ax, _, (elevation, azimuth) = _close_up(CHAIN9, q, EMPTY, margin=0.5)
    assert (ax.elev, ax.azim) == (elevation, azimuth)
    assert elevation == still_panels.ELEVATION[0]
    assert azimuth == pytest.approx(-90.0 + still_panels.OFF_AXIS)  # on the usual side (-60), kept off the y axis


def test_a_straight_chain_is_seen_square_to_it_from_thirty_degrees_up():
    q = np.array([5.0, 5.0, 5.0, 0.7, 0.0, 0.0, 0.0, 0.0, 0.0])  # straight, turned 0.7 rad (40 degrees) about z
    along = np.array([np.cos(0.7), np.sin(0.7), 0.0])
    ax, _, _ = _close_up(CHAIN9, q, EMPTY, margin=0.5)
    assert _camera(ax) @ along == pytest.approx(0.0, abs=1e-9)  # 130 or -50 degrees: off every axis as it is
    assert ax.elev == pytest.approx(30.0) and ax.azim == pytest.approx(np.rad2deg(0.7) - 90.0)  # the usual side
    along_x, _, _ = _close_up(CHAIN9, np.array([5.0, 5.0, 5.0, 0, 0, 0, 0, 0, 0]), EMPTY, margin=0.5)
    assert along_x.azim == pytest.approx(-90.0 + still_panels.OFF_AXIS)  # not straight along y: its ticks would pile


def test_the_joints_are_marked_where_two_links_meet_and_drawn_over_the_links_over_the_blocks():
    q = np.array([5.0, 5.0, 5.0, 0.3, -0.4, 0.5, 1.2, -1.0, 1.2])
    centres, rotations, half = CHAIN9.link_boxes(q[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    block = np.array([[[5.2, 4.2, 4.2], [6.2, 4.8, 4.8]]])  # under the chain's start
    ax, _, _ = _close_up(CHAIN9, q, Workspace(np.zeros(3), np.full(3, 11.0), block, family="3dc"), margin=0.6)
    (joints,) = [c for c in ax.collections if c.get_label() == "joint"]
    marked = np.array(joints._offsets3d).T  # (L - 1, 3)
    assert len(marked) == CHAIN9.n_links - 1
    for k, point in enumerate(marked):  # on the surface of link k and of link k + 1: where they meet
        for link in (k, k + 1):
            local = np.abs(rotations[0, link].T @ (point - centres[0, link]))  # (3,) in the link's frame
            assert np.all(local <= half[link] + 1e-9) and np.any(np.isclose(local, half[link]))
    links = [c for c in ax.collections if c.get_gid() == "link"]
    assert not ax.computed_zorder and len(links) == CHAIN9.n_links
    assert max(c.get_zorder() for c in links) < joints.get_zorder()
    assert {c.get_alpha() for c in links} == {1.0}


def test_a_block_between_the_robot_and_the_camera_is_drawn_over_it_faded_one_behind_under_it():
    """mplot3d has no depth buffer: drawn always under the robot, a block in front of it made a free robot look
    inside the block (a quarter-turn view in chapter 05). Each block goes in front of the links or behind them by
    where it stands: 2 units toward the camera from the robot's middle, or 2 units away."""
    q = np.array([5.5, 5.5, 5.5, 0.0, 0.0, 0.0, 0.0])  # 3DC-7, straight along x
    ax = Figure().add_subplot(projection="3d")
    elevation, azimuth = still_panels.view_angles(CHAIN7, q)
    e, a = np.deg2rad([elevation, azimuth])
    toward = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])  # (3,) to the camera
    middle = CHAIN7.link_boxes(q[None])[0][0].mean(axis=0)  # (3,)
    blocks = np.array([[c - 0.25, c + 0.25] for c in (middle + 0.6 * toward, middle - 0.6 * toward)])  # (2, 2, 3)
    workspace = Workspace(np.zeros(3), np.full(3, 11.0), blocks, family="3dc")
    still_panels.close_up(ax, CHAIN7, q, workspace, color=VALID_COLOR, margin=1.0, turns=(0.0,))  # not turned
    links = [c.get_zorder() for c in ax.collections if c.get_gid() == "link"]
    front, back = sorted((c for c in ax.collections if c.get_gid() == "block"), key=lambda c: -c.get_zorder())
    assert back.get_zorder() < min(links) and max(links) < front.get_zorder()
    corners = front._faces.reshape(-1, 3)  # (24, 3) its faces' corners (mplot3d has no public getter)
    assert np.allclose(corners.mean(axis=0), middle + 0.6 * toward)  # the one toward the camera is the one in front
    assert front.get_alpha() < 0.5  # faded: the robot shows through it


def test_a_close_up_turns_its_camera_round_where_a_block_stands_between_it_and_the_robot():
    """Reader r33e: chapter 05's goal close-up drew the chain through a faded block in front of it, and it looked
    inside the block. Where turning the camera half round clears every line of sight, the close-up turns it."""
    q = np.array([5.5, 5.5, 5.5, 0.0, 0.0, 0.0, 0.0])  # 3DC-7, straight along x
    elevation, azimuth = still_panels.view_angles(CHAIN7, q)
    middle = CHAIN7.link_boxes(q[None])[0][0].mean(axis=0)  # (3,)
    centre = middle + 0.6 * still_panels._toward_camera(elevation, azimuth)  # (3,) a block toward the camera
    workspace = Workspace(np.zeros(3), np.full(3, 11.0), np.array([[centre - 0.25, centre + 0.25]]), family="3dc")
    ax, _, angles = _close_up(CHAIN7, q, workspace, margin=1.0)
    assert angles == (elevation, azimuth + 180.0)
    links = [c.get_zorder() for c in ax.collections if c.get_gid() == "link"]
    assert all(c.get_zorder() < min(links) for c in ax.collections if c.get_gid() == "block")  # behind it now


def test_blocks_near_a_link_are_darker_than_the_rest_of_the_window_and_counted():
    q = np.array([5.0, 5.0, 5.0, 0.0, 0.0, 0.0, 0.0])  # 3DC-7 straight along x from (5, 5, 5): its box to x = 5.5
    hi_y = 5.05  # the links' top in y
    blocks = np.array(
        [
            [[5.0, hi_y + 0.2, 4.9], [5.4, hi_y + 0.6, 5.1]],  # 0.2 above the links' box in y: near
            [[5.0, hi_y + 0.5, 4.9], [5.4, hi_y + 0.9, 5.1]],  # 0.5 above: in the window, not near
            [[9.0, 9.0, 9.0], [10.0, 10.0, 10.0]],  # outside the window: not drawn
        ]
    )
    ax, near, _ = _close_up(CHAIN7, q, Workspace(np.zeros(3), np.full(3, 11.0), blocks, family="3dc"), margin=1.0)
    drawn = sorted((c for c in ax.collections if c.get_gid() == "block"), key=lambda c: -c.get_alpha())
    assert near == 1 and len(drawn) == 2
    assert drawn[0].get_alpha() > 2 * drawn[1].get_alpha()
    assert drawn[0].get_linewidth()[0] > drawn[1].get_linewidth()[0]
    corners = drawn[0]._faces.reshape(-1, 3)  # (6 * 4, 3) its faces' corners (mplot3d has no public getter)
    assert np.allclose([corners.min(axis=0), corners.max(axis=0)], blocks[0])  # the darker one is the near one


def test_an_overviews_marks_are_wide_enough_to_tell_a_circle_from_a_diamond_on_the_site():
    """Readers r12b, r13b: the far marks, 4 pixels wide, were told apart by colour alone. As the site shows a still
    (100 dpi, about as wide as drawn), a circle is at least 8 pixels across, a diamond at least as wide, both
    edged in ink, and a diamond covers about as much as a circle (neither kind looks more numerous)."""
    points = np.array([[1.0, 1.0, 1.0], [2.0, 2.0, 2.0]])
    ax = Figure().add_subplot(projection="3d")
    still_panels.draw_points(
        ax, (points, {"valid": np.array([True, False]), "in collision": np.array([False, True])}), None
    )
    marks = {c.get_label(): c for c in ax.collections}
    pixels = {}
    for kind in ("valid", "in collision"):
        mark = marks[f"sample, {kind}"]
        style = MarkerStyle(still_panels.SAMPLE_MARKS[kind][0])
        outline = style.get_path().transformed(style.get_transform()).vertices  # (V, 2) for a size of 1 point
        pixels[kind] = np.ptp(outline[:, 0]) * np.sqrt(mark.get_sizes()[0]) * 100 / 72
        assert mark.get_linewidths()[0] > 0
    assert pixels["valid"] >= 8.0 and pixels["in collision"] >= pixels["valid"]
    circle, diamond = (still_panels.SAMPLE_MARKS[k][2] for k in ("valid", "in collision"))
    assert np.pi / 4 * circle == pytest.approx(diamond, rel=0.05)


def test_a_close_ups_text_counts_the_near_blocks_and_says_how_it_is_seen():
    from toolkit.plots import scenes

    q = np.array([5.0, 5.0, 5.0, 0.0, 0.0, 0.0, 0.0])
    blocks = np.array([[[5.0, 5.25, 4.9], [5.4, 5.65, 5.1]]])
    fig = scenes.scene_still(CHAIN7, Workspace(np.zeros(3), np.full(3, 11.0), blocks, family="3dc"), {"the chain": q})
    assert "seen across the plane it spreads in, its links opaque" in alt_text(fig)  # reader r31e: seen once
    assert "turn round" not in alt_text(fig)
    assert "the blocks within 0.3 of a link darker (1 block near the chain)" in alt_text(fig)


def test_an_overview_draws_the_whole_robot_over_light_marks_its_name_above_it():
    """Reader r14b: the overview marked only the base with a square, under 500 marks, so the chain's place among the
    blocks was not visible. Now its links are drawn end to end, each along its longest axis, in the robot's colour,
    ringed, over the samples; the samples light; the blocks near the robot darker; its name above it."""
    q = np.array([5.0, 5.0, 5.0, 0.3, -0.4, 0.5, 1.2, -1.0, 1.2])
    centres, rotations, half = CHAIN9.link_boxes(q[None])  # (1, L, 3), (1, L, 3, 3), (L, 3)
    block = np.array([[[5.2, 4.2, 3.9], [6.2, 4.8, 4.8]], [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]])  # near it; far away
    workspace = Workspace(np.zeros(3), np.full(3, 11.0), block, family="3dc")
    points = np.array([[2.0, 2.0, 2.0], [8.0, 8.0, 8.0]])
    samples = (points, {"valid": np.array([True, False]), "in collision": np.array([False, True])})
    ax = Figure().add_subplot(projection="3d")
    still_panels.overview(ax, CHAIN9, workspace, {"the robot": (q, VALID_COLOR)}, samples, None)
    (robot,) = [line for line in ax.get_lines() if line.get_gid() == "robot"]
    drawn = np.array(robot.get_data_3d()).T  # (2 L, 3): each link's two ends
    assert len(drawn) == 2 * CHAIN9.n_links
    for link, (a, b) in enumerate(drawn.reshape(-1, 2, 3)):
        assert np.allclose((a + b) / 2, centres[0, link])  # through the link's centre
        assert np.linalg.norm(b - a) == pytest.approx(2 * half[link].max())  # as long as the link
        local = np.abs(rotations[0, link].T @ (b - a))  # (3,) along the link's longest axis
        assert local.argmax() == half[link].argmax() and np.allclose(np.delete(local, local.argmax()), 0.0)
    assert robot.get_color() == VALID_COLOR and robot.get_linewidth() >= 3.0 and robot.get_path_effects()
    marks = [c for c in ax.collections if (c.get_label() or "").startswith("sample")]
    assert marks and all(c.get_alpha() <= 0.5 and c.get_zorder() < robot.get_zorder() for c in marks)
    (label,) = [t for t in ax.texts if t.get_gid() == "pose label"]
    assert label.get_text() == "the robot" and label.get_position_3d()[2] > CHAIN9.link_aabbs(q[None])[0][:, 1, 2].max()
    near, far = [c for c in ax.collections if c.get_gid() == "block"]
    assert near.get_alpha() > far.get_alpha()  # the block by the robot darker than the one in the corner
