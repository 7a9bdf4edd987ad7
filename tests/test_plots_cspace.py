"""Notebook 01's figures draw what the geometry says: blocks, grids, link boxes and C-obstacles.

The C-space images are held against checkers other than the one that drew them
(python-fcl against the numpy point-robot check, the separating-axis reference
against python-fcl), so a figure that drew the wrong cells would fail.
"""

import numpy as np
import pytest
from matplotlib.colors import rgb_to_hsv, to_hex, to_rgba
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon, Rectangle
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from toolkit import scenarios
from toolkit.geometry import robots
from toolkit.geometry.collision import (
    CollisionChecker,
    FCLChecker,
    PointRobotChecker,
    SeparatingAxisChecker,
    exact_checker,
)
from toolkit.geometry.workspace import Workspace
from toolkit.plots import boxes, contact, cspace, near_blocks, palette, robot_drawing, slices, verdict
from toolkit.plots.alt import alt_text, parts_of
from toolkit.plots.robot_drawing import KEY_COLORS


@pytest.fixture
def square_world():
    """31x31 with two blocks: [10, 12]^2 and [20, 25] x [3, 9]."""
    return Workspace(
        np.zeros(2),
        np.array([31.0, 31.0]),
        np.array([[[10, 10], [12, 12]], [[20, 3], [25, 9]]], dtype=float),
        family="2ds",
    )


@pytest.fixture
def clutter():
    return scenarios.get("3dc7").make_workspace(np.random.default_rng(3))


def _patches(ax, gid):
    return [p for p in ax.patches if p.get_gid() == gid]


def _image(fig, panel=0):
    return np.asarray(fig.axes[panel].images[0].get_array())


class RecordedPolys(Poly3DCollection):
    """A ``Poly3DCollection`` that keeps the 3D faces it was made of (matplotlib keeps them only privately)."""

    def __init__(self, verts, *args, **kwargs):
        super().__init__(verts, *args, **kwargs)
        self.faces3d = np.asarray(verts, dtype=float)  # (faces, corners, 3)


@pytest.fixture
def recorded_polys(monkeypatch):
    """The 3D boxes the figures draw, recorded with their faces."""
    monkeypatch.setattr(boxes, "Poly3DCollection", RecordedPolys)


# -- boxes ------------------------------------------------------------------------------


def test_corner_k_lies_on_the_plus_side_of_axis_a_where_bit_d_minus_1_minus_a_of_k_is_set():
    signs = boxes.corner_signs(3)  # (8, 3)
    for k, corner in enumerate(signs):
        np.testing.assert_array_equal(corner, [1.0 if k >> (2 - a) & 1 else -1.0 for a in range(3)])


def test_the_faces_are_the_six_sides_of_a_box_each_once_its_corners_in_order_around_it():
    signs = boxes.corner_signs(3)  # (8, 3)
    sides = set()
    for face in boxes.FACES:  # (4,) corner indices
        corners = signs[face]  # (4, 3)
        (axis,) = np.flatnonzero(np.ptp(corners, axis=0) == 0)  # the one axis the face does not span
        sides.add((int(axis), float(corners[0, axis])))
        around = np.abs(corners - np.roll(corners, 1, axis=0)).sum(axis=1)  # (4,) to the previous corner
        np.testing.assert_array_equal(around, 2.0)  # one edge of the box each, never a diagonal
    assert sides == {(a, s) for a in range(3) for s in (-1.0, 1.0)}


def test_the_shadow_of_a_box_turned_about_z_is_its_turned_rectangle_in_order_around_it():
    c, s = np.cos(0.3), np.sin(0.3)
    turn = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    corners = boxes.box_corners(np.array([5.0, 2.0, 1.0]), turn, np.array([2.0, 1.0, 0.5]))  # (8, 3)
    np.testing.assert_allclose(corners.mean(axis=0), [5.0, 2.0, 1.0])
    np.testing.assert_allclose(np.linalg.norm(corners - [5.0, 2.0, 1.0], axis=1), np.sqrt(4 + 1 + 0.25))
    shadow = boxes.outline(corners, (0, 1))  # (4, 2): top and bottom faces fall on each other
    expected = boxes.box_corners(np.array([5.0, 2.0]), turn[:2, :2], np.array([2.0, 1.0]))  # (4, 2)
    assert sorted(map(tuple, shadow.round(9))) == sorted(map(tuple, expected.round(9)))
    sides = np.linalg.norm(shadow - np.roll(shadow, 1, axis=0), axis=1)  # (4,)
    np.testing.assert_allclose(np.sort(sides), [2.0, 2.0, 4.0, 4.0])  # the rectangle's sides: no diagonal
    np.testing.assert_allclose(boxes.aabb_corners(np.zeros(2), np.array([2.0, 1.0])), [[0, 0], [0, 1], [2, 0], [2, 1]])


# -- workspaces and grids -------------------------------------------------------------


def test_workspace_figure_2d_draws_one_rectangle_per_block(square_world):
    fig = cspace.workspace_figure(square_world)
    rects = _patches(fig.axes[0], "block")
    assert len(rects) == len(square_world.boxes)
    for rect, (lo, hi) in zip(rects, square_world.boxes):
        assert isinstance(rect, Rectangle)
        np.testing.assert_allclose(rect.get_xy(), lo)
        np.testing.assert_allclose([rect.get_width(), rect.get_height()], hi - lo)
    assert fig.axes[0].get_xlim() == (0.0, 31.0)
    (blocks,) = [part for part in parts_of(fig) if part.name == "blocks"]  # review r31a: one numbering, from 0
    assert [row[0] for row in blocks.rows] == ["0", "1"] and blocks.rows[0][2] == "(10, 10)"


def test_workspace_figure_3d_draws_each_block_at_its_corners(recorded_polys):
    ws = scenarios.get("3do").make_workspace(np.random.default_rng(1))
    fig = cspace.workspace_figure(ws)
    blocks = [c for c in fig.axes[0].collections if c.get_gid() == "block"]
    assert len(blocks) == len(ws.boxes) and all(isinstance(b, RecordedPolys) for b in blocks)
    for block, (lo, hi) in zip(blocks, ws.boxes):
        corners = block.faces3d.reshape(-1, 3)  # (6 faces * 4, 3)
        np.testing.assert_allclose(corners.min(axis=0), lo)
        np.testing.assert_allclose(corners.max(axis=0), hi)
    legend = [t.get_text() for t in fig.legends[0].get_texts()]  # below the view, over no block
    assert legend == sorted(set(ws.labels))
    x, _, z = fig.axes[0].get_box_aspect()  # reader r19b: drawn to scale, the office's 6 high could not be read
    assert z / x == pytest.approx(3 * 6 / 41) and fig.axes[0].get_zlabel() == "z (vertical ×3)"
    assert "heights stretched 3 times against widths" in alt_text(fig)
    # reader r27a: no y tick at the corner where the x and y axes meet; reader r57a: nor x's "40", which stood there
    # alone above the legend
    assert [t.get_text() for t in fig.axes[0].get_xticklabels()] == ["0", "10", "20", "30"]
    assert [t.get_text() for t in fig.axes[0].get_yticklabels()] == ["10", "20", "30", "40"]
    clutter = cspace.workspace_figure(scenarios.get("3dc7").make_workspace(np.random.default_rng(1)))
    assert np.ptp(clutter.axes[0].get_box_aspect()) == pytest.approx(0) and clutter.axes[0].get_zlabel() == "z"
    assert clutter.get_figwidth() < 0.7 * fig.get_figwidth()  # reader r36a: the clutter's cubes filled a screen


