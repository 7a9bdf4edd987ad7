"""The viewer's scene and GUI, driven from Python: nodes per scenario, sliders, colors, plans, events, ports.
Embedded pages are tested in test_viewer_embed.py."""

import ast
import dataclasses
import re
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest
from matplotlib import image as mpimg

from toolkit import scenarios, viewer
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.learning import learned
from toolkit.planning import sampling
from toolkit.planning.prm import GOAL, START
from toolkit.viewer import browser as viewer_browser
from toolkit.viewer import drawing as draw


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Flipped(CollisionChecker):
    """A "model" that is always wrong: predicts the opposite of the exact checker."""

    def __init__(self, workspace, robot):
        super().__init__(robot)
        self.exact = exact_checker(workspace, robot)

    def probability(self, Q):
        return np.where(self.exact.are_valid(Q), 0.0, 1.0)

    def validity(self, Q):
        return ~self.exact.are_valid(Q)


@pytest.fixture
def make_panel(make_viewer):
    """GUI panels over viewers on free ports, as ``viewer.launch`` joins them; ``panel.viewer`` is the scene."""
    return lambda scenario, **kwargs: viewer.Panel(make_viewer(scenario, **kwargs))


def link_colors(v):
    return np.asarray(v.nodes["robot"].batched_colors)


@pytest.mark.parametrize("name", ["2ds", "3do", "3dc7", "3dc9"])
def test_scene_holds_the_workspace_and_the_robot(make_panel, name):
    panel = make_panel(name, seed=3)
    v = panel.viewer
    scenario = scenarios.get(name)
    ws = scenario.make_workspace(np.random.default_rng(3))
    assert v.workspace == ws
    obstacles = v.nodes["obstacles"]
    assert len(obstacles.batched_positions) == len(ws.boxes)  # one instanced box per block
    lo, hi = ws.boxes[:, 0], ws.boxes[:, 1]
    np.testing.assert_allclose(obstacles.batched_positions[:, : ws.dim], (lo + hi) / 2, atol=1e-5)
    np.testing.assert_allclose(obstacles.batched_scales[:, : ws.dim], hi - lo, atol=1e-5)
    assert np.asarray(v.nodes["region"].points).shape == (12, 2, 3)
    links = v.nodes["robot"]
    assert len(links.batched_positions) == scenario.robot.n_links
    centers = scenario.robot.link_boxes(v.q[None])[0][0]  # (L, D)
    np.testing.assert_allclose(links.batched_positions[:, : ws.dim], centers, atol=1e-5)
    assert v.valid and exact_checker(ws, scenario.robot).is_valid(v.q)
    assert np.all(link_colors(v) == draw.VALID)
    sliders = panel.sliders
    assert [s.label for s in sliders] == list(scenario.robot.dof_names)
    np.testing.assert_allclose([s.min for s in sliders], scenario.robot.lower)
    np.testing.assert_allclose([s.max for s in sliders], scenario.robot.upper)
    np.testing.assert_allclose([s.value for s in sliders], v.q)
    # reader r15b: the yaw's box showed 2.5128 cut off and its ends read -3.141593: each slider steps by the power of
    # ten under 1/500 of its range, shows that many decimals, and labels its ends with two
    range_ = scenario.robot.upper - scenario.robot.lower  # (dof,)
    steps = np.array([s.step for s in sliders])
    assert np.all((steps <= range_ / 500) & (steps > range_ / 5000))
    assert [s.precision for s in sliders] == [round(-np.log10(step)) for step in steps]
    assert all(s.precision <= 3 for s in sliders), [s.precision for s in sliders]  # viser's covered the ends': 6
    assert "prediction" not in v.nodes and "disagreement" not in v.nodes  # no model loaded


