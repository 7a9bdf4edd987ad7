"""Notebook 05's path figure: the robot drawn by forward kinematics at the chosen frame, the path's series beside it."""

import itertools

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_hex, to_rgba
from matplotlib.figure import Figure
from matplotlib.markers import MarkerStyle
from matplotlib.text import Text
from mpl_toolkits.mplot3d import proj3d

from toolkit import scenarios
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.plots import closest_pair, dof_panels, palette, path_series, robot_drawing, scenes, still_panels
from toolkit.plots.alt import alt_text
from toolkit.plots.boxes import add_box_3d
from toolkit.plots.palette import contrast
from toolkit.plots.robot_drawing import INVALID_COLOR, VALID_COLOR

FRAMES = 25


@pytest.fixture(scope="module")
def crossing():
    """A 3DC-7 straight path from a valid configuration through the nearest block's centre: valid, then colliding."""
    scenario = scenarios.get("3dc7")
    workspace, robot = scenario.make_workspace(np.random.default_rng(2)), scenario.robot
    exact = exact_checker(workspace, robot)
    Q = robot.sample(np.random.default_rng(0), 400)
    start = Q[exact.are_valid(Q)][0]
    centres = workspace.boxes.mean(axis=1)  # (K, 3)
    goal = start.copy()
    goal[:3] = centres[np.argmin(np.linalg.norm(centres - start[:3], axis=1))]  # the base inside a block
    path = robot.interpolate(start, goal, np.linspace(0.0, 1.0, FRAMES))  # (T, dof)
    valid = exact.are_valid(path)
    assert valid[0] and not valid[-1]
    return robot, workspace, exact, path, valid


def links(ax):
    return [c for c in ax.collections if c.get_gid() == "link"]


def shape(mark) -> np.ndarray:
    """A marker's outline ``(V, 2)`` scaled to unit size: a collection's path or a marker's name."""
    if isinstance(mark, str):
        style = MarkerStyle(mark)
        mark = style.get_path().transformed(style.get_transform())
    return mark.vertices / np.abs(mark.vertices).max()


def line(ax, gid):
    return next(artist for artist in ax.lines if artist.get_gid() == gid)


@pytest.mark.parametrize("index", [0, FRAMES - 1])
def test_the_robot_is_its_link_boxes_at_the_frame_colored_by_validity(crossing, index, monkeypatch):
    """The frame's configuration goes to ``robot_drawing.draw_robot`` (whose boxes ``tests/test_plots_cspace.py``
    holds to forward kinematics) in the colour of its validity, in 3D, with the workspace."""
    robot, workspace, _, path, valid = crossing
    drawn_robots = []

    def recording(ax, robot, Q, *, colors, view, workspace, margin, clip):
        drawn_robots.append((Q, colors, view, workspace, clip))
        robot_drawing.draw_robot(ax, robot, Q, colors=colors, view=view, workspace=workspace, margin=margin, clip=clip)

    monkeypatch.setattr(scenes, "draw_robot", recording)
    fig = scenes.path_frame(robot, path, index, workspace=workspace, valid=valid)
    want = VALID_COLOR if valid[index] else INVALID_COLOR
    [(Q, colors, view, drawn_in, clip)] = drawn_robots
    np.testing.assert_array_equal(Q, path[index : index + 1])
    assert (colors, view, drawn_in, clip) == ([want], "3d", workspace, True)  # blocks clipped: none over the ticks
    drawn = links(fig.axes[0])
    assert len(drawn) == robot.n_links
    for box in drawn:
        np.testing.assert_allclose(box.get_facecolor()[0][:3], to_rgba(want)[:3])
    assert ("valid (exact checker)" if valid[index] else "IN COLLISION") in fig.get_suptitle()


def test_without_validity_the_robot_is_neutral(crossing):
    robot, workspace, _, path, _ = crossing
    fig = scenes.path_frame(robot, path, 3, workspace=workspace)
    assert all(
        np.allclose(box.get_facecolor()[0][:3], to_rgba(scenes.UNCHECKED_COLOR)[:3]) for box in links(fig.axes[0])
    )
    assert "exact" not in fig.get_suptitle()


def test_the_blocks_near_the_robot_are_drawn_and_the_trace_stays_in_the_window(crossing, monkeypatch):
    """The blocks that meet the window are drawn, each only as far as it lies inside it (reader r19c: mplot3d drew a
    block past its axes, over their tick labels), the nearest one too; the base's trace only inside it."""
    robot, workspace, _, path, valid = crossing
    index = FRAMES - 1  # the base inside a block: that block is drawn
    boxes = []  # (8, 3) corners of every box drawn

    def recording(ax, corners, **style):
        boxes.append(corners)
        return add_box_3d(ax, corners, **style)

    monkeypatch.setattr(robot_drawing, "add_box_3d", recording)
    monkeypatch.setattr(still_panels, "add_box_3d", recording)
    wide = scenes.path_frame(robot, path, index, workspace=workspace, margin=1.5).axes[0]  # 8 of 9 blocks cross it
    lo, hi = np.array([wide.get_xlim(), wide.get_ylim(), wide.get_zlim()]).T
    corners = np.array(boxes)  # (boxes, 8, 3): the blocks, the links, the nearest block
    assert len(corners) == 9 + robot.n_links + 1
    assert np.all((corners >= lo - 1e-9) & (corners <= hi + 1e-9))
    scene = scenes.path_frame(robot, path, index, workspace=workspace, valid=valid, margin=1.0).axes[0]
    lo, hi = np.array([scene.get_xlim(), scene.get_ylim(), scene.get_zlim()]).T
    aabbs = robot.link_aabbs(path[index])[0]  # (L, 2, 3)
    np.testing.assert_allclose(lo, np.maximum(aabbs[:, 0].min(axis=0) - 1.0, workspace.lower))
    np.testing.assert_allclose(hi, np.minimum(aabbs[:, 1].max(axis=0) + 1.0, workspace.upper))
    near = np.all((workspace.boxes[:, 0] <= hi) & (workspace.boxes[:, 1] >= lo), axis=1)
    assert len([c for c in scene.collections if c.get_gid() == "block"]) == near.sum() >= 1
    trace = np.array(line(scene, "trace").get_data_3d()).T  # (T, 3)
    bases = robot.link_boxes(path)[0][:, 0]  # (T, 3)
    inside = np.all((bases >= lo) & (bases <= hi), axis=1)
    assert inside[index] and inside.sum() > 0
    np.testing.assert_allclose(trace[inside], bases[inside])
    assert np.isnan(trace[~inside]).all()
    (name,) = [t for t in scene.texts if t.get_text() == "nearest block"]  # reader r20c: it crossed the block's edges
    x, y, _ = proj3d.proj_transform(*boxes[-1].T, scene.get_proj())  # (8,) each: the last box drawn, the nearest's
    assert name.xy == pytest.approx((np.mean(x), np.max(y)))  # over its highest corner on the picture
    assert name.get_va() == "bottom" and name.anncoords == "offset points" and name.xyann[1] > 0  # above its picture