def test_occupancy_figure_2d_is_dark_exactly_on_cells_whose_centre_is_in_a_block(square_world):
    image = _image(cspace.occupancy_figure(square_world))  # (y, x)
    centres = square_world.grid_points()  # (31, 31, 2), [x, y]
    expected = np.where(square_world.contains_points(centres), 1.0, -1.0).T
    np.testing.assert_array_equal(image, expected)
    assert image.sum() == 31 * 31 - 2 * (31 * 31 - 2 * 2 - 5 * 6)  # 4 + 30 cells occupied


def ticks_in_view(axis) -> list[float]:
    low, high = sorted(axis.get_view_interval())
    return [t for t in axis.get_majorticklocs() if low - 1e-9 <= t <= high + 1e-9]


def test_occupancy_grids_are_ticked_every_few_cells(square_world, clutter):
    """Reader r8b: the 2DS grid (0 to 31) was ticked at 0 and 20 only. One grid: a tick every 5 or 10 cells at most,
    at least 4 each way; each layer of a 3D grid: at least 3 each way."""
    fig = cspace.occupancy_figure(square_world)
    fig.draw_without_rendering()
    ax = fig.axes[0]
    for axis in (ax.xaxis, ax.yaxis):
        ticks = ticks_in_view(axis)
        assert len(ticks) >= 4 and np.max(np.diff(ticks)) <= 10
    layers = cspace.occupancy_figure(clutter, layers=[2, 7])
    layers.draw_without_rendering()
    assert all(len(ticks_in_view(axis)) >= 3 for ax in layers.axes for axis in (ax.xaxis, ax.yaxis))


def test_occupancy_figure_3d_draws_one_layer_per_z(clutter):
    fig = cspace.occupancy_figure(clutter)
    images = [ax.images[0] for ax in fig.axes]
    assert len(images) == 11
    centres = clutter.grid_points()  # (11, 11, 11, 3)
    for z, image in enumerate(images):
        expected = np.where(clutter.contains_points(centres[:, :, z]), 1.0, -1.0).T
        np.testing.assert_array_equal(np.asarray(image.get_array()), expected)
    assert fig.axes[4].get_title() == "layer z = 4.5"
    chosen = cspace.occupancy_figure(clutter, layers=[2, 7])
    assert [ax.get_title() for ax in chosen.axes] == ["layer z = 2.5", "layer z = 7.5"]


def test_occupancy_figure_rings_each_block_of_a_kind_on_the_layers_it_reaches():
    """Reader r39a: the office's chairs, one cell each of layer z = 0.5, could not be told from other furniture."""
    office = scenarios.get("3do").make_workspace(np.random.default_rng(0))
    chairs = office.boxes[np.array(office.labels) == "chair"]  # (C, 2, 3)
    fig = cspace.occupancy_figure(office, layers=range(4), columns=2, ring="chair")
    rings = [[line for line in ax.get_lines() if line.get_gid() == "ring"] for ax in fig.axes]
    assert [len(r[0].get_xydata()) for r in rings] == [int(np.sum(chairs[:, 1, 2] >= z + 0.5)) for z in range(4)]
    np.testing.assert_allclose(rings[0][0].get_xydata(), chairs[:, :, :2].mean(axis=1))
    assert rings[0][0].get_color() == palette.COLORS["ink"] and len(chairs) > 0  # reader r50a: not the verdict's
    assert rings[0][0].get_path_effects()  # ringed white: seen on a dark cell
    assert fig.get_suptitle().endswith("; each chair ringed")
    assert f"each chair ringed, per image: {len(chairs)}, 0, 0, 0" in alt_text(fig)
    fig.draw_without_rendering()  # two layers a row fill the page's width (were 197 px of 610: 4.8 px a cell)
    assert fig.get_figwidth() == palette.PAGE_WIDTH and all(ax.get_window_extent().width > 240 for ax in fig.axes)


# -- robots ----------------------------------------------------------------------------


@pytest.mark.parametrize("deficiency", [None, "deuteranopia", "protanopia", "tritanopia"])
def test_the_colours_that_tell_links_and_poses_apart_are_never_the_verdicts_and_stay_apart(deficiency):
    """Reader r50a: chain7's link 1 orange over its blue link 0, where the text says overlap is no collision; orange
    means "in collision" on every figure of chapter 01. Every two key colours stay apart in each colour vision."""
    from test_palette import ciede2000, seen_as

    assert not set(KEY_COLORS) & {palette.COLORS["valid"], palette.COLORS["invalid"], palette.OKABE_ITO["orange"]}
    assert not set(KEY_COLORS) & {palette.OKABE_ITO["blue"], palette.OKABE_ITO["sky blue"]}
    seen = seen_as(list(KEY_COLORS), deficiency)
    assert min(ciede2000(a, b) for i, a in enumerate(seen) for b in seen[i + 1 :]) >= palette.MIN_DISTANCE
    shared = robot_drawing.SHARED_SHADE[0]  # "the same in each" beside the youBot's three poses
    assert min(ciede2000(*seen_as([shared, c], deficiency)) for c in KEY_COLORS[:3]) >= palette.MIN_DISTANCE


def test_robot_figure_draws_the_point_robot_square_at_q(square_world):
    robot = robots.point_robot()
    fig = robot_drawing.robot_figure(robot, [[5.0, 6.0], [9.9, 11.0]], square_world, valid=[True, False])
    links = _patches(fig.axes[0], "link")
    assert len(links) == 2 and all(isinstance(p, Polygon) for p in links)
    np.testing.assert_allclose(links[0].get_xy().min(axis=0), [4.75, 5.75])
    np.testing.assert_allclose(links[0].get_xy().max(axis=0), [5.25, 6.25])
    assert links[0].get_facecolor()[:3] != links[1].get_facecolor()[:3]  # green vs red
    assert len(_patches(fig.axes[0], "block")) == 1  # the block at [10, 12]^2; [20, 25] x [3, 9] is far
    unjudged = robot_drawing.robot_figure(robot, [[5.0, 6.0], [9.9, 11.0]])  # no validity: a colour per configuration
    assert [p.get_facecolor()[:3] for p in _patches(unjudged.axes[0], "link")] == [
        to_rgba(c)[:3] for c in KEY_COLORS[:2]
    ]