@pytest.mark.parametrize("name", ["2ds", "3dc7"])
def test_every_block_is_outlined_by_edges_that_stand_out(make_viewer, name):
    """WCAG 1.4.11: a block's faces are 1.3:1 on the viewer's white (a see-through 3DC block fainter still), so each
    block's 12 edges outline it, in a colour at 3:1 or more on the white and on any block face (opaque or see-through
    over the white, lit or in shade); they hide and show with the obstacles."""
    from toolkit.plots.palette import contrast

    v = make_viewer(name, seed=3)
    blocks = v.workspace.boxes  # (K, 2, D)
    lo = np.zeros((len(blocks), 3))  # the blocks' corners in 3D; 2D blocks stand on the floor, FLAT_HEIGHT high
    hi = np.full((len(blocks), 3), draw.FLAT_HEIGHT)
    lo[:, : v.workspace.dim], hi[:, : v.workspace.dim] = blocks[:, 0], blocks[:, 1]
    edges = np.asarray(v.nodes["obstacle_edges"].points).reshape(len(blocks), 12, 2, 3)  # per block, in its order
    at_corner = np.isclose(edges, lo[:, None, None]) | np.isclose(edges, hi[:, None, None])  # (K, 12, 2, 3)
    assert at_corner.all()  # every end is one of its block's corners
    moved = ~np.isclose(edges[:, :, 0], edges[:, :, 1])  # (K, 12, 3): the one axis an edge runs along
    assert (moved.sum(axis=-1) == 1).all() and (moved.sum(axis=1) == 4).all()  # 4 edges along each axis
    ends = np.sort(edges, axis=2).reshape(len(blocks), 12, 6)
    assert all(len(np.unique(block, axis=0)) == 12 for block in ends)  # 12 different edges

    def hex_of(rgb) -> str:
        return "#" + "".join(f"{int(round(c)):02x}" for c in rgb)

    face = np.array(draw.OBSTACLE, dtype=float)
    opacity = draw.OBSTACLE_OPACITY.get(v.workspace.family, 1.0)
    faces = [hex_of(shade * face * alpha + 255 * (1 - alpha)) for shade in (0.5, 1.0) for alpha in (opacity, 1.0)]
    edge = hex_of(np.asarray(v.nodes["obstacle_edges"].colors).reshape(-1, 3)[0])
    assert min(contrast(edge, background) for background in ["#ffffff", *faces]) >= 3.0
    assert contrast(hex_of(face), "#ffffff") < 1.5  # the faces alone: why the edges are there
    v.set_visible("obstacles", False)
    assert not v.nodes["obstacle_edges"].visible and not v.nodes["obstacles"].visible
    v.set_visible("obstacles", True)
    assert v.nodes["obstacle_edges"].visible


@pytest.mark.parametrize("name", ["3dc9", "3do", "2ds"])
def test_every_link_is_edged_and_its_edges_move_with_it(make_viewer, name, rng):
    """Reader r13b: chapter 05's 9-DoF chain read as one thin bar among the blocks. Each link's 12 edges are drawn
    in the blocks' ink, so each link reads as a box and the joints show: in the link's own frame (the robot's
    ``link_boxes``) every end of an edge is a corner, at plus or minus half its size on each axis, 4 edges along
    each axis; they follow the robot to a new configuration and hide and show with it."""
    v = make_viewer(name, seed=1)
    for q in (v.q, v.robot.sample(rng, 1)[0]):
        v.set_configuration(q)
        centers, rotations, half = v.robot.link_boxes(q[None])  # (1, L, D), (1, L, D, D), (L, D)
        centers, rotations = centers[0], rotations[0]
        if v.robot.dim == 2:  # the flat scene: the square stands on the floor, FLAT_ROBOT_HEIGHT high
            centers = np.column_stack([centers, np.full(len(centers), draw.FLAT_ROBOT_HEIGHT / 2)])
            rotations = np.stack(
                [np.block([[r, np.zeros((2, 1))], [np.zeros((1, 2)), np.ones((1, 1))]]) for r in rotations]
            )
            half = np.column_stack([half, np.full(len(half), draw.FLAT_ROBOT_HEIGHT / 2)])
        edges = np.asarray(v.nodes["link_edges"].points, dtype=float).reshape(len(half), 12, 2, 3)
        local = np.einsum("lji,lkej->lkei", rotations, edges - centers[:, None, None])  # (L, 12, 2, 3) link frames
        np.testing.assert_allclose(np.abs(local), np.broadcast_to(half[:, None, None], local.shape), atol=1e-5)
        along = ~np.isclose(local[:, :, 0], local[:, :, 1], atol=1e-5)  # (L, 12, 3): the axis each edge runs along
        assert (along.sum(axis=-1) == 1).all() and (along.sum(axis=1) == 4).all()
    assert np.all(np.asarray(v.nodes["link_edges"].colors).reshape(-1, 3) == draw.EDGE)
    v.set_visible("robot", False)
    assert not v.nodes["link_edges"].visible and not v.nodes["robot"].visible
    v.set_visible("robot", True)
    assert v.nodes["link_edges"].visible