def test_the_series_panels_show_each_dof_clearance_and_probability(crossing):
    robot, workspace, exact, path, valid = crossing
    clearance = exact.clearances(path, cap=1.0)
    probability = np.linspace(1.0, 0.0, FRAMES)
    index, threshold = 7, 0.4
    fig = scenes.path_frame(
        robot,
        path,
        index,
        workspace=workspace,
        valid=valid,
        clearance=clearance,
        probability=probability,
        threshold=threshold,
    )
    *dof_axes, clearance_ax, probability_ax = fig.axes[1:]
    along = np.linspace(0.0, 1.0, FRAMES)
    panels = [[artist for artist in ax.lines if artist.get_gid() == "dof"] for ax in dof_axes]
    # a panel per kind, none with more than three lines (seven in one crossed and hid each other: reader r8b)
    assert [[artist.get_label() for artist in lines] for lines in panels] == [
        ["x", "y", "z"],
        ["alpha", "beta", "gamma"],
        ["joint1"],
    ]
    assert [ax.get_ylabel() for ax in dof_axes] == ["position", "angles", "joints"]
    dofs = [artist for lines in panels for artist in lines]
    for k, artist in enumerate(dofs):
        np.testing.assert_allclose(artist.get_xdata(), along)
        np.testing.assert_allclose(
            artist.get_ydata(), (path[:, k] - robot.lower[k]) / (robot.upper[k] - robot.lower[k])
        )
    np.testing.assert_allclose(line(clearance_ax, "clearance").get_ydata(), clearance)
    assert clearance[0] > 0 and clearance[-1] == 0  # room at the start, none inside the block
    np.testing.assert_allclose(line(probability_ax, "probability").get_ydata(), probability)
    assert line(probability_ax, "threshold").get_ydata()[0] == threshold
    for ax in fig.axes[1:]:
        assert line(ax, "now").get_xdata()[0] == pytest.approx(along[index])
    title = fig.get_suptitle()
    assert (
        title.startswith(f"frame {index} (frames 0–{FRAMES - 1}): ") and f"P(valid) {probability[index]:.2f} ≥" in title
    )
    assert "≥ threshold 0.40" in title  # 0.71 >= 0.4 (reader r32e: no brackets for the title to wrap inside)


def test_the_nearest_blocks_name_says_where_a_wall_of_the_workspace_is_nearer():
    """Reader r23b: at clearance 0.372 the block named "nearest block" stood 1-2 units off; the cube's top wall was
    the nearer. A chain flying just under the top wall, its nearest block further off, says so on the picture."""
    scenario = scenarios.get("3dc7")
    robot = scenario.robot
    q = np.zeros(robot.dof)
    q[:3] = (5.0, 5.0, 10.7)  # the base 0.3 under the top wall (z = 11)
    top = robot.link_aabbs(q[None])[0][:, 1, 2].max()  # the links' highest point
    assert top < 11.0
    far = Workspace(np.zeros(3), np.full(3, 11.0), np.array([[[5.0, 5.0, 7.0], [6.0, 6.0, 8.0]]]), family="3dc")
    near = Workspace(far.lower, far.upper, np.array([[[5.0, 5.0, top + 0.01], [6.0, 6.0, 11.0]]]), family="3dc")
    names = [
        [
            t.get_text()
            for t in scenes.path_frame(robot, q[None], 0, workspace=w).axes[0].texts
            if "nearest" in t.get_text()
        ]
        for w in (far, near)
    ]
    assert names == [["nearest block\n(a wall of the workspace is nearer)"], ["nearest block"]]


def test_a_single_frame_below_the_threshold_gets_a_band_of_its_own(crossing):
    """Reader r23b: P(valid) dipped below the threshold at one frame and no band showed (a fill between points
    needs two). Each run of frames below it gets one band, half a step either side and at least path_series.BAND."""
    robot, workspace, _, path, _ = crossing
    probability = np.ones(FRAMES)
    probability[[3, 9, 10]] = 0.1  # one frame alone, then a run of two
    fig = scenes.path_frame(robot, path, 0, workspace=workspace, probability=probability, threshold=0.5)
    bands = [p for p in fig.axes[-1].patches if p.get_gid() == "below threshold"]
    along, half = np.linspace(0.0, 1.0, FRAMES), max(0.5 / (FRAMES - 1), path_series.BAND)
    spans = [(p.get_x(), p.get_x() + p.get_width()) for p in bands]
    np.testing.assert_allclose(spans, [(along[3] - half, along[3] + half), (along[9] - half, along[10] + half)])
    assert path_series.below_threshold(np.zeros(FRAMES, bool), along) == []


def test_only_the_given_series_get_panels(crossing):
    robot, workspace, _, path, _ = crossing
    assert len(scenes.path_frame(robot, path, 0, workspace=workspace).axes) == 1 + 3  # the robot, the DoFs by kind
    assert len(scenes.path_frame(robot, path, 0, probability=np.ones(FRAMES)).axes) == 1 + 3 + 1
    office = scenarios.get("3do").robot  # x, y on the floor, its heading, five joints
    assert dof_panels.dof_groups(office) == {"position": [0, 1], "angles": [2], "joints": [3, 4, 5, 6, 7]}