def test_robot_figure_overlays_configurations_nearest_the_viewer_last_and_names_them():
    youbot = scenarios.get("3do").robot
    bending = np.tile([5.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], (3, 1))
    bending[:, 4] = [-1.0, 0.0, 1.0]  # the upper arm back, upright, forward
    labels = ["back", "upright", "forward"]
    fig = robot_drawing.robot_figure(youbot, bending, views=("xy",), labels=labels)
    links = _patches(fig.axes[0], "link")
    assert len(links) == 3 * youbot.n_links
    top_z = youbot.link_aabbs(bending)[:, :, 1, 2]  # (3, L): how high each link reaches
    k, link = np.unravel_index(np.argsort(top_z, axis=None, kind="stable"), top_z.shape)
    shared = to_rgba(palette.COLORS["shade"])[:3]  # review r29a: the platform and turret, the same in all three
    drawn = [shared if j < 2 else to_rgba(KEY_COLORS[i])[:3] for i, j in zip(k, link)]
    assert [p.get_facecolor()[:3] for p in links] == drawn  # from above: lowest first, the upright gripper last
    assert links[-1].get_facecolor()[:3] == to_rgba(KEY_COLORS[1])[:3]
    assert [t.get_text() for t in fig.legends[0].get_texts()] == labels + ["the same in each"]
    # reader r51a: "at most one of them is plain": the first pose plain, the shared links hatched upright
    hatches = [p.get_hatch() or "" for p in links]  # drawn in the order of (k, link)
    assert {h for h, j in zip(hatches, link) if j < 2} == {"||"}
    assert [j for h, i, j in zip(hatches, k, link) if not h] == [j for i, j in zip(k, link) if i == 0 and j >= 2]
    assert "light grey, hatched upright" in alt_text(fig)
    with pytest.raises(ValueError, match="2 labels for 3 configurations"):
        robot_drawing.robot_figure(youbot, bending, labels=labels[:2])


def test_named_configurations_carry_a_marker_of_their_own_at_their_last_link():
    """Reader r10b: chapter 01's joint2 = -1 and +1 arms differed by colour only (their links too thin for a hatch).
    Each named configuration gets a marker of its own (circle, square, triangle) at its last link's centre, in each
    flat view where that centre projects (and in 3D), the same marker beside its name in the legend, and the
    description says which; a single configuration needs none."""
    youbot = scenarios.get("3do").robot
    bending = np.tile([5.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], (3, 1))
    bending[:, 4] = [-1.0, 0.0, 1.0]
    fig = robot_drawing.robot_figure(youbot, bending, views=("xz", "xy"), labels=["back", "upright", "forward"])
    ends = youbot.link_boxes(bending)[0][:, -1]  # (3, 3) each configuration's last link centre
    for ax, axes in zip(fig.axes, ((0, 2), (0, 1))):
        marks = [line for line in ax.get_lines() if line.get_marker() not in ("None", "")]
        assert [m.get_marker() for m in marks] == ["o", "s", "^"]
        assert [m.get_color() for m in marks] == [to_hex(c) for c in KEY_COLORS[:3]]
        np.testing.assert_allclose([m.get_xydata()[0] for m in marks], ends[:, list(axes)])
    assert [line.get_marker() for line in fig.legends[0].findobj(Line2D)] == ["o", "s", "^"]  # each beside its name
    assert (
        "forward (dotted, its last link marked with a triangle). A thin link has no room to show a hatch: its "
        "marker tells the configurations apart." in alt_text(fig)
    )  # review r16b: the hatches vanish on thin links
    single = robot_drawing.robot_figure(youbot, bending[:1], views=("xz",), labels=["upright"])
    assert not [line for line in single.axes[0].get_lines() if line.get_marker() not in ("None", "")]


def test_a_figure_of_the_robots_parts_marks_its_base_and_shades_each_link():
    """Review r29a: the 9-DoF chain's base was unmarked and its small cubes drawn as its long links."""
    robot = robots.box_chain(3)
    q = np.array([5.0, 5.0, 5.0, 0.3, 0.2, 0.0, 1.0, -1.0, 0.8])
    fig = robot_drawing.robot_figure(robot, q, views=("xy",), parts=True)
    faces = [to_hex(p.get_facecolor()[:3]) for p in _patches(fig.axes[0], "link")]
    assert len(set(faces)) == 4  # review r31a: the two long links, one shade, could not be told apart
    (dot,) = [line for line in fig.axes[0].get_lines() if line.get_marker() == "o"]
    np.testing.assert_allclose(dot.get_xydata()[0], [5.0, 5.0])
    assert [t.get_text() for t in fig.legends[0].get_texts()] == [
        "link 0: 0.1 long",
        "link 1: 0.4 long",
        "link 2: 0.1 long",
        "link 3: 0.4 long",
        "base",
        "dashed: link outlines, on top",
    ]
    assert "Its base is marked with a black dot" in alt_text(fig)
    # reader r47a: link 3's swatch, opaque black, hid the cross-hatch its drawing shows: each swatch as drawn
    links = sorted(_patches(fig.axes[0], "link"), key=lambda p: to_hex(p.get_facecolor()[:3]))
    swatches = sorted(fig.legends[0].get_patches(), key=lambda p: to_hex(p.get_facecolor()[:3]))
    assert [(tuple(p.get_facecolor()), p.get_hatch()) for p in swatches] == [
        (tuple(p.get_facecolor()), p.get_hatch()) for p in links
    ]
    # reader r41a: link 2, white under its neighbours' ends, could not be found: every link numbered on the drawing
    numbers = [t for t in fig.axes[0].texts if t.get_gid() == "link number"]
    assert [t.get_text() for t in numbers] == ["0", "1", "2", "3"] and min(t.get_zorder() for t in numbers) > 90
    small = [to_hex(fig.legends[0].get_patches()[k].get_facecolor()[:3]) for k in (0, 2)]  # links 0 and 2: 0.1 long
    assert to_hex("#ffffff") not in small  # a white link is a long one, outlined along its length
    # reader r48a: link 3 cross-hatched like a robot in collision; a link's shade is never the verdict's hatch
    assert not {p.get_hatch() for p in _patches(fig.axes[0], "link")} & {"xx", "++"}
    # reader r53a: link 2, under the rising link 3 from above, was hidden: every link's outline dashed on top
    outlines = _patches(fig.axes[0], "link outline")
    assert len(outlines) == 4 and not any(p.get_fill() for p in outlines)
    assert all(p.get_linestyle() == (0, (3, 2)) for p in outlines)  # dashed
    assert min(p.get_zorder() for p in outlines) > max(p.get_zorder() for p in _patches(fig.axes[0], "link"))


def test_a_robot_figures_flat_views_fill_their_width():
    """Reader r39a: chain9's two views were 140 px wide under a wide legend, the youBot's side view sat above an empty
    band. Flat views: the figure as tall as its panels, drawn to scale, need to fill the page's width; one wide panel
    alone, the youBot's side view, most of it (reader r40a: 280 px across)."""
    robot = robots.box_chain(3)
    q = np.array([5.0, 5.0, 5.0, 0.3, 0.2, 0.0, 1.0, -1.0, 0.8])
    fig = robot_drawing.robot_figure(robot, q, views=("xz", "xy"), margin=0.1, parts=True)
    fig.draw_without_rendering()
    widths = [ax.get_window_extent().width / fig.dpi for ax in fig.axes]  # inches
    assert min(widths) >= 0.28 * fig.get_figwidth(), widths  # were 1.77 and 1.14 of 6.1 inches
    youbot = scenarios.get("3do").robot
    side = robot_drawing.robot_figure(youbot, [5.0, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0], views=("xz",), labels=["up"])
    side.draw_without_rendering()
    (ax,) = side.axes
    assert ax.get_window_extent().height >= 0.55 * side.bbox.height  # no empty band under the panel
    assert ax.get_window_extent().width >= 0.6 * palette.PAGE_WIDTH * side.dpi  # reader r40a: its arm in hairlines


