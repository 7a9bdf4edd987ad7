"""The viewer's scene and GUI, driven from Python: nodes per scenario, sliders, colors, plans, ports, embedding."""

import base64
import html
import re
import signal
import socket
import subprocess
import sys
import time
import urllib.request

import msgspec
import numpy as np
import pytest
import zstandard
from matplotlib import image as mpimg

from toolkit import scenarios, viewer
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.learning import learned
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

    def _are_valid(self, Q):
        return ~self.exact.are_valid(Q)


def link_colors(v):
    return np.asarray(v.nodes["robot"].batched_colors)


@pytest.mark.parametrize("name", ["2ds", "3do", "3dc7", "3dc9"])
def test_scene_holds_the_workspace_and_the_robot(make_viewer, name):
    v = make_viewer(name, seed=3)
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
    sliders = v.panel.sliders
    assert [s.label for s in sliders] == list(scenario.robot.dof_names)
    np.testing.assert_allclose([s.min for s in sliders], scenario.robot.lower)
    np.testing.assert_allclose([s.max for s in sliders], scenario.robot.upper)
    np.testing.assert_allclose([s.value for s in sliders], v.q)
    assert "prediction" not in v.nodes and "disagreement" not in v.nodes  # no model loaded


def test_2ds_is_a_flat_3d_scene(make_viewer):
    v = make_viewer("2ds")
    np.testing.assert_allclose(v.nodes["obstacles"].batched_scales[:, 2], draw.FLAT_HEIGHT)
    np.testing.assert_allclose(v.nodes["obstacles"].batched_positions[:, 2], draw.FLAT_HEIGHT / 2)
    np.testing.assert_allclose(v.nodes["robot"].batched_scales[:, 2], draw.FLAT_ROBOT_HEIGHT)


def test_sliders_move_the_youbot_into_an_obstacle_and_out(make_viewer):
    v = make_viewer("3do", seed=0)
    rest = v.q.copy()
    x, y = v.panel.sliders[0], v.panel.sliders[1]
    block = v.workspace.boxes[0]  # furniture stands on the floor, as high as the youBot's base at least
    x.value, y.value = (block[0, :2] + block[1, :2]) / 2
    q = np.concatenate([(block[0, :2] + block[1, :2]) / 2, rest[2:]])
    np.testing.assert_allclose(v.q, q)
    assert not v.valid and not v.exact.is_valid(q)
    assert np.all(link_colors(v) == draw.COLLIDING)
    np.testing.assert_allclose(v.nodes["robot"].batched_positions, draw.robot_boxes(v.robot, q[None]).centers,
                               atol=1e-5)
    assert "in collision" in v.panel.status.content
    x.value, y.value = rest[:2]
    assert v.valid and np.all(link_colors(v) == draw.VALID)
    assert "valid" in v.panel.status.content


def test_an_arm_joint_slider_turns_the_arm(make_viewer):
    v = make_viewer("3do", seed=0)
    before = np.array(v.nodes["robot"].batched_positions)
    v.panel.sliders[4].value = 1.0  # joint2: the shoulder pitch
    after = np.array(v.nodes["robot"].batched_positions)
    assert np.allclose(after[:2], before[:2], atol=1e-6)  # base and turret stay
    assert not np.allclose(after[2:], before[2:], atol=1e-3)  # the arm moves


def test_workspace_controls_rebuild_the_scene(make_viewer):
    v = make_viewer("3do", seed=0)
    v.panel.new_workspace.value = True  # press the button: next seed
    assert v.seed == 1 and v.panel.seed.value == 1
    assert v.workspace == scenarios.get("3do").make_workspace(np.random.default_rng(1))
    v.panel.scenario.value = "3dc9"
    assert v.scenario.name == "3dc9" and len(v.panel.sliders) == 9
    assert len(v.nodes["robot"].batched_positions) == 4
    assert len(v.nodes["obstacles"].batched_positions) == len(v.workspace.boxes)


def test_samples_are_colored_by_the_exact_checker(make_viewer, rng):
    v = make_viewer("2ds")
    Q = v.robot.sample(rng, 300)
    colors = v.show_samples(Q)
    valid = v.exact.are_valid(Q)
    assert 0 < valid.sum() < len(Q)
    assert np.all(colors[valid] == draw.VALID) and np.all(colors[~valid] == draw.COLLIDING)
    cloud = v.nodes["samples"]
    np.testing.assert_allclose(cloud.points[:, :2], Q, atol=0.02)  # float16 points
    assert np.array_equal(cloud.colors, colors)


@pytest.mark.parametrize("sampler", ["BS", "OB", "G", "BT"])
def test_the_four_samplers_show_valid_samples(make_viewer, sampler):
    v = make_viewer("2ds")
    Q = v.sample(sampler, 200, seed=0)
    assert len(Q) > 0 and v.exact.are_valid(Q).all()
    assert len(v.nodes["samples"].points) == len(Q)


def test_a_wrong_model_is_marked_everywhere(make_viewer, rng):
    v = make_viewer("2ds", predictor=lambda ws: Flipped(ws, scenarios.get("2ds").robot))
    assert v.valid and v.probability == 0.0 and not v.predicted_valid
    assert v.nodes["disagreement"].visible
    assert np.all(np.asarray(v.nodes["prediction"].batched_colors) == draw.COLLIDING)  # p = 0 -> red
    assert "disagrees" in v.panel.status.content
    v.sample("raw", 300, seed=1)
    colors = v.nodes["samples"].colors
    valid = v.exact.are_valid(v.robot.sample(np.random.default_rng(1), 300))
    assert np.all(colors[valid] == draw.PREDICTED_COLLIDING_BUT_VALID)
    assert np.all(colors[~valid] == draw.PREDICTED_VALID_BUT_COLLIDING)
    v.panel.layers["prediction"].value = False
    assert not v.nodes["prediction"].visible and not v.nodes["disagreement"].visible