@pytest.mark.parametrize("series", [{}, {"clearance": np.ones(FRAMES), "probability": np.ones(FRAMES)}])
def test_the_dof_legend_lies_inside_the_figure_below_the_title(crossing, series):
    robot, _, _, path, _ = crossing
    fig = scenes.path_frame(robot, path, 0, **series)
    renderer = FigureCanvasAgg(fig).get_renderer()
    suptitle = next(t for t in fig.texts if t.get_text() == fig.get_suptitle())
    title = suptitle.get_window_extent(renderer)
    legend = fig.legends[0].get_window_extent(renderer)
    figure = fig.bbox
    assert figure.x0 <= legend.x0 and legend.x1 <= figure.x1 and figure.y0 <= legend.y0 and legend.y1 <= figure.y1
    assert legend.y1 <= title.y0  # below the title, not over it
    panels_top = max(ax.get_window_extent(renderer).y1 for ax in fig.axes[1:])
    assert panels_top <= legend.y0 + 1  # and above the panels
    assert [t.get_text() for t in fig.legends[0].get_texts()] == list(robot.dof_names)


def test_bad_input(crossing):
    robot, _, _, path, _ = crossing
    with pytest.raises(ValueError, match="index"):
        scenes.path_frame(robot, path, FRAMES)
    with pytest.raises(ValueError, match="one value per configuration"):
        scenes.path_frame(robot, path, 0, probability=np.ones(FRAMES - 1))
    with pytest.raises(ValueError, match="shape"):
        scenes.path_frame(robot, path[:, :3], 0)


def test_a_scenes_still_draws_the_workspace_then_the_robot_close_up_at_each_pose(crossing):
    robot, workspace, _, path, valid = crossing
    points = robot.link_boxes(path)[0][:, 0]  # (T, 3) the base along the path, as sample points
    kinds = {"valid": valid, "in collision": ~valid}
    fig = scenes.scene_still(
        robot,
        workspace,
        {"start": path[0], "end": path[-1]},
        valid={"start": True, "end": False},
        samples=(points, kinds),
        trace=points,
    )
    overview, start, end = fig.axes
    assert overview.get_title() == f"the whole workspace: {len(workspace.boxes)} blocks"
    assert [start.get_title(), end.get_title()] == ["start, close up, valid", "end, close up, in collision"]
    assert (start.elev, start.azim) == (end.elev, end.azim)  # reader r34e: one camera, so that the poses compare
    assert to_rgba(links(start)[0].get_facecolor()[0], None)[:3] == to_rgba(VALID_COLOR)[:3]
    assert to_rgba(links(end)[0].get_facecolor()[0], None)[:3] == to_rgba(INVALID_COLOR)[:3]
    drawn = {c.get_label(): len(c.get_offsets()) for c in overview.collections if c.get_label().startswith("sample")}
    assert drawn == {"sample, valid": int(valid.sum()), "sample, in collision": int((~valid).sum())}
    names = [t.get_text() for t in fig.legends[0].get_texts()]
    assert "robot, valid" in names and "robot, in collision" in names
    labels = [t.get_text() for t in overview.texts if t.get_gid() == "pose label"]
    assert labels == ["start", "end, in collision"]  # each pose named over it; a collision said in words too
    robots = [line for line in overview.get_lines() if line.get_gid() == "robot"]
    assert [to_hex(line.get_color()) for line in robots] == [to_hex(VALID_COLOR), to_hex(INVALID_COLOR)]
    assert (
        "the path of the robot's base and its shadow on the floor, dotted, a thin dash-dot line from the robot's base "
        "straight down to the floor at each pose, the robot drawn over them at each pose, labelled;" in alt_text(fig)
    )
    assert {line.get_linestyle() for line in overview.get_lines() if line.get_gid() == "drop"} == {"-."}  # r31e
    (shadow,) = [line for line in overview.get_lines() if line.get_gid() == "shadow"]  # reader r20c: depth cues
    np.testing.assert_allclose(np.array(shadow.get_data_3d()).T, np.c_[points[:, :2], np.zeros(len(points))])
    drops = [np.array(line.get_data_3d()).T for line in overview.get_lines() if line.get_gid() == "drop"]  # (2, 3)
    bases = robot.link_boxes(path[[0, -1]])[0][:, 0]  # (2, 3) each pose's first link's centre
    np.testing.assert_allclose(drops, [[base, [*base[:2], 0.0]] for base in bases])
    for close_up, at in ((start, 0), (end, -1)):  # the samples inside its window but off the robot's
        fig.draw_without_rendering()  # reader r39e: half-width, its ticks crowded; r41e: but with none, no scale
        shown = [t.get_text() for t in close_up.get_xticklabels() if t.get_text()]
        lo_x, hi_x = close_up.get_xlim()
        within = [x for x in close_up.get_xticks() if lo_x <= x <= hi_x]
        assert shown and 1 <= len(within) <= 3 and close_up.xaxis.get_ticklabels()[0].get_fontsize() == 8
        lo, hi = np.array([close_up.get_xlim(), close_up.get_ylim(), close_up.get_zlim()]).T  # picture, shaped by
        inside = np.all((points >= lo) & (points <= hi), axis=1)  # (T,) validity; links told apart; trace dashed
        over = still_panels.over_robot(close_up, robot, path[at], points)  # (T,) pictured on or beside a link
        assert over[at] and (inside & ~over).any()  # its own base is; others are not
        inside &= ~over
        marks = {c.get_label(): c for c in close_up.collections if c.get_label().startswith("sample")}
        for kind, mask, marker in (("valid", valid, "o"), ("in collision", ~valid, "D")):
            expected = points[inside & mask]  # (n, 3)
            assert (len(marks[f"sample, {kind}"]._offsets3d[0]) if f"sample, {kind}" in marks else 0) == len(expected)
            assert expected.size == 0 or np.allclose(shape(marks[f"sample, {kind}"].get_paths()[0]), shape(marker))
        parts = links(close_up)
        assert {float(c.get_linewidth()[0]) for c in parts} == {still_panels.LINK_EDGE}
        assert {c.get_alpha() for c in parts} == {1.0}  # opaque: the robot reads as one body over the faded blocks
    traces = [line for ax in fig.axes for line in ax.get_lines() if line.get_gid() not in ("robot", "shadow", "drop")]
    assert traces and all(line.get_linestyle() == "--" for line in traces)