def test_robot_figure_projects_a_chain_by_forward_kinematics():
    robot = robots.box_chain(1)  # small link 0.1 long, then big link 0.4 long, along x at zero
    q = np.array([5.0, 5.0, 5.0, 0.0, 0.0, 0.0, np.pi / 2])  # the joint turns the big link to +y
    fig = robot_drawing.robot_figure(robot, q, views=("xy", "xz", "3d"))
    xy = np.concatenate([p.get_xy() for p in _patches(fig.axes[0], "link")])
    np.testing.assert_allclose(xy.min(axis=0), [5.0, 4.95], atol=1e-9)
    np.testing.assert_allclose(xy.max(axis=0), [5.15, 5.4], atol=1e-9)
    xz = np.concatenate([p.get_xy() for p in _patches(fig.axes[1], "link")])
    np.testing.assert_allclose([xz[:, 1].min(), xz[:, 1].max()], [4.95, 5.05], atol=1e-9)
    assert len([c for c in fig.axes[2].collections if c.get_gid() == "link"]) == robot.n_links


def test_draw_robot_in_3d_draws_each_link_box_at_its_pose_and_the_blocks_near_it(recorded_polys, clutter):
    robot = robots.box_chain(3)
    Q = np.array([[5.0, 5.0, 5.0, 0.3, -0.2, 0.1, 0.5, -1.0, 1.5], [2.0, 8.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]])
    fig = Figure()
    ax = fig.add_subplot(projection="3d")
    robot_drawing.draw_robot(ax, robot, Q, colors=["C3", "C4"], view="3d", workspace=clutter, margin=0.5)
    links = [c for c in ax.collections if c.get_gid() == "link"]
    assert len(links) == 2 * robot.n_links
    centers, rotations, half = robot.link_boxes(Q)  # (2, L, 3), (2, L, 3, 3), (L, 3)
    for k, box in enumerate(links):
        i, link = divmod(k, robot.n_links)  # configuration by configuration, link by link
        local = (box.faces3d.reshape(-1, 3) - centers[i, link]) @ rotations[i, link]  # in the link's frame
        np.testing.assert_allclose(np.abs(local), np.broadcast_to(half[link], local.shape), atol=1e-9)  # +-half
        np.testing.assert_allclose(box.get_facecolor()[0][:3], to_rgba(("C3", "C4")[i])[:3])
    aabbs = robot.link_aabbs(Q)  # (2, L, 2, 3)
    lo, hi = aabbs[:, :, 0].min(axis=(0, 1)) - 0.5, aabbs[:, :, 1].max(axis=(0, 1)) + 0.5
    near = np.all((clutter.boxes[:, 0] <= hi) & (clutter.boxes[:, 1] >= lo), axis=1)  # (K,) blocks in the window
    assert 0 < near.sum() == len([c for c in ax.collections if c.get_gid() == "block"])


def test_draw_robot_rejects_an_unknown_view_and_a_colour_count_off_by_one():
    robot, fig = robots.point_robot(), Figure()
    with pytest.raises(ValueError, match="unknown view 'xw'"):
        robot_drawing.draw_robot(fig.add_subplot(), robot, [[5.0, 5.0]], colors=["C0"], view="xw")
    with pytest.raises(ValueError, match="2 colours for 1 configurations"):
        robot_drawing.draw_robot(fig.add_subplot(), robot, [[5.0, 5.0]], colors=["C0", "C1"], view="xy")


# -- configuration space ---------------------------------------------------------------


def test_slice_configs_varies_two_dof_and_fixes_the_rest():
    robot = robots.box_chain(3)
    q = np.linspace(0.1, 0.9, robot.dof)
    values_i, values_j, Q = slices.slice_configs(robot, q, (7, 2), resolution=5)
    assert Q.shape == (5, 5, robot.dof)
    np.testing.assert_allclose(values_i, [-1.6, -0.8, 0.0, 0.8, 1.6])  # cell centres: 5 cells over [-2, 2]
    np.testing.assert_allclose(values_j, 1.1 + 2.2 * np.arange(5))
    np.testing.assert_allclose(Q[3, 1, 7], values_i[3])
    np.testing.assert_allclose(Q[3, 1, 2], values_j[1])
    others = [k for k in range(robot.dof) if k not in (7, 2)]
    np.testing.assert_allclose(Q[..., others], np.broadcast_to(q[others], (5, 5, len(others))))
    with pytest.raises(ValueError, match="two different"):
        slices.slice_configs(robot, q, (3, 3), resolution=5)


def test_cspace_image_is_dark_exactly_where_fcl_reports_collision(square_world):
    robot = robots.point_robot()
    fig = cspace.cspace_image(PointRobotChecker(square_world, robot), resolution=90)
    _, _, Q = slices.slice_configs(robot, robot.lower, (0, 1), resolution=90)
    by_fcl = FCLChecker(square_world, robot).are_valid(Q.reshape(-1, 2)).reshape(90, 90)
    image = _image(fig)  # (y, x): 1 dark
    np.testing.assert_array_equal(image, (~by_fcl).T.astype(float))
    assert 0 < image.mean() < 0.2
    assert len(_patches(fig.axes[0], "block")) == 2


def test_cspace_image_grows_each_block_by_the_robots_half_width(square_world):
    """Zoomed on the block [10, 12]^2: dark from 9.75 to 12.25 (touching counts), light beyond."""
    robot = robots.point_robot()
    fig = cspace.cspace_image(PointRobotChecker(square_world, robot), resolution=20, window=((9.0, 13.0), (10.0, 12.0)))
    row = _image(fig)[10]  # y = 11.05; x at 9.1, 9.3, ..., 12.9
    x = 9.1 + 0.2 * np.arange(20)
    np.testing.assert_array_equal(row, ((x > 9.75) & (x < 12.25)).astype(float))
    assert fig.axes[0].images[0].get_extent() == [9.0, 13.0, 10.0, 12.0]
    assert fig.axes[0].get_xlim() == (9.0, 13.0) and fig.axes[0].get_ylim() == (10.0, 12.0)
    assert "of this window" in fig.axes[0].get_title()
    with pytest.raises(ValueError, match="cspace_slice"):
        cspace.cspace_image(
            FCLChecker(Workspace(np.zeros(3), np.full(3, 11.0), np.zeros((0, 2, 3))), robots.box_chain(1))
        )