def test_the_viewer_takes_a_scenario_object_and_keeps_it(make_viewer):
    """Objects flow down: a scenario the caller holds (here an equal copy of 2DS) is shown as it is, not looked up
    again by name (``toolkit view --checkpoint`` passes the checkpoint's scenario)."""
    own = dataclasses.replace(scenarios.get("2ds"))
    v = make_viewer(own)
    assert v.scenario is own and v.robot is own.robot


def test_2ds_is_a_flat_3d_scene(make_viewer):
    v = make_viewer("2ds")
    np.testing.assert_allclose(v.nodes["obstacles"].batched_scales[:, 2], draw.FLAT_HEIGHT)
    np.testing.assert_allclose(v.nodes["obstacles"].batched_positions[:, 2], draw.FLAT_HEIGHT / 2)
    np.testing.assert_allclose(v.nodes["robot"].batched_scales[:, 2], draw.FLAT_ROBOT_HEIGHT)


def test_sliders_move_the_youbot_into_an_obstacle_and_out(make_panel):
    panel = make_panel("3do", seed=0)
    v = panel.viewer
    rest = v.q.copy()
    x, y = panel.sliders[0], panel.sliders[1]
    block = v.workspace.boxes[0]  # furniture stands on the floor, as high as the youBot's base at least
    x.value, y.value = (block[0, :2] + block[1, :2]) / 2
    q = np.concatenate([(block[0, :2] + block[1, :2]) / 2, rest[2:]])
    np.testing.assert_allclose(v.q, q)
    assert not v.valid and not v.exact.is_valid(q)
    assert np.all(link_colors(v) == draw.COLLIDING)
    np.testing.assert_allclose(
        v.nodes["robot"].batched_positions, draw.robot_boxes(v.robot, q[None]).centers, atol=1e-5
    )
    assert "in collision" in panel.status.content
    x.value, y.value = rest[:2]
    assert v.valid and np.all(link_colors(v) == draw.VALID)
    assert "valid" in panel.status.content


def test_an_arm_joint_slider_turns_the_arm(make_panel):
    panel = make_panel("3do", seed=0)
    v = panel.viewer
    before = np.array(v.nodes["robot"].batched_positions)
    panel.sliders[4].value = 1.0  # joint2: the shoulder pitch
    after = np.array(v.nodes["robot"].batched_positions)
    assert np.allclose(after[:2], before[:2], atol=1e-6)  # base and turret stay
    assert not np.allclose(after[2:], before[2:], atol=1e-3)  # the arm moves


def test_workspace_controls_rebuild_the_scene(make_panel):
    panel = make_panel("3do", seed=0)
    v = panel.viewer
    panel.new_workspace.value = True  # press the button: next seed
    assert v.seed == 1 and panel.seed.value == 1
    assert v.workspace == scenarios.get("3do").make_workspace(np.random.default_rng(1))
    panel.scenario.value = "3dc9"
    assert v.scenario.name == "3dc9" and len(panel.sliders) == 9
    assert len(v.nodes["robot"].batched_positions) == 4
    assert len(v.nodes["obstacles"].batched_positions) == len(v.workspace.boxes)


def test_move_boxes_moves_only_a_node_of_boxes(make_viewer):
    v = make_viewer("2ds")
    boxes = draw.robot_boxes(v.robot, v.robot.upper[None] - 1.0)
    draw.move_boxes(v.nodes["robot"], boxes, draw.COLLIDING)
    np.testing.assert_allclose(v.nodes["robot"].batched_positions, boxes.centers, atol=1e-5)
    with pytest.raises(TypeError, match="a node made by add_boxes, got a LabelHandle"):
        draw.move_boxes(v.server.scene.add_label("/label", "not boxes"), boxes, draw.COLLIDING)