def test_a_stills_overview_thins_a_dense_cloud_and_its_text_says_so(crossing):
    robot, workspace, _, _, _ = crossing
    assert len(workspace.boxes) > still_panels.DENSE_BLOCKS  # reader r33e: a dense workspace's overview draws fewer
    n = 2 * still_panels.DENSE_SAMPLES + 1
    points = robot.link_boxes(robot.sample(np.random.default_rng(0), n))[0][:, 0]  # (n, 3) bases
    valid = np.arange(n) % 5 == 0  # (n,) every 5th: 0, 5, 10, ...
    fig = scenes.scene_still(
        robot,
        workspace,
        {"here": robot.sample(np.random.default_rng(1), 1)[0]},
        samples=(points, {"valid": valid, "in collision": ~valid}),
    )
    close_up, overview = fig.axes  # one pose: seen once, a whole row wide, above the overview (reader r31e)
    assert close_up.get_title() == "here, close up"
    drawn = {c.get_label(): c for c in overview.collections if c.get_label().startswith("sample")}
    kept = np.arange(n) % 3 == 0  # 1 in 3: at most DENSE_SAMPLES of 2 * DENSE_SAMPLES + 1
    assert len(drawn["sample, valid"].get_offsets()) == int((kept & valid).sum())
    assert len(drawn["sample, in collision"].get_offsets()) == int((kept & ~valid).sum())
    assert all(c.get_alpha() < 1 for c in drawn.values())  # lighter: the blocks show through
    FigureCanvasAgg(fig).draw()  # the overview a whole row under the close-ups (review r16c), the legend under it
    assert overview.get_position().y1 <= close_up.get_position().y0
    assert overview.get_position().width > 0.6 and close_up.get_position().width > 0.4  # each a row (r16c, r31e)
    assert fig.legends[0].get_window_extent().y1 <= overview.get_position().y0 * fig.bbox.height
    lo, hi = np.array([close_up.get_xlim(), close_up.get_ylim(), close_up.get_zlim()]).T  # (3,) each
    near = int(np.all((points >= lo) & (points <= hi), axis=1).sum())  # every sample in its window, thinned or not
    assert f"{int(valid.sum())} samples valid (circles), {int((~valid).sum())} samples in collision" in alt_text(fig)
    thinned = "1 sample in every 3 drawn (in the order sampled, whatever its kind)"
    assert f"in collision (diamonds), {thinned}" in alt_text(fig)
    said = f"as a still: first the robot close up among the blocks near it: here, {near} sample{'s' * (near != 1)} "
    assert near and f"{said}near it, the robot seen across" in alt_text(fig)  # reader r32e: the close-up, drawn first


def test_a_stills_model_wrong_star_is_hollow_round_the_mark_it_flags_larger_round_a_diamond(crossing):
    robot, workspace, _, path, valid = crossing
    points = robot.link_boxes(path)[0][:, 0]  # (T, 3)
    wrong = np.arange(len(points)) % 3 == 0
    kinds = {"valid": valid, "in collision": ~valid, "model wrong": wrong}
    fig = scenes.scene_still(robot, workspace, {}, samples=(points, kinds))
    overview = fig.axes[0]
    (stars,) = [c for c in overview.collections if c.get_label() == "sample, model wrong"]
    (large,) = [c for c in overview.collections if c.get_label() == still_panels.DANGEROUS_LABEL]
    assert len(stars.get_offsets()) == int((wrong & valid).sum()) and len(large.get_offsets()) == int(
        (wrong & ~valid).sum()
    )
    # reader r27e: a dangerous mistake's star told apart from a conservative one's: larger, its line thicker
    assert large.get_sizes()[0] > 1.5 * stars.get_sizes()[0] and large.get_linewidth()[0] > stars.get_linewidth()[0]
    legend = dict(zip([t.get_text() for t in fig.legends[0].get_texts()], fig.legends[0].legend_handles))
    # reader r21c: its star drawn round a mark, as in the panels, not empty; r24b: one entry per kind of mistake
    assert still_panels.DANGEROUS_ENTRY in legend and still_panels.CONSERVATIVE_ENTRY in legend
    assert "sample, model wrong" not in legend and still_panels.DANGEROUS_LABEL not in legend
    (circle,) = [c for c in overview.collections if c.get_label() == "sample, valid"]
    (diamond,) = [c for c in overview.collections if c.get_label() == "sample, in collision"]
    kinds = {"sample, valid": circle, "sample, in collision": diamond, "sample, model wrong": stars}
    both = still_panels.star_on_mark(kinds | {still_panels.DANGEROUS_LABEL: large})
    assert both[still_panels.DANGEROUS_ENTRY] == (diamond, large) and both[still_panels.CONSERVATIVE_ENTRY] == (
        circle,
        stars,
    )
    entry = still_panels.star_on_mark({"sample, valid": circle, "sample, model wrong": stars})
    assert entry == {"sample, valid": circle, still_panels.CONSERVATIVE_ENTRY: (circle, stars)}
    assert len(stars.get_facecolor()) == 0 or stars.get_facecolor()[0][3] == 0  # the circle or diamond shows inside
    # round the mark, larger than it (reader r41e: smaller than before in the overview, where they overlapped)
    assert 2.5 * still_panels.SAMPLE_MARKS["valid"][2] < stars.get_sizes()[0] < 150
    with pytest.raises(ValueError, match="drawn in 3D"):
        scenes.scene_still(scenarios.get("2ds").robot, workspace, {})


def test_a_stills_close_up_says_what_the_model_answers(crossing):
    """Review r17c: nothing on the still marked that the model rejects the valid robot (P = 0.08). The close-up's
    title says it, and the text; a still without a model says nothing of a model."""
    robot, workspace, _, path, _ = crossing
    q = path[0]
    fig = scenes.scene_still(
        robot, workspace, {"the robot": q}, valid={"the robot": True}, model={"the robot": (0.08, False)}
    )
    close_up, _ = fig.axes
    # readers r28e, r29e: and says the robot is itself a mistake, the conservative kind
    assert (
        close_up.get_title()
        == "the robot, close up, valid\nthe model: P(valid) 0.08, rejects it:\na conservative mistake"
    )
    assert "the robot, valid, the model: P(valid) 0.08, rejects it: a conservative mistake" in alt_text(fig)
    accepted = scenes.scene_still(robot, workspace, {"start": q}, model={"start": (0.914, True)})
    assert accepted.axes[0].get_title().endswith("the model: P(valid) 0.91, accepts it")
    assert "model" not in scenes.scene_still(robot, workspace, {"start": q}).axes[0].get_title()