def test_a_model_of_another_robot_is_not_used(make_viewer):
    v = make_viewer("3dc9", predictor=lambda ws: Flipped(ws, scenarios.get("3dc7").robot))
    assert v.model is None and "chain7" in v.model_error and "model not used" in v.panel.status.content


def test_a_trained_checkpoint_colors_the_robot_and_samples(make_viewer, checkpoint_2ds, rng):
    v = make_viewer("2ds", checkpoint=checkpoint_2ds)
    model = learned.load_checker(checkpoint_2ds, v.workspace)
    assert v.probability == pytest.approx(float(model.probability(v.q[None])[0]))
    np.testing.assert_array_equal(np.asarray(v.nodes["prediction"].batched_colors)[0],
                                  draw.probability_colors([v.probability])[0])
    Q = v.robot.sample(rng, 500)
    colors = v.show_samples(Q)
    np.testing.assert_array_equal(colors, draw.validity_colors(v.exact.are_valid(Q), model.are_valid(Q)))


def test_plan_shows_one_roadmap_node_and_a_playable_path(make_viewer):
    v = make_viewer("2ds")
    result = v.plan("BS", seed=0)
    assert result.success
    edges, nodes = result.roadmap.edges, result.roadmap.nodes
    segments = np.asarray(v.nodes["roadmap"].points)
    assert segments.shape == (len(edges), 2, 3)  # every edge in one line-segment node
    np.testing.assert_allclose(segments[:, :, :2], nodes[edges], atol=1e-4)
    np.testing.assert_allclose(v.q, result.path[0])  # the robot waits at the start
    assert not v.panel.along.disabled
    v.panel.along.value = 1.0  # scrub to the end
    np.testing.assert_allclose(v.q, result.path[-1], atol=1e-9)
    v.panel.along.value = 0.5
    assert v.exact.is_valid(v.q)
    dense = v.path_configurations(np.linspace(0, 1, 200))
    assert v.exact.are_valid(dense).all()
    np.testing.assert_allclose(dense[[0, -1]], result.path[[0, -1]], atol=1e-9)


def test_play_and_pause(make_viewer):
    v = make_viewer("2ds")
    v.plan("BS", seed=0)
    v.panel.toggle_play()
    deadline = time.monotonic() + 10
    while v.panel.along.value == 0.0 and time.monotonic() < deadline:
        time.sleep(0.05)
    v.panel.toggle_play()  # pause
    paused_at = v.panel.along.value
    assert 0.0 < paused_at < 1.0 and v.panel._player is None
    np.testing.assert_allclose(v.q, v.path_configurations([paused_at])[0])


def test_layers_toggle(make_viewer):
    v = make_viewer("3dc7")
    v.sample("raw", 50)
    for layer in ("obstacles", "robot", "samples"):
        v.panel.layers[layer].value = False
        assert not v.nodes[layer].visible
    v.sample("raw", 50, seed=1)  # a redrawn layer keeps its toggle
    assert not v.nodes["samples"].visible


def test_bad_input(make_viewer):
    port = free_port()
    with pytest.raises(ValueError, match="unknown scenario"):
        viewer.Viewer("4d", port=port)
    with socket.socket() as again:
        again.bind(("127.0.0.1", port))  # the failed viewer left no server behind
    v = make_viewer("2ds")
    with pytest.raises(ValueError, match="shape"):
        v.set_configuration([1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match="NaN"):
        v.set_configuration([np.nan, 2.0])
    with pytest.raises(ValueError, match="unknown layer"):
        v.set_visible("clouds", False)
    with pytest.raises(ValueError, match="no path"):
        v.path_configurations([0.5])
    v.panel.play.value = True  # the GUI shows the error instead of raising in a worker thread
    assert "no path to play" in v.panel.status.content


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


def embedded_messages(snippet: str) -> list[dict]:
    """The scene messages inside an embedded viewer's HTML (viser's .viser recording, base64 in the page)."""
    document = html.unescape(re.search(r'srcdoc="([^"]*)"', snippet).group(1))
    data = base64.b64decode(re.search(r'__VISER_EMBED_DATA__="([^"]+)"', document).group(1))
    inner = zstandard.ZstdDecompressor().decompress(data[8:], max_output_size=int.from_bytes(data[:8], "little"))
    size = int.from_bytes(inner[:8], "little")
    return [message for _, message in msgspec.msgpack.decode(inner[8: 8 + size])["messages"]]


def test_embed_is_a_static_snapshot_of_the_scene(rng):
    robot = scenarios.get("3dc7").robot
    snippet = viewer.embed("3dc7", seed=2, samples=robot.sample(rng, 40), height=320)
    assert snippet.startswith("<div><iframe") and 'height="320"' in snippet
    names = {message.get("name") for message in embedded_messages(snippet)}
    assert {"/workspace/obstacles", "/robot/links", "/samples"} <= names


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
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        lines = iter(process.stdout.readline, "")
        line = next(line for line in lines if line.startswith("toolkit view:"))
        url = re.search(r"http://127\.0\.0\.1:\d+", line).group(0)
        with urllib.request.urlopen(url, timeout=10) as page:
            assert page.status == 200 and b"<html" in page.read(2000).lower()
        process.send_signal(signal.SIGINT)
        assert process.wait(timeout=30) == 0
    finally:
        process.kill()
        process.stdout.close()