def test_samples_are_colored_by_the_exact_checker(make_viewer, rng):
    v = make_viewer("2ds")
    Q = v.robot.sample(rng, 300)
    colors = v.show_samples(Q)
    valid = v.exact.are_valid(Q)
    assert 0 < valid.sum() < len(Q)
    assert np.all(colors[valid] == draw.VALID) and np.all(colors[~valid] == draw.COLLIDING)
    for kind, mask in (("valid", valid), ("in collision", ~valid)):
        cloud = v.sample_clouds[kind]
        np.testing.assert_allclose(cloud.points[:, :2], Q[mask], atol=0.02)  # float16 points
        assert np.array_equal(cloud.colors, colors[mask]) and cloud.point_shape == draw.SAMPLE_SHAPES[kind][0]
    assert "model wrong" not in v.sample_clouds and f"Samples: {valid.sum()} valid (circles)" in v.summary()


@pytest.mark.parametrize("sampler", ["BS", "OB", "G", "BT"])
def test_the_four_samplers_show_valid_samples(make_viewer, sampler):
    v = make_viewer("2ds")
    Q = v.sample(sampler, 200, seed=0)
    assert len(Q) > 0 and v.exact.are_valid(Q).all()
    assert len(v.sample_clouds["valid"].points) == len(Q) and "in collision" not in v.sample_clouds


def test_a_wrong_model_is_marked_everywhere(make_panel, rng):
    panel = make_panel("2ds", predictor=lambda ws: Flipped(ws, scenarios.get("2ds").robot))
    v = panel.viewer
    assert v.valid and v.probability == 0.0 and not v.predicted_valid
    assert v.nodes["disagreement"].visible
    wireframe = v.nodes["prediction"]
    assert np.all(np.asarray(wireframe.colors) == draw.probability_colors([0.0])[0])  # the map's dark grey end
    # reader r19c: a 1-pixel wireframe with its faces' diagonals read as hair lines: now each box's 12 edges, 3 px wide
    assert wireframe.thickness == draw.PREDICTION_PX >= 3 and wireframe.thickness_units == "screen"
    # reader r15b: at 1.15 times a 0.1-thick link the wireframe lay on the link's edges; it stands half the thinnest
    # link's thickness clear of every face
    links = draw.robot_boxes(v.robot, v.q[None])
    grown = draw.Boxes(links.centers, links.rotations, links.sizes + 2 * float(np.min(links.sizes)) / 2)
    np.testing.assert_allclose(np.asarray(wireframe.points), draw.box_edges(grown), atol=1e-6)
    assert "disagrees" in panel.status.content
    v.sample("raw", 300, seed=1)
    valid = v.exact.are_valid(v.robot.sample(np.random.default_rng(1), 300))
    assert v.sample_counts == {"valid": valid.sum(), "in collision": (~valid).sum(), "model wrong": 300}
    wrong = v.sample_clouds["model wrong"]
    assert len(wrong.points) == 300 and np.all(wrong.colors == draw.MISTAKE)
    assert "300 the model gets wrong (sparkles)" in v.summary()
    panel.layers["prediction"].value = False
    assert not v.nodes["prediction"].visible and not v.nodes["disagreement"].visible


def test_a_model_of_another_robot_is_not_used(make_panel):
    panel = make_panel("3dc9", predictor=lambda ws: Flipped(ws, scenarios.get("3dc7").robot))
    v = panel.viewer
    assert v.model is None and "chain7" in v.model_error and "model not used" in panel.status.content


def test_a_model_that_gives_no_probability_is_not_used(make_panel):
    panel = make_panel("2ds", predictor=lambda ws: exact_checker(ws, scenarios.get("2ds").robot))
    v = panel.viewer
    assert v.model is None and "PointRobotChecker gives no probability(Q)" in v.model_error
    assert v.probability is None and "model not used" in panel.status.content