def test_cspace_slice_equals_the_separating_axis_reference(clutter):
    robot = robots.box_chain(1)
    checker = FCLChecker(clutter, robot)
    q = near_blocks.configuration_near_blocks(checker, np.random.default_rng(0), n=500)
    fig = cspace.cspace_slice(checker, q, joints=(5, 6), resolution=30)
    _, _, Q = slices.slice_configs(robot, q, (5, 6), resolution=30)
    by_sat = SeparatingAxisChecker(clutter, robot).are_valid(Q.reshape(-1, robot.dof)).reshape(30, 30)
    image = _image(fig)
    np.testing.assert_array_equal(image, (~by_sat).T.astype(float))
    assert 0 < image.mean() < 1  # the slice crosses a C-obstacle
    ax = fig.axes[0]
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("gamma (rad)", "joint1 (rad)")
    assert ax.get_box_aspect() == 1  # reader r48a: two angles, 2π and 4 rad, drawn as a square, not taller
    star = next(line for line in ax.lines if line.get_gid() == "q")
    np.testing.assert_allclose(np.ravel(star.get_data()), q[[5, 6]])
    assert star.get_color() == robot_drawing.VALID_COLOR
    assert star.get_markersize() <= 11  # reader r50a: a 2-unit star touched a grown shelf 0.4 from q
    assert len(_patches(fig.axes[1], "link")) == robot.n_links
    assert ax.get_title().split("\n")[1] == "the other DoF at the star's values"  # review r31a: not four lines
    (star_at,) = [part for part in parts_of(fig) if part.name == "the star's configuration"]  # the values: its table
    assert [tuple(row) for row in star_at.rows] == [
        (name, f"{q[k]:.3g}", "yes" if k in (5, 6) else "no") for k, name in enumerate(robot.dof_names)
    ]


def test_a_checker_that_knows_no_workspace_is_a_clear_error():
    class Blind(CollisionChecker):
        def validity(self, Q):
            return np.ones(len(Q), dtype=bool)

    with pytest.raises(TypeError, match="a Blind knows none"):
        cspace.cspace_image(Blind(robots.point_robot()), resolution=4)


def test_configuration_near_blocks_is_the_valid_sample_closest_to_a_block(clutter):
    robot = robots.box_chain(1)
    checker = FCLChecker(clutter, robot)
    q = near_blocks.configuration_near_blocks(checker, np.random.default_rng(5), n=300)
    Q = robot.sample(np.random.default_rng(5), 300)
    Q = Q[checker.are_valid(Q)]

    def block_distance(config):  # one link and one block at a time
        distance = np.inf
        for lo, hi in robot.link_aabbs(config)[0]:
            for b_lo, b_hi in clutter.boxes:
                distance = min(distance, np.linalg.norm(np.maximum(np.maximum(b_lo - hi, lo - b_hi), 0)))
        return distance

    assert checker.is_valid(q)
    assert block_distance(q) == pytest.approx(min(block_distance(c) for c in Q))


def test_the_offices_cabinets_and_desks_differ_in_lightness_and_their_hatches_show():
    """Boxes of about one size, told apart at the site's width: colours at least 3:1 apart, hatches drawn thick."""
    office = scenarios.get("3do").make_workspace(np.random.default_rng(1))
    fig = cspace.workspace_figure(office)
    ax = fig.axes[0]
    faces = {}
    for label, block in zip(office.labels, [c for c in ax.collections if c.get_gid() == "block"]):
        faces.setdefault(label, block)
    cabinet, desk = (to_hex(faces[k].get_facecolor()[0][:3]) for k in ("cabinet", "desk"))
    assert palette.contrast(cabinet, desk) >= 3.0
    table = to_hex(faces["table"].get_facecolor()[0][:3])  # reader r40a: a blue cabinet, a sky-blue table, alike
    hue = [rgb_to_hsv(to_rgba(c)[:3])[0] for c in (cabinet, table)]
    assert min(abs(hue[0] - hue[1]), 1 - abs(hue[0] - hue[1])) >= 0.2  # a fifth of a turn round the hue circle
    assert all(block.get_hatch() and block.get_hatch_linewidth() >= 1.2 for k, block in faces.items() if k != "chair")
    assert len({block.get_hatch() for block in faces.values()}) == len(faces) == 6  # reader r50a: a hatch each
    verdict = {palette.COLORS["valid"], palette.COLORS["invalid"], palette.OKABE_ITO["orange"]}
    assert not {to_hex(block.get_facecolor()[0][:3]) for block in faces.values()} & verdict  # r50a: tables orange
    assert palette.COLORS["overlap"] not in {to_hex(b.get_facecolor()[0][:3]) for b in faces.values()}  # r51a
    # reader r48a: desks cross-hatched like a robot in collision; a kind's hatch is never the verdict's "xx" or "++"
    assert not {block.get_hatch() for block in faces.values()} & {"xx", "++"}
    assert fig.get_figwidth() <= palette.PAGE_WIDTH and fig.legends  # the legend below the view, over no block


def test_touching_names_exactly_the_link_and_block_pairs_the_separating_axis_reference_finds(clutter):
    """Review r26a: the figure of one check marks the link box and the block that touch; each pair it names must be
    one the reference checker finds in collision alone, and a valid configuration names none."""
    robot = robots.box_chain(1)
    checker = SeparatingAxisChecker(clutter, robot)
    Q = robot.sample(np.random.default_rng(3), 200)
    inside = Q[robot.in_bounds(Q)]
    for q in inside[:80]:
        pairs = contact.touching(robot, clutter, q)
        for _, block in pairs:
            alone = Workspace(clutter.lower, clutter.upper, clutter.boxes[block : block + 1])
            assert not SeparatingAxisChecker(alone, robot).is_valid(q)
        if checker.is_valid(q):
            assert pairs == []
    hits = [q for q in inside if not checker.is_valid(q) and contact.touching(robot, clutter, q)]
    assert hits  # some configurations touch a block


def test_verdict_figure_titles_each_panel_with_the_checkers_verdict_and_marks_what_touches(clutter):
    robot = robots.box_chain(1)
    checker = FCLChecker(clutter, robot)
    q = near_blocks.configuration_near_blocks(checker, np.random.default_rng(0), n=500)
    hit = near_blocks.nudged_into_a_block(checker, q, step=0.05)
    assert hit is not None and not checker.is_valid(hit)
    moved = np.flatnonzero(hit != q)
    assert len(moved) == 1 and moved[0] in (0, 1)  # one of x, y, by whole steps
    assert abs(hit[moved[0]] - q[moved[0]]) / 0.05 == pytest.approx(round(abs(hit[moved[0]] - q[moved[0]]) / 0.05))
    fig = verdict.verdict_figure(checker, np.stack([q, hit]))
    left, right = fig.axes
    assert left.get_title() == "valid" and right.get_title().startswith("in collision:\nlink ")  # FCL proves no gap
    exact = exact_checker(clutter, robot)  # a robot that turns: its proven gap is a lower bound, and said so
    Q = robot.sample(np.random.default_rng(0), 200)
    bounds = exact.clearances(Q, cap=1.0)  # (200,)
    clear = Q[np.argmax(bounds)]
    title = verdict.verdict_figure(exact, clear[None]).axes[0].get_title()
    wide = Workspace(clutter.lower - 1, clutter.upper + 1, clutter.boxes)  # no wall within the cap: blocks alone
    to_blocks = exact_checker(wide, robot).clearances(clear[None], cap=1.0)[0]
    assert 0 < bounds.max() <= to_blocks  # reader r55a: the title's bound is to the blocks, not to a floor
    assert title == f"valid; at least {to_blocks:.2g} from every block\n(a lower bound: the gap can be wider)"
    assert left.get_xlim() == right.get_xlim() and left.get_ylim() == right.get_ylim()  # review r27a: one window
    assert not _patches(left, "touching link") and not _patches(left, "touched block")
    pairs = contact.touching(robot, clutter, hit)
    assert len(_patches(right, "touching link")) == len(_patches(right, "touched block")) == len(pairs) > 0
    link, block, depth = contact.contacts(robot, clutter, hit)[0]  # numbered as the arrays are (review r30a)
    assert f"link {link} overlaps block {block} by {depth:.2g}" in right.get_title() and depth > 0
    assert "configuration 2, in collision" in alt_text(fig)
    (key,) = fig.legends  # reader r39a: a key under the panels, right under them, names what they draw
    assert [t.get_text() for t in key.get_texts()] == ["block", "valid", "in collision", "block touched"]
    assert "A key under the panels names block, valid, in collision, block touched." in alt_text(fig)
    fig.draw_without_rendering()
    panels = min(ax.get_tightbbox().y0 for ax in fig.axes)
    assert 0 <= panels - key.get_window_extent().y1 <= 10  # pixels: no band between the panels and their key