def test_a_stills_overview_stars_mistakes_as_often_as_the_model_makes_them(crossing):
    """Reader r19c: every mistake drawn beside every k-th right answer made stars look like 40 % of the marks where the
    model erred on 5 %. Thinned to every k-th of every kind alike, the overview stars the conservative mistakes among
    them, so its share of those stars is the model's rate of them; reader r27e: every dangerous mistake drawn, thinned
    or not (the rare kind: thinning left one of 13). Its title and text say which k, and the dangerous ones added."""
    robot, workspace, _, _, _ = crossing
    assert len(workspace.boxes) > still_panels.DENSE_BLOCKS  # reader r33e: a dense workspace's overview draws fewer
    n = 2 * still_panels.DENSE_SAMPLES + 1
    points = robot.link_boxes(robot.sample(np.random.default_rng(0), n))[0][:, 0]  # (n, 3) bases
    valid = np.arange(n) % 5 == 0  # (n,)
    wrong = np.arange(n) % 7 == 1  # (n,) 29 of 201: 14 %
    kinds = {"valid": valid, "in collision": ~valid, "model wrong": wrong}
    fig = scenes.scene_still(robot, workspace, {}, samples=(points, kinds))
    overview = fig.axes[0]
    drawn = {c.get_label(): len(c.get_offsets()) for c in overview.collections}
    kept = np.arange(n) % 3 == 0  # (n,) 1 in 3, whatever its kind
    dangerous = wrong & ~valid  # (n,) every one drawn
    assert drawn["sample, model wrong"] == int((kept & wrong & valid).sum())  # conservative: thinned alike
    assert drawn[still_panels.DANGEROUS_LABEL] == int(dangerous.sum()) == 23
    assert drawn["sample, valid"] == int((kept & valid).sum())
    assert drawn["sample, in collision"] == int(((kept | dangerous) & ~valid).sum())
    stars = drawn["sample, model wrong"] / drawn["sample, valid"]
    assert stars == pytest.approx((wrong & valid).sum() / valid.sum(), abs=0.05)
    extra = int((dangerous & ~kept).sum())
    assert extra > 0  # reader r34e: the title counts both kinds, so 13 drawn large do not outnumber 97 drawn 1 in 20
    conservative = int((wrong & valid).sum())
    assert overview.get_title().endswith(
        f"1 sample in 3 drawn\n23 dangerous mistakes, all drawn; {conservative} conservative, "
        f"{drawn['sample, model wrong']} drawn"  # reader r39e, 05 figure 6: "5 drawn", not "1 in 20"
    )
    thinned = "1 sample in every 3 drawn (in the order sampled, whatever its kind)"
    assert f"{thinned}, and all the dangerous mistakes" in alt_text(fig)