def test_a_trained_checkpoint_colors_the_robot_and_samples(make_viewer, checkpoint_2ds, rng):
    v = make_viewer("2ds", checkpoint=checkpoint_2ds)
    model = learned.load_checker(checkpoint_2ds, v.workspace)
    assert v.probability == pytest.approx(float(model.probability(v.q[None])[0]))
    np.testing.assert_array_equal(np.asarray(v.nodes["prediction"].colors), draw.probability_colors([v.probability])[0])
    Q = v.robot.sample(rng, 500)
    colors = v.show_samples(Q)
    valid, predicted = v.exact.are_valid(Q), model.are_valid(Q)
    np.testing.assert_array_equal(colors, draw.validity_colors(valid))
    assert v.sample_counts["model wrong"] == np.sum(valid != predicted)


def test_plan_shows_one_roadmap_node_and_a_playable_path(make_panel):
    panel = make_panel("2ds")
    v = panel.viewer
    result = v.plan("BS", seed=0)
    assert result.success
    edges, nodes = result.roadmap.edges, result.roadmap.nodes
    segments = np.asarray(v.nodes["roadmap"].points)
    assert segments.shape == (len(edges), 2, 3)  # every edge in one line-segment node
    np.testing.assert_allclose(segments[:, :, :2], nodes[edges], atol=1e-4)
    np.testing.assert_allclose(v.q, result.path[0])  # the robot waits at the start
    assert not panel.along.disabled
    panel.along.value = 1.0  # scrub to the end
    np.testing.assert_allclose(v.q, result.path[-1], atol=1e-9)
    panel.along.value = 0.5
    assert v.exact.is_valid(v.q)
    dense = v.path_configurations(np.linspace(0, 1, 200))
    assert v.exact.are_valid(dense).all()
    np.testing.assert_allclose(dense[[0, -1]], result.path[[0, -1]], atol=1e-9)


def test_play_and_pause(make_panel):
    panel = make_panel("2ds")
    v = panel.viewer
    v.plan("BS", seed=0)
    panel.toggle_play()
    deadline = time.monotonic() + 10
    while panel.along.value == 0.0 and time.monotonic() < deadline:
        time.sleep(0.05)
    panel.toggle_play()  # pause
    paused_at = panel.along.value
    assert 0.0 < paused_at < 1.0 and not panel.playing
    np.testing.assert_allclose(v.q, v.path_configurations([paused_at])[0])


def test_layers_toggle(make_panel):
    panel = make_panel("3dc7")
    v = panel.viewer
    v.sample("raw", 50)
    for layer in ("obstacles", "robot", "samples"):
        panel.layers[layer].value = False
        assert not v.nodes[layer].visible
    v.sample("raw", 50, seed=1)  # a redrawn layer keeps its toggle
    assert not v.nodes["samples"].visible