def test_a_valid_panel_says_the_gap_its_checker_proves(square_world):
    """Review r29a: chapter 01's valid youBot looked as if it touched a block, its gap (0.007) said four screens on."""
    exact = exact_checker(square_world, robots.point_robot())
    Q = np.array([[9.5, 11.0], [9.9, 11.0]])  # 0.25 left of the block at [10, 12]^2, then overlapping it
    gap = exact.clearances(Q[:1], cap=1.0)[0]
    left, right = verdict.verdict_figure(exact, Q).axes
    assert gap == pytest.approx(0.25)  # reader r43a: the point robot's square never turns, its bound is its gap
    assert left.get_title() == "valid: 0.25 clear of the nearest\nblock or the region's boundary"
    assert right.get_title() == "in collision:\nsquare overlaps block 0 by 0.15"  # the point robot's link, by name


def test_panels_in_rows_are_wider_and_their_key_fills_the_empty_place(square_world):
    """Reader r41a: the first check's three panels, a row, were the page's smallest figure; two a row, the key in
    the third row's empty place."""
    exact = exact_checker(square_world, robots.point_robot())
    Q = np.array([[9.5, 11.0], [9.75, 11.0], [9.95, 11.0]])  # clear, touching, 0.2 into the block at [10, 12]^2
    in_a_row, in_rows = verdict.verdict_figure(exact, Q), verdict.verdict_figure(exact, Q, columns=2)
    width = [
        [ax.get_position().width * fig.get_figwidth() for ax in fig.axes if ax.axison] for fig in (in_a_row, in_rows)
    ]
    assert len(width[1]) == 3 and min(width[1]) > 1.4 * max(width[0])
    (spare,) = [ax for ax in in_rows.axes if not ax.axison]
    assert spare.get_legend() is not None and not in_rows.legends
    assert "A key in the last row names block, valid, in collision, block touched" in alt_text(in_rows)


def test_a_panel_tells_touching_from_overlapping_and_fills_the_overlap(square_world):
    """Review r31a: chapter 01's squares touching and 0.2 into the block bore one title, the overlap hidden under
    the outlines. The title says how deep; the part of a 2D link inside the block is filled."""
    exact = exact_checker(square_world, robots.point_robot())
    Q = np.array([[9.75, 11.0], [9.95, 11.0]])  # touching the block at [10, 12]^2, then 0.2 into it
    touching, overlapping = verdict.verdict_figure(exact, Q).axes
    assert touching.get_title() == "in collision:\nsquare touches block 0" and not _patches(touching, "overlap")
    assert overlapping.get_title() == "in collision:\nsquare overlaps block 0 by 0.2"
    (fill,) = _patches(overlapping, "overlap")
    np.testing.assert_allclose(np.sort(fill.get_xy()[:, 0])[[0, -1]], (10.0, 10.2))  # the square's part inside
    assert contact.contacts(robots.point_robot(), square_world, Q[1]) == [(0, 0, pytest.approx(0.2))]


def test_a_youbot_platform_overlapping_a_block_by_a_little_is_filled_and_enlarged_in_an_inset():
    """Reader r40a: chapter 01's youBot "overlaps block 18 (shelf) by 0.078", a few pixels at one corner, unseen.
    From above, a platform that only turns about z overlaps a block exactly where its shadow does: that part is
    filled, and an inset enlarges it; a valid panel has neither."""
    youbot = scenarios.get("3do").robot
    world = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]), np.array([[[20.0, 10, 0], [22, 22, 1]]]))
    q = np.array([18.5, 15.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0])  # yawed, the platform's front corner short of x = 20
    reach = youbot.link_aabbs(q[None])[0, 0, 1, 0]  # the platform's farthest x
    q[0] += 20.05 - reach  # that corner 0.05 into the block
    fig = verdict.verdict_figure(exact_checker(world, youbot), np.stack([q - 0.3 * np.eye(8)[0], q]))
    clear, hit = fig.axes
    assert "platform overlaps block 0" in hit.get_title() and not _patches(clear, "overlap")
    (fill,) = _patches(hit, "overlap")
    assert fill.get_xy()[:, 0].min() == pytest.approx(20.0) and fill.get_xy()[:, 0].max() == pytest.approx(20.05)
    (inset,) = hit.child_axes
    assert _patches(inset, "overlap") and inset.get_xlim()[0] < 20.0 < 20.05 < inset.get_xlim()[1]
    assert not clear.child_axes and "An inset under the panel enlarges" in alt_text(fig)
    (gap,) = [line for line in clear.lines if line.get_gid() == "gap"]  # reader r55a: the gap drawn, labelled
    assert not [line for line in hit.lines if line.get_gid() == "gap"]
    x0, x1 = sorted(gap.get_xdata())
    assert x1 == pytest.approx(20.0) and x0 == pytest.approx(19.75, abs=0.02)  # platform corner -> block face
    bound = verdict.blocks_bound(exact_checker(world, youbot), q - 0.3 * np.eye(8)[0], world)
    assert 0 < bound <= 0.25 + 1e-9 and clear.get_title().startswith(f"valid; at least {bound:.2g} from every block")
    assert [t.get_text() for t in clear.texts if t.get_gid() == "gap label"] == [f"gap ≥ {bound:.2g}"]
    assert "In configuration 1's panel a labelled segment draws its gap to a block." in alt_text(fig)
    fig.draw_without_rendering()  # reader r50a: inside the panel it read as a second block and robot: under it
    assert inset.get_window_extent().y1 < hit.get_window_extent().y0 and "zoom x" in inset.get_xlabel()
    # reader r42a: unframed, the inset read as one more block and robot in the room: framed heavy. Reader r47a: on a
    # grey ground it read as a block: white, as the room
    assert min(s.get_linewidth() for s in inset.spines.values()) >= 2
    assert to_hex(inset.get_facecolor()) == palette.COLORS["free"] != palette.COLORS["block"]