@pytest.mark.parametrize("index", [0, FRAMES // 2])
def test_no_text_of_a_frame_lies_over_another(crossing, index):
    """Chapter 05's frame at the site's width: the names at the DoF lines' ends a line of text apart even where every
    line ends at the same height (here all at mid-bounds), and no text of one panel (the 3D panel's z label, the
    right panels' axis names) over a text of another."""
    robot, workspace, _, path, valid = crossing
    path = path.copy()
    path[-1] = (robot.lower + robot.upper) / 2  # every DoF ends at 0.5 of its bounds: seven names at one height
    fig = scenes.path_frame(
        robot, path, index, workspace=workspace, valid=valid, clearance=np.linspace(0.1, 1, FRAMES), probability=valid
    )
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    names = [t for ax in fig.axes[1:] for t in ax.texts if t.get_text() in robot.dof_names]
    assert len(names) == robot.dof
    boxes = [(t, Text.get_window_extent(t, renderer)) for t in drawn_texts(fig)]  # the text's box, not its leader's
    over = [
        f"{a.get_text()!r} / {b.get_text()!r}"
        for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2)
        if box_a.overlaps(box_b) and min(box_a.intersection(box_a, box_b).size) > 1
    ]
    assert over == []
    for ax in fig.axes[1:]:  # in each panel, the names a line of text apart
        heights = sorted(box.y0 for t, box in boxes if t in names and t in ax.texts)  # pixels, at 100 dpi
        assert len(heights) < 2 or np.min(np.diff(heights)) >= dof_panels.LABEL_GAP * fig.dpi / 72 - 1


def test_the_names_at_the_dof_lines_ends_are_ink_and_their_leaders_stay_outside_the_panel(crossing):
    """WCAG 1.4.3: a DoF's name at its line's end is 8-point text, so it is drawn in ink (at least 4.5:1 on the
    panel's white, the palette's line colours reach 3.1 to 3.9:1). Its leader is thin, grey and wholly right of the
    panel (reader r19c: a solid stroke in the line's colour inside the panel, past the path's end, read as data)."""
    robot, workspace, _, path, valid = crossing
    fig = scenes.path_frame(robot, path, 0, workspace=workspace, valid=valid, clearance=None, probability=None)
    renderer = FigureCanvasAgg(fig).get_renderer()
    fig.draw(renderer)
    names = [t for ax in fig.axes[1:] for t in ax.texts if t.get_text() in robot.dof_names]
    assert sorted(t.get_text() for t in names) == sorted(robot.dof_names)
    low = {t.get_text(): round(contrast(to_hex(t.get_color()), "#ffffff"), 2) for t in names}
    assert {name: ratio for name, ratio in low.items() if ratio < 4.5} == {}
    line_colors = {to_hex(c) for c in palette.LINE_COLORS}
    for ax in fig.axes[1:]:
        right = ax.get_window_extent(renderer).x1  # pixels: the panel's right edge
        for name in (t for t in ax.texts if t.get_text() in robot.dof_names):
            stroke = name.arrow_patch
            assert stroke is not None and to_hex(stroke.get_edgecolor()) == dof_panels.LEADER_COLOR
            assert dof_panels.LEADER_COLOR not in line_colors and stroke.get_linewidth() < 1.0
            assert stroke.get_window_extent(renderer).x0 >= right - 0.5, name.get_text()


def drawn_texts(fig) -> list[Text]:
    """The texts a figure draws: every visible text but the labels of ticks outside their axis's view."""
    hidden = set()
    for ax in fig.axes:
        for axis in [ax.xaxis, ax.yaxis, *([ax.zaxis] if hasattr(ax, "zaxis") else [])]:
            low, high = sorted(axis.get_view_interval())
            hidden |= {t.label1 for t in axis.get_major_ticks() if not low - 1e-9 <= t.get_loc() <= high + 1e-9}
    texts = [t for t in fig.findobj(Text) if t.get_visible() and t.get_text().strip() and t not in hidden]
    return [t for t in texts if t.get_window_extent().width > 0]


def test_an_angle_that_wraps_around_runs_out_at_one_edge_and_comes_back_at_the_other_not_across_the_panel():
    robot = scenarios.get("3dc7").robot
    Q = np.zeros((4, robot.dof))
    Q[:, 3] = [3.0, 3.1, -3.1, -3.0]  # alpha goes through pi = -pi between frames 1 and 2
    Q[:, 0] = [1.0, 2.0, 3.0, 4.0]  # x does not wrap
    fig = Figure()
    ax = fig.subplots()
    along = np.linspace(0.0, 1.0, 4)
    dof_panels.draw_dofs(fig, robot, Q, [3], "angles", ax, along)
    dof_panels.draw_dofs(fig, robot, Q, [0], "position", ax, along)
    alpha, x = ax.get_lines()
    scaled = (Q[:, 3] - robot.lower[3]) / (robot.upper[3] - robot.lower[3])  # (4,) near 1, then near 0
    np.testing.assert_allclose(alpha.get_ydata(), [scaled[0], scaled[1], 1.0, np.nan, 0.0, scaled[2], scaled[3]])
    edge = along[1] + (along[2] - along[1]) / 2  # 3.1 to pi is halfway from 3.1 to -3.1 (= 2 pi - 3.1)
    np.testing.assert_allclose(alpha.get_xdata(), [along[0], along[1], edge, np.nan, edge, along[2], along[3]])
    assert set(alpha.get_markevery()) <= {0, 1, 5, 6}  # markers on frames only, none at the edges
    assert len(x.get_xdata()) == 4  # unbroken
    text = alt_text(scenes.path_frame(robot, Q, 0))  # review r16c: the description said nothing of the jump
    assert "alpha wraps round (crosses ±π, its line jumping from one edge of its panel to the other) at 50%" in text
    assert "x wraps" not in text
    title = scenes.path_frame(robot, Q, 0).legends[0].get_title().get_text()  # reader r20c: a gap read as data lost
    assert (
        title
        == "each DoF in its bounds: 0 lower, 1 upper\nalpha: at ±π a line leaves one edge and comes back at the other"
    )
    assert f"at 50% (from {scaled[1]:.2f} to {scaled[2]:.2f})" in text  # the edges its line leaves and comes back at
    Q[:, 5] = [3.0, -3.1, -3.0, -2.9]  # gamma too
    assert dof_panels.wrap_note(robot, Q, [3, 4, 5]).startswith("\nalpha and gamma: at ±π")
    assert dof_panels.wrap_note(robot, Q[:, [0, 1, 2, 4, 4, 4, 6]], [3, 4, 5]) == ""  # beta alone: no wrap


def test_an_angle_that_wraps_after_its_first_frame_runs_that_frame_to_the_edge_no_lone_marker():
    """Reader r21c: beta "0.00 to 0.38" in words, but its line began near 1.00: frame 0 alone, before a wrap, drew
    nothing. Reader r23b: a lone marker for it read as an outlier. Now frame 0's piece is a line to the edge it
    crosses (the bottom, -π), the line coming back at the top; no marker of its own, and the words name both edges."""
    robot = scenarios.get("3dc7").robot
    Q = np.zeros((4, robot.dof))
    Q[:, 4] = [-3.14, 3.1, 3.0, 2.9]  # beta wraps between frames 0 and 1
    fig = Figure()
    ax = fig.subplots()
    dof_panels.draw_dofs(fig, robot, Q, [4], "angles", ax, np.linspace(0.0, 1.0, 4))
    (line,) = ax.get_lines()  # one line, no lone marker beside it
    scaled = (Q[:, 4] - robot.lower[4]) / (robot.upper[4] - robot.lower[4])
    np.testing.assert_allclose(line.get_ydata(), [scaled[0], 0.0, np.nan, 1.0, *scaled[1:]])
    assert line.get_xdata()[1] == line.get_xdata()[3] > 0.0  # out at the bottom and in at the top, where it wraps
    text = alt_text(scenes.path_frame(robot, Q, 0))
    assert "beta wraps round (crosses ±π, its line jumping from one edge of its panel to the other) at 17% (from " in (
        text
    )
    assert f"(from {scaled[0]:.2f} to {scaled[1]:.2f})" in text


@pytest.mark.parametrize(("name", "seed", "count"), [("3dc9", 1, 3), ("3do", 2, 1)])
def test_no_text_of_a_still_lies_over_another(name, seed, count):
    """The close-ups look from any side (:func:`toolkit.plots.still_panels.view_angles`): an axis' name then lands
    where it lands, and side by side a panel's z name met its neighbour's tick labels (these two cases did)."""
    scenario = scenarios.get(name)
    workspace, robot = scenario.make_workspace(np.random.default_rng(0)), scenario.robot
    Q = robot.sample(np.random.default_rng(seed), 80)
    Q = Q[exact_checker(workspace, robot).are_valid(Q)][:count]  # (count, dof) valid poses
    poses = dict(zip(("start", "middle", "goal"), Q)) if count > 1 else {"the robot": Q[0]}
    fig = scenes.scene_still(robot, workspace, poses, valid=dict.fromkeys(poses, True))
    FigureCanvasAgg(fig).draw()
    boxes = [(t, Text.get_window_extent(t)) for t in drawn_texts(fig)]
    over = [
        f"{a.get_text()!r} / {b.get_text()!r}"
        for (a, box_a), (b, box_b) in itertools.combinations(boxes, 2)
        if box_a.overlaps(box_b) and min(box_a.intersection(box_a, box_b).size) > 1
    ]
    assert over == []


def test_a_path_frames_camera_turns_off_a_block_straight_behind_the_robot():
    """Review r17c: at frame 39 the valid robot (clearance 0.030) looked inside the "nearest block" box standing
    behind it. A unit block 1.5 units behind the robot as mplot3d's usual camera (30, -60) sees it turns the camera
    (the least of scenes.FRAME_TURNS that misses it); with no block on that line the camera stays."""
    robot = scenarios.get("3dc7").robot
    path = np.array([[5.0, 5.0, 5.0, 0.7, 0.0, 0.0, 0.0], [5.5, 5.0, 5.0, 0.7, 0.0, 0.0, 0.0]])  # (2, 7)
    toward = np.array([np.cos(np.pi / 6) * np.cos(-np.pi / 3), np.cos(np.pi / 6) * np.sin(-np.pi / 3), 0.5])  # (3,)
    centre = robot.link_boxes(path[:1])[0][0].mean(axis=0) - 1.5 * toward  # (3,) behind the robot, seen so
    behind = Workspace(np.zeros(3), np.full(3, 11.0), np.array([[centre - 0.5, centre + 0.5]]), family="3dc")
    aside = Workspace(np.zeros(3), np.full(3, 11.0), np.array([[[8.0, 8.0, 8.0], [9.0, 9.0, 9.0]]]), family="3dc")
    turned = scenes.path_frame(robot, path, 0, workspace=behind).axes[0]
    kept = scenes.path_frame(robot, path, 0, workspace=aside).axes[0]
    assert (kept.elev, kept.azim) == (30.0, -60.0)
    assert turned.elev == 30.0 and (turned.azim + 60.0) in scenes.FRAME_TURNS[1:]


def test_a_path_frames_camera_never_looks_along_an_axis():
    """Reader r19c: a frame turned to look along x piled its tick labels onto its name ("5 x"). Every turn a path
    frame's camera may take keeps it at least 20 degrees from every axis of the workspace, as a close-up's does."""
    azimuths = (-60.0 + np.array(scenes.FRAME_TURNS)) % 90.0  # (turns,) degrees past the last axis
    assert np.all((azimuths >= still_panels.OFF_AXIS) & (azimuths <= 90.0 - still_panels.OFF_AXIS))
    assert scenes.FRAME_TURNS[0] == 0.0  # mplot3d's usual camera first


@pytest.mark.parametrize("valid", [True, False])
def test_a_single_robot_in_a_still_overview_is_ringed_and_named_left_of_every_mark(valid):
    """Reader r23b: in chapter 05's cube of 123 blocks the robot, about 10 px tall, was hard to find and its name, above
    it, sat on marks. Now a ring round it, and its name beside the region, left of every sample and block, a leader
    from the name to the ring."""
    scenario = scenarios.get("3dc9")
    workspace, robot = scenario.make_workspace(np.random.default_rng(0)), scenario.robot
    Q = robot.sample(np.random.default_rng(0), 300)
    q = Q[exact_checker(workspace, robot).are_valid(Q) == valid][0]
    kinds = {"valid": np.arange(300) % 2 == 0, "in collision": np.arange(300) % 2 == 1}
    fig = scenes.scene_still(robot, workspace, {"the robot": q}, valid={"the robot": valid}, samples=(Q[:, :3], kinds))
    FigureCanvasAgg(fig).draw()
    overview = fig.axes[1]  # after the one close-up (reader r31e)
    (ring,) = [c for c in overview.collections if c.get_gid() == "robot ring"]
    (name,) = [t for t in overview.texts if t.get_gid() == "pose label"]
    assert name.get_text() == ("the robot" if valid else "the robot,\nin collision") and name.arrow_patch is not None
    marks = [c for c in overview.collections if c.get_gid() != "robot ring" and len(c.get_offsets())]
    lefts = [overview.transData.transform(c.get_offsets())[:, 0].min() for c in marks]  # px: each kind's leftmost
    assert marks and Text.get_window_extent(name).x1 < min(lefts)
    centre = robot.link_aabbs(q[None])[0].mean(axis=(0, 1))  # (3,) where the ring is
    np.testing.assert_allclose(np.ravel(ring._offsets3d), centre)
    assert "the robot drawn over them, ringed, its name beside the workspace" in alt_text(fig)


def test_a_path_frame_draws_the_closest_pair_labelled_with_the_gap_and_the_bound():
    """Reader r30e: at frame 48 the title said "clearance ≥ 0.028" while the chain stood well away from the nearest
    block; the frame draws the gap itself, an ink line between the closest points, labelled with its length and the
    bound, the length never below the exact checker's bound."""
    scenario = scenarios.get("3dc7")
    robot = scenario.robot
    q = np.zeros(robot.dof)
    q[:3] = (5.0, 5.0, 5.0)  # at rest: the links axis-aligned, so the top face's grid holds the closest point
    top = robot.link_aabbs(q[None])[0][:, 1, 2].max()
    blocks = np.array([[[4.0, 4.0, top + 0.25], [6.0, 6.0, top + 1.25]]])
    workspace = Workspace(np.zeros(3), np.full(3, 11.0), blocks, family="3dc")
    bound = float(exact_checker(workspace, robot).clearances(q[None], cap=1.0)[0])
    robot_point, block_point, gap = closest_pair.closest_pair(robot, q, blocks)
    assert gap == pytest.approx(0.25) and gap >= bound - 1e-9
    assert block_point[2] == pytest.approx(top + 0.25) and robot_point[2] == pytest.approx(top)
    fig = scenes.path_frame(robot, np.stack([q, q]), 0, workspace=workspace, clearance=[bound, bound])
    scene = fig.axes[0]
    assert [line.get_gid() for line in scene.get_lines()].count("closest") == 1
    assert [t.get_text() for t in scene.texts if "apart" in t.get_text()] == [f"0.250 apart\n(bound {bound:.3f})"]
    # reader r33e: the base's dashed trace ran through the label; it is drawn above every line and face, on white
    fig.canvas.draw()  # mplot3d gives its artists their z-orders by depth when it draws
    label = next(t for t in scene.texts if "apart" in t.get_text())
    drawn = [*scene.get_lines(), *scene.collections, *scene.patches]
    assert label.get_zorder() > max(a.get_zorder() for a in drawn)
    assert label.get_bbox_patch() is not None and label.get_bbox_patch().get_facecolor()[:3] == (1.0, 1.0, 1.0)


def test_an_overview_draws_a_sparse_workspaces_blocks_darker_and_a_dense_ones_fainter_with_fewer_samples():
    """Reader r33e: the office's 30 blocks were very faint on its wide floor, and 3DC-9's 123 blocks with 167 marks a
    grey haze. Blocks of a sparse workspace are drawn darker than a dense one's, and a dense one's overview draws at
    most DENSE_SAMPLES samples."""
    sparse, dense = (still_panels.OVERVIEW_BLOCKS[d] for d in (False, True))
    assert sparse[0]["alpha"] > dense[0]["alpha"] and sparse[0]["linewidth"] > dense[0]["linewidth"]
    assert all(far["alpha"] < near["alpha"] for far, near in (sparse, dense))  # the blocks near the robot darker
    office, clutter = (len(scenarios.get(s).make_workspace(np.random.default_rng(0)).boxes) for s in ("3do", "3dc9"))
    assert office <= still_panels.DENSE_BLOCKS < clutter
    assert still_panels.overview_step(2000, office) == 10 and still_panels.overview_step(500, clutter) == 5


def test_the_frame_title_names_a_dip_beside_the_frame():
    """Reader r35e, 05 item 4: the P(valid) panel's dip to 0.575 at frame 47 touched frame 48's line, whose title said
    0.92; the title now names a neighbour more than 0.1 lower, and only then."""
    from toolkit.plots.scenes import _frame_title

    series = {"valid": None, "clearance": None, "probability": np.array([0.9, 0.575, 0.92, 0.95])}
    assert _frame_title(2, 4, series, 0.57) == "frame 2 (frames 0–3): P(valid) 0.92 ≥ threshold 0.57 (frame 1: 0.57)"
    assert _frame_title(3, 4, series, 0.57) == "frame 3 (frames 0–3): P(valid) 0.95 ≥ threshold 0.57"


def test_a_path_frame_dots_its_p_valid_ticks_a_dip_and_the_nodes_and_draws_no_markers_on_the_dofs(crossing):
    """Reader r39e, 05 figures 1-2: frame 48's line crossed frame 47's dip, so 0.92 read as 0.58; and markers every
    few frames read as roadmap nodes. Now a dot at the frame's P(valid), a tick at the dip, none on the DoF lines, and
    a tick on each panel's lower edge at each node of the path."""
    from toolkit.plots import path_marks

    robot, workspace, _, path, valid = crossing
    nodes = path[[0, FRAMES // 2, -1]]  # (3, dof): a straight path, three of its frames named its nodes
    probability = np.full(FRAMES, 0.9)
    probability[FRAMES // 2 - 1] = 0.55  # a dip just before the frame shown
    fig = scenes.path_frame(
        robot, path, FRAMES // 2, workspace=workspace, valid=valid, probability=probability, threshold=0.5, nodes=nodes
    )
    panels = [ax for ax in fig.axes if any(h.get_gid() == "now" for h in ax.get_lines())]
    assert all(h.get_marker() in ("None", None, "") for ax in panels for h in ax.get_lines() if h.get_gid() == "dof")
    assert all(h.get_marker() in ("None", None, "") for h in fig.legends[0].legend_handles)
    ticks = [[h.get_xdata()[0] for h in ax.get_lines() if h.get_gid() == "node"] for ax in panels]
    assert all(t == pytest.approx([0.0, 0.5, 1.0]) for t in ticks)
    along = np.linspace(0.0, 1.0, FRAMES)
    (dot,) = [h for h in panels[-1].get_lines() if h.get_gid() == "frame value"]
    assert (dot.get_xdata()[0], dot.get_ydata()[0]) == (along[FRAMES // 2], 0.9)
    (dip,) = [h for h in panels[-1].get_lines() if h.get_gid() == "dip"]
    said = f"frame {FRAMES // 2 - 1}\n0.550 ≥ 0.500\ncalled valid"  # reader r42e: the ring's verdict, not hidden
    assert dip.get_xdata()[0] == along[FRAMES // 2 - 1] and said in [t.get_text() for t in panels[-1].texts]
    # reader r40e, 05 contradiction 2: the dip's mark sits on its value, small, and its label above it, so neither
    # crosses a threshold just under the dip
    assert dip.get_ydata()[0] == 0.55 and dip.get_marker() == "o" and dip.get_markersize() <= 5
    (label,) = [t for t in panels[-1].texts if t.get_text() == said]
    assert label.get_va() == "bottom" and label.get_position()[1] > 0
    assert path_marks.dip_beside(probability, FRAMES // 2 - 3) is None and "roadmap nodes" in panels[-1].get_xlabel()


def test_a_close_ups_marks_over_the_robot_are_found_in_the_box_as_drawn(crossing):
    """Reader r42e: a diamond stood on a valid robot's link. The marks were measured in the panel's own (wide) shape,
    before mplot3d squares it, so their pixels were stretched; now in the box as drawn, the panel left as it was."""
    robot, workspace, _, path, _ = crossing
    fig = Figure(figsize=(6.1, 3.0))
    ax = fig.add_subplot(projection="3d")
    still_panels.close_up(ax, robot, path[0], workspace, color=VALID_COLOR, margin=0.5)
    offsets = np.stack(np.meshgrid(*[np.linspace(-0.3, 0.3, 9)] * 3), axis=-1).reshape(-1, 3)  # (729, 3)
    points = path[0][:3] + offsets  # (729, 3) round the robot's base
    panel = ax.get_position(original=True).bounds
    over = still_panels.over_robot(ax, robot, path[0], points)
    assert ax.get_position(original=True).bounds == panel and over.any() and not over.all()
    FigureCanvasAgg(fig).draw()  # as the page draws it: the box squared
    assert np.array_equal(over, still_panels.over_robot(ax, robot, path[0], points))


def test_a_robot_standing_on_the_floor_gets_no_line_down_to_it():
    """Reader r43e: 3DO's legend named "the robot's base, straight down to the floor" for a youBot on the floor."""
    office, chain = scenarios.get("3do"), scenarios.get("3dc7")
    standing = office.robot.sample(np.random.default_rng(1), 5)  # (5, 8) the youBot's base on the floor, any pose
    assert still_panels.on_floor(office.robot, list(standing), 0.0)
    assert not still_panels.on_floor(chain.robot, [np.full(chain.robot.dof, 0.5)], -1.0)  # the chain flies
    fig = Figure()
    ax = fig.add_subplot(projection="3d")
    still_panels._floor_cues(ax, office.robot, list(standing), None, 0.0)
    assert not [line for line in ax.get_lines() if line.get_gid() == "drop"]