def test_bad_input(make_panel):
    port = free_port()
    with pytest.raises(ValueError, match="unknown scenario"):
        viewer.Viewer("4d", port=port)
    with socket.socket() as again:
        again.bind(("127.0.0.1", port))  # the failed viewer left no server behind
    panel = make_panel("2ds")
    v = panel.viewer
    with pytest.raises(ValueError, match="shape"):
        v.set_configuration([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="NaN"):
        v.set_configuration([np.nan, 2.0])
    with pytest.raises(ValueError, match="unknown layer"):
        v.set_visible("clouds", False)
    with pytest.raises(ValueError, match="no path"):
        v.path_configurations([0.5])
    panel.play.value = True  # the GUI shows the error instead of raising in a worker thread
    assert "no path to play" in panel.status.content


class Recording(sampling.Sampler):
    """A toy sampler: uniform configurations the checker accepts, each remembered in ``drawn`` (class-wide)."""

    drawn: ClassVar[list] = []

    def draw(self, n, rng):
        Q = self.robot.sample(rng, n)  # (n, dof)
        Q = Q[self.valid(Q)]
        Recording.drawn.append(Q)
        return Q


@pytest.fixture
def toy_sampler():
    """``"toy"``: :class:`Recording`, registered for one test (registration lasts for the process)."""
    Recording.drawn = []
    sampling.register_sampler("toy", Recording)
    yield "toy"
    del sampling.SAMPLERS["toy"]


def test_a_registered_sampler_is_offered_and_samples_and_plans(make_panel, toy_sampler):
    panel = make_panel("2ds")
    v = panel.viewer
    assert panel.sampler.options == ("raw", "BS", "OB", "G", "BT", toy_sampler)  # the paper's four first
    assert panel.planner_sampler.options == ("BS", "OB", "G", "BT", toy_sampler)
    Q = v.sample(toy_sampler, 300, seed=4)
    np.testing.assert_array_equal(Q, Recording.drawn[-1])  # the viewer asked the registered class
    assert 0 < len(Q) < 300 and v.exact.are_valid(Q).all()
    np.testing.assert_allclose(v.sample_clouds["valid"].points[:, :2], Q, atol=0.02)
    Recording.drawn = []
    result = v.plan(toy_sampler, seed=0)
    assert result.success and Recording.drawn  # the planner drew its rounds from the toy sampler
    drawn = np.concatenate(Recording.drawn)  # (M, 2)
    nodes = np.delete(result.roadmap.nodes, [START, GOAL], axis=0)  # (V - 2, 2) the sampled nodes
    assert len(nodes) and all(np.any(np.all(drawn == node, axis=1)) for node in nodes)
    assert v.exact.are_valid(v.path_configurations(np.linspace(0, 1, 200))).all()
    panel.planner_sampler.value = toy_sampler  # the same from the GUI
    panel.plan.value = True
    assert panel.plan_status.content.startswith("path of"), panel.status.content


def test_the_viewer_tells_its_listeners_what_happened(make_viewer):
    v = make_viewer("2ds")
    heard = []
    for event in viewer.EVENTS:
        v.subscribe(event, lambda *args, event=event: heard.append((event, *args)))
    v.load("2ds", 5)
    assert heard == [("loading",), ("loaded",), ("moved",)] and v.seed == 5
    heard.clear()
    result = v.plan("BS", seed=0)
    assert heard[-1] == ("planned", result) and ("moved",) in heard  # the robot went to the path's start
    heard.clear()
    v.stop()
    v.stop()  # told once
    assert heard == [("stopping",)]
    with pytest.raises(ValueError, match="unknown event 'clicked'"):
        v.subscribe("clicked", print)
    with pytest.raises(TypeError, match="callable"):
        v.subscribe("moved", None)


def test_a_panel_joined_later_shows_the_viewer_as_it_is(make_viewer):
    v = make_viewer("2ds", seed=2)
    v.plan("BS", seed=0)
    v.set_configuration(v.path_configurations([0.5])[0])
    panel = viewer.Panel(v)
    np.testing.assert_allclose([s.value for s in panel.sliders], v.q)
    assert panel.seed.value == 2 and not panel.along.disabled
    assert "seed 2" in panel.status.content
    v.set_configuration(v.path[0])  # from a script: the panel follows
    np.testing.assert_allclose([s.value for s in panel.sliders], v.path[0])


def test_launch_joins_one_panel_to_the_viewer(capsys):
    v = viewer.launch("2ds", port=0, quiet=True)
    try:
        panels = {callback.__self__ for callbacks in v.listeners.values() for callback in callbacks}
        assert len(panels) == 1 and isinstance(panels.pop(), viewer.Panel)
        assert capsys.readouterr().out == ""  # quiet
    finally:
        v.stop()


# the order of the modules in toolkit/viewer/__init__.py's docstring
READING_ORDER = [
    "drawing",
    "framing",
    "server",
    "address",
    "labels",
    "models",
    "snapshot",
    "scene",
    "panel",
    "app",
    "browser",
]


def viewer_imports(source: str) -> set[str]:
    """The ``toolkit.viewer`` modules that ``source`` imports anywhere (``TYPE_CHECKING`` blocks included)."""
    names = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            names |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module:
            names |= {node.module} | {f"{node.module}.{alias.name}" for alias in node.names}
    return {name.split(".")[2] for name in names if name.startswith("toolkit.viewer.")} & set(READING_ORDER)


def test_each_viewer_module_imports_only_those_before_it():
    folder = Path(viewer.__file__).parent
    assert sorted(READING_ORDER) == sorted(path.stem for path in folder.glob("*.py") if path.stem != "__init__")
    assert viewer_imports("from toolkit.viewer import drawing as draw\nimport toolkit.viewer.panel") == {
        "drawing",
        "panel",
    }
    for place, name in enumerate(READING_ORDER):
        imported = viewer_imports((folder / f"{name}.py").read_text())
        assert imported <= set(READING_ORDER[:place]), f"{name} imports {sorted(imported)}"


def test_busy_port_moves_on_and_stop_frees_it(capsys):
    port = free_port()
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", port))
        busy.listen()
        v = viewer.launch("2ds", port=port)
        try:
            assert v.port != port
            assert f"{v.url} (port {port} was busy)" in capsys.readouterr().out
            assert v.url.startswith("http://127.0.0.1:")
        finally:
            v.stop()
    v.stop()  # twice is harmless
    with socket.socket() as again:
        again.bind(("127.0.0.1", v.port))  # free after stop()


def test_in_a_crowded_view_far_marks_grow_less_and_near_ones_shrink():
    """Reader r15b: in the 3DC-7 view of 2000 marks the grown far marks (9 to 13 px of 440) and the near ones (up to
    60 px) buried the robot. Crowded, a circle is drawn 6.2 to 8.8 px wide far and at most 17.6 near, in steps of
    sqrt 2 from its own size (those in between keep it); a view of few marks still grows far ones to 8.8 px or more."""
    size, depth = draw.POINT_SIZE["3dc"], np.geomspace(0.05, 30.0, 400)  # (N,)
    px = 440 * size / (depth * np.tan(np.deg2rad(75.0) / 2))  # (N,) a circle's width at its own size
    crowded = px * draw.far_scale(depth, size, crowded=True)
    assert px.min() < 6 and px.max() > 40  # the depths span far and near
    assert crowded.max() <= 17.61 and crowded.min() >= 6.2 and crowded[px < 6.2].max() <= 8.81
    kept = (px >= 6.2) & (px <= 17.6)
    np.testing.assert_allclose(crowded[kept], px[kept])
    steps = np.log(crowded / px) / np.log(np.sqrt(2.0))
    np.testing.assert_allclose(steps, np.rint(steps), atol=1e-9)
    sparse = px * draw.far_scale(depth, size)
    assert sparse.min() >= 8.79 and np.array_equal(sparse[px > 9], px[px > 9])


def test_color_share_reads_pixels(tmp_path):
    picture = np.ones((100, 500, 3))  # white
    picture[40:60, 30:50] = np.array(draw.OBSTACLE) / 255 * 0.6  # a shaded obstacle face
    picture[40:60, 450:470] = np.array(draw.OBSTACLE) / 255  # under the GUI panel: not counted
    mpimg.imsave(tmp_path / "p.png", picture)
    canvas = 75 * (500 - 340 - 10)  # rows 20..95; columns 10 .. width - PANEL_PX
    assert viewer_browser.color_share(tmp_path / "p.png", draw.OBSTACLE) == pytest.approx(400 / canvas)
    assert viewer_browser.color_share(tmp_path / "p.png", draw.COLLIDING) == 0.0


def test_toolkit_view_serves_until_ctrl_c():
    command = [sys.executable, "-m", "toolkit", "view", "--scenario", "2ds", "--port", "0"]
    process = subprocess.Popen(
        command,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    try:
        lines = iter(process.stdout.readline, "")
        line = next(line for line in lines if line.startswith("toolkit view:"))
        url = re.search(r"http://127\.0\.0\.1:\d+/\S+/", line).group(0)  # the launch's secret included
        with urllib.request.urlopen(url, timeout=10) as page:
            assert page.status == 200 and b"<html" in page.read(2000).lower()
        process.send_signal(signal.SIGINT)
        assert process.wait(timeout=30) == 0
    finally:
        process.kill()
        process.stdout.close()