def test_a_slice_over_positions_shows_a_pixel_beyond_the_bounds_hatched_grey(square_world):
    """Review r26a: the wall's bar at x = 0 merged with the axis's spine; a pixel's width beyond the bounds is drawn,
    and an angle's axis is not padded. Reader r58a: drawn dark, that never-checked pixel read as "in collision": it is
    light grey and hatched, with a key entry."""
    robot = robots.point_robot()
    fig = cspace.cspace_slice(exact_checker(square_world, robot), [5.0, 6.0], joints=(0, 1), resolution=31)
    ax = fig.axes[0]
    lo, hi = robot.lower[0], robot.upper[0]
    np.testing.assert_allclose(ax.get_xlim(), (lo - (hi - lo) / 31, hi + (hi - lo) / 31))
    assert ax.get_aspect() == 1.0  # reader r48a: two lengths drawn to one scale (the youBot's 41 x 41 was 1.3x tall)
    (ring,) = [p for p in ax.patches if p.get_gid() == "unchecked"]
    assert to_hex(ring.get_facecolor()) == palette.COLORS["shade"] != palette.COLORS["occupied"]
    assert ring.get_hatch() == "//" and ring.get_zorder() < ax.images[0].get_zorder()  # under the checked pixels
    np.testing.assert_allclose(ring.get_x(), lo - (hi - lo) / 31)
    (key,) = ax.get_legend().get_texts()
    assert key.get_text() == "past the bounds: not checked"
    assert "dark frame" not in alt_text(fig)  # the square's edge pixels are free: no frame inside the bounds
    # reader r57a: the outer pixel is past the bounds, outside X: said so, and left out of the title's share
    past = "A pixel's width past the bounds, hatched light grey, is never checked and not in the share in collision."
    assert past in alt_text(fig)


def test_a_youbot_slice_names_its_frame_where_the_platform_crosses_the_region_s_boundary():
    """Reader r55a: the youBot's (x, y) slice never leaves its bounds; its frame, inside them, is the platform
    crossing the region's boundary (every edge pixel dark at 60 pixels across 41), plus the pixel drawn past them."""
    youbot = scenarios.get("3do").robot
    world = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]), np.array([[[20.0, 20, 0], [21, 21, 1]]]))
    q = np.array([10.0, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    fig = cspace.cspace_slice(exact_checker(world, youbot), q, joints=(0, 1), resolution=60, view=None)
    frame = "A dark frame runs round the slice: the robot must stay inside the region's boundary. A pixel's width past"
    assert frame + " the bounds, hatched light grey, is never checked" in alt_text(fig)  # reader r58a: not dark
    assert "leaves its bounds" not in alt_text(fig)


def test_a_slice_over_angles_names_no_frame(clutter):
    """Reader r54a's frame is a slice over two positions' alone: an angle's axis is not padded."""
    q = [5.5, 5.5, 5.5, 0.0, 0.0, 0.0, 0.0]
    fig = cspace.cspace_slice(exact_checker(clutter, robots.box_chain(1)), q, joints=(3, 4), resolution=8, view=None)
    assert (
        "Slice of the" in alt_text(fig) and "dark frame" not in alt_text(fig) and "past the bounds" not in alt_text(fig)
    )
    assert fig.axes[0].get_legend() is None


def test_the_slice_explorer_starts_at_a_valid_configuration_and_redraws_when_a_slider_moves(capsys):
    """Chapter 01, section 5: one slider per DoF at a start near a block, the scenario's two DoF swept first."""
    box = near_blocks.slice_explorer({"3dc7": (5, 6)}, start="3dc7", seed=0, resolution=8)
    controls, _ = box.children
    scenario, _, sweep_i, sweep_j, _, fixed = controls.children
    robot = scenarios.get("3dc7").robot
    assert (scenario.value, sweep_i.value, sweep_j.value, len(fixed.children)) == ("3dc7", 5, 6, robot.dof)
    start = np.array([s.value for s in fixed.children])
    assert FCLChecker(scenarios.get("3dc7").make_workspace(np.random.default_rng(0)), robot).is_valid(start)
    capsys.readouterr()  # outside a kernel, the Output widget's content goes to stdout
    sweep_j.value = 5  # the same DoF twice: a message, not a figure
    assert "choose two different DoF" in capsys.readouterr().out


def test_the_youbots_arm_is_labelled_in_its_flat_views():
    """Review r31a: the arm, a few pixels on the platform, went unseen in chapter 01's robot panels."""
    youbot = scenarios.get("3do").robot
    world = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]), np.array([[[20, 20, 0], [22, 22, 1]]], dtype=float))
    checker = exact_checker(world, youbot)
    q = np.array([10.0, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    panels = [
        verdict.verdict_figure(checker, q[None]).axes[0],
        cspace.cspace_slice(checker, q, resolution=4).axes[1],
    ]
    assert [[t.get_text() for t in ax.texts] for ax in panels] == [["arm"], ["arm"]]
    assert not verdict.verdict_figure(exact_checker(world, robots.box_chain(1)), [5.0] * 3 + [0.0] * 4).axes[0].texts


def test_a_slice_outlines_the_blocks_a_flat_view_draws_across_links_they_cannot_reach():
    """Review r32a: the 9-DoF chain's panel drew its valid robot inside a filled block lying wholly above it. A block
    drawn across the links but wholly above or below every link over it (in front or behind, from the side) is a
    dotted outline; a block beside the links, whatever its height, stays filled."""
    boxes = [[[4, 4, 6], [6, 6, 7]], [[5.25, 5.25, 4], [5.5, 5.5, 6]], [[7, 7, 6], [8, 8, 7]]]  # above, beside, far
    fig = _one_link_slice(boxes)
    ax = fig.axes[1]
    (above,) = _patches(ax, "beyond")
    assert not above.get_fill() and above.get_linestyle() == ":"
    assert _drawn_inside(above, (4, 4), (6, 6))
    assert len(_patches(ax, "block")) == 2  # the block beside the links, and the far one
    assert "no link touches (above or below them) is a dotted outline, drawn a little inside its edges." in alt_text(
        fig
    )
    side = _one_link_slice(boxes, view="xz")
    (behind,) = _patches(side.axes[1], "beyond")  # from the side: the second block, behind the links
    assert _drawn_inside(behind, (5.25, 4), (5.5, 6))
    assert ax.get_title().endswith("valid — base (black dot) at z = 5.00")  # r41a: a top view hides the height
    assert side.axes[1].get_title().endswith(" — base (black dot)")  # the side view shows it


def _one_link_slice(boxes, view="xy", x=5.0):
    """The slice of a one-link chain, laid along +x from (x, 5, 5) (to x + 0.5; z 4.95 to 5.05), among ``boxes``."""
    world = Workspace(np.zeros(3), np.full(3, 11.0), np.array(boxes, dtype=float), family="3dc")
    q = np.array([x, 5.0, 5.0, 0.0, 0.0, 0.0, 0.0])
    checker = exact_checker(world, robots.box_chain(1))
    return cspace.cspace_slice(checker, q, joints=(5, 6), resolution=8, view=view, margin=3.0)


def _drawn_inside(outline, lo, hi) -> bool:
    """A dotted outline lies a little inside its block ``[lo, hi]``, no more than a quarter of each side in (r34a:
    neighbours' outlines joined into lines across the panel that read as a grid)."""
    x, y = outline.get_xy()
    inner = np.array([x, y, x + outline.get_width(), y + outline.get_height()])
    side = np.subtract(hi, lo)
    low_in, high_in = inner[:2] - lo, hi - inner[2:]
    return bool(np.all(low_in > 0) and np.all(high_in > 0) and np.all(np.maximum(low_in, high_in) <= side / 4 + 1e-12))


def test_a_block_over_a_tilted_link_is_outlined_though_the_links_bounds_reach_its_height():
    """Review r34a: a block above the base was drawn filled across a valid robot, the box round a tilted link
    reaching its height though the link clears it where their shadows meet. Judged by the boxes themselves, a block
    no link touches is a dotted outline wherever it is drawn across the links; a block a link touches stays filled."""
    robot = robots.box_chain(1)
    q = np.array([5.0, 5.0, 5.0, 0.0, -0.5, 0.0, 0.0])  # the big link tipped up: its bounds reach z 5.28
    assert robot.link_aabbs(q[None])[0, 1, 1, 2] > 5.1
    over_base = Workspace(np.zeros(3), np.full(3, 11.0), np.array([[[4.9, 4.9, 5.1], [5.06, 5.1, 6]]]), family="3dc")
    checker = exact_checker(over_base, robot)
    assert checker.are_valid(q[None])[0]
    ax = cspace.cspace_slice(checker, q, joints=(5, 6), resolution=4, margin=0.5).axes[1]
    assert len(_patches(ax, "beyond")) == 1 and not _patches(ax, "block")
    lowered = Workspace(over_base.lower, over_base.upper, over_base.boxes - [0, 0, 0.2], family="3dc")
    assert contact.contacts(robot, lowered, q) and not contact.passed_over(robot, lowered, q, (0, 1)).any()


def test_the_figure_of_one_check_names_each_office_block_inside_it():
    """Review r32a: the title named "block 18 (shelf)", but the shelf, drawn grey and clipped, bore no name in the
    left panel. Where the workspace names kinds, each block drawn carries its number and kind at the middle of its
    part inside the window; unnamed blocks carry none."""
    youbot = scenarios.get("3do").robot
    boxes = np.array([[[20, 20, 0], [22, 22, 1]], [[9, 11, 0], [30, 12, 3]]], dtype=float)
    world = Workspace(np.zeros(3), np.array([41.0, 41.0, 6.0]), boxes, labels=("desk", "shelf"))
    q = np.array([10.0, 10.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    ax = verdict.verdict_figure(exact_checker(world, youbot), q[None]).axes[0]
    (name,) = [t for t in ax.texts if t.get_gid() == "name"]  # the desk lies far outside the window
    assert name.get_text() == "1 shelf"
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    np.testing.assert_allclose(name.get_position(), [(max(9, x0) + min(30, x1)) / 2, (max(11, y0) + min(12, y1)) / 2])


def test_a_slices_robot_panel_dashes_the_block_a_link_touches_and_keys_each_way_a_block_is_drawn():
    """Reader r37a, C1: the figure of one check dashed a touched block, the slices' robot panels filled it, and filled
    grey blocks beside a valid robot read as touched. One rule in both: dashed is touched, and a key says so."""
    boxes = [[[4, 4, 6], [6, 6, 7]], [[5.5, 4, 4], [6, 6, 6]], [[7, 7, 6], [8, 8, 7]]]  # above, touching, far
    fig = _one_link_slice(boxes)
    ax = fig.axes[1]
    (dashed,) = _patches(ax, "touched block")
    assert dashed.get_linestyle() == "--" and not dashed.get_fill() and dashed.get_xy() == (5.5, 4)
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "grey: a block beside the links (any height)",  # r48a: a block at z 2-3 looked level; r51a: vs dotted?
        "dotted: the links pass over or under",
        "dashed: a link touches it",
    ]
    assert "A block a link touches is outlined dashed." in alt_text(fig)
    moved = _one_link_slice(boxes, x=4.0)  # a unit back: nothing touched
    assert not _patches(moved.axes[1], "touched block")
    assert "dashed: a link touches it" not in [t.get_text() for t in moved.axes[1].get_legend().get_texts()]


def test_the_chapters_joint_slice_tips_its_last_link_up_at_positive_joint2_its_gamma_near_pi():
    """Reader r57a: section 2's q9 tips the last link up at negative joint2, yet chapter 01's joint2 x joint3 slice
    reaches the cube above the base at positive joint2. The chapter says why: the star's gamma, near pi, has rolled
    the chain almost upside down, which turns the joint's sense round."""
    chain9 = scenarios.get("3dc9").robot
    checker = exact_checker(scenarios.get("3dc9").make_workspace(np.random.default_rng(0)), chain9)
    q = near_blocks.configuration_near_blocks(checker, np.random.default_rng(0))
    assert abs(q[chain9.dof_names.index("gamma")]) > 0.9 * np.pi

    def last_link_height(config, joint2: float) -> float:
        config = np.array(config, dtype=float)
        config[chain9.dof_names.index("joint2")] = joint2
        return float(chain9.link_boxes(config)[0][0, -1, 2])

    assert last_link_height(q, 1.0) > last_link_height(q, 0.0) > last_link_height(q, -1.0)  # up at positive joint2
    q9 = [5.0, 5.0, 5.0, 0.3, 0.2, 0.0, 1.0, -1.0, 0.8]  # section 2's, gamma 0
    assert last_link_height(q9, -1.0) > last_link_height(q9, 0.0) > last_link_height(q9, 1.0)  # up at negative
    values, _, Q = slices.slice_configs(chain9, q, (7, 8), resolution=12)
    dark = ~checker.are_valid(Q.reshape(-1, chain9.dof)).reshape(12, 12)  # (joint2, joint3)
    assert dark.any() and values[dark.any(axis=1)].min() > 0  # every dark pixel at positive joint2


def test_slice_hits_names_the_block_the_chapters_joint_slice_reaches_and_counts_the_boundary_apart():
    """Reader r51a: chapter 01's joint2 x joint3 slice said "the last two links sweep into a nearby block" and named
    none. Over the slice's in-collision pixels, each (link, block) pair that touches is counted; at the chapter's
    configuration only the last link reaches one block, the unit cube right above the base, in every dark pixel."""
    clutter0 = scenarios.get("3dc9").make_workspace(np.random.default_rng(0))
    chain9 = scenarios.get("3dc9").robot
    checker = exact_checker(clutter0, chain9)
    q = near_blocks.configuration_near_blocks(checker, np.random.default_rng(0))
    hits, elsewhere = near_blocks.slice_hits(checker, q, (7, 8), 12)
    Q = slices.slice_configs(chain9, q, (7, 8), resolution=12)[2].reshape(-1, chain9.dof)
    dark = int((~checker.are_valid(Q)).sum())
    assert set(hits) == {(3, 117)} and hits[(3, 117)] == dark > 0 and elsewhere == 0
    np.testing.assert_array_equal(clutter0.boxes[117], [[0, 9, 1], [1, 10, 2]])
    table = near_blocks.slice_hits_table(checker, q, (7, 8), 12).splitlines()
    assert table[2:] == [f"| link 3 | block 117, (0, 9, 1) to (1, 10, 2) | {dark} of 144 |"]
    empty = Workspace(clutter0.lower, clutter0.upper, clutter0.boxes[:0])  # no block: the floor alone
    hits, elsewhere = near_blocks.slice_hits(exact_checker(empty, chain9), q, (3, 4), 12)
    assert not hits and elsewhere > 0
    table = near_blocks.slice_hits_table(exact_checker(empty, chain9), q, (3, 4), 12).splitlines()
    assert table[2:] == [f"| a link | the region's boundary | {elsewhere} of 144 |"]
