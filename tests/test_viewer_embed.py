"""Embedded viewer pages for notebooks: a snapshot of the scene, a recorded animation of the robot along a path.

The recording is decoded here as viser's player reads it (a zstd frame of msgpack
messages with binary arrays appended), so the tests see the frames a student sees.
"""

import base64
import html
import json
import re
from time import monotonic

import msgspec
import numpy as np
import pytest
import zstandard
from IPython.display import HTML

from toolkit import scenarios, viewer
from toolkit.geometry.collision import exact_checker
from toolkit.viewer import browser as viewer_browser
from toolkit.viewer import drawing as draw
from toolkit.viewer import framing, snapshot
from toolkit.viewer.labels import NO_WEBGL


def found(pattern: str, text: str) -> str:
    """The first group of ``pattern``'s first match in ``text`` (failing the test where there is none)."""
    match = re.search(pattern, text)
    assert match is not None, f"no {pattern!r} in the page"
    return match.group(1)


def page_of(snippet: str) -> str:
    """The document an ``<iframe srcdoc=...>`` snippet carries."""
    return html.unescape(found(r'srcdoc="([^"]*)"', snippet))


def recording(document: str) -> tuple[dict, list[bytes]]:
    """The ``.viser`` recording inside a self-contained page: its msgpack record and its binary buffers."""
    data = base64.b64decode(found(r'__VISER_EMBED_DATA__="([^"]+)"', document))
    inner = zstandard.ZstdDecompressor().decompress(data[8:], max_output_size=int.from_bytes(data[:8], "little"))
    size = int.from_bytes(inner[:8], "little")
    record = msgspec.msgpack.decode(inner[8 : 8 + size])
    buffers, offset = [], 8 + size
    for length in record["binaryBufferLengths"]:
        offset += -offset % 8  # each buffer starts 8-byte aligned
        buffers.append(inner[offset : offset + length])
        offset += length
    return record, buffers


def robot_poses(document: str) -> list[tuple[float, np.ndarray]]:
    """``(time, link centres (L, 3))`` of the robot at each moment of a recording that places it (the last word)."""
    record, buffers = recording(document)
    poses = {}
    for time, message in record["messages"]:
        if message.get("name") == "/robot/links":  # created (props) or moved (updates)
            array = (message.get("updates") or message.get("props") or {}).get("batched_positions")
            if array is not None:
                poses[time] = np.frombuffer(buffers[array["__binary_index"]], dtype=array["dtype"]).reshape(-1, 3)
    return sorted(poses.items(), key=lambda pose: pose[0])


@pytest.fixture(scope="module")
def planned():
    """A 3DC-7 viewer with a planned path (exact planner), stopped after the module."""
    with viewer.Viewer("3dc7", seed=1, port=0) as v:
        result = v.plan("BS", seed=0)
        assert result.success and len(result.path) >= 2
        yield v


def test_the_animation_holds_one_robot_pose_per_frame_along_the_path(planned):
    v, frames, seconds = planned, 12, 3.0
    document = v.animation_html(frames=frames, seconds=seconds)
    record, _ = recording(document)
    assert record["durationSeconds"] == pytest.approx(seconds)
    poses = robot_poses(document)
    Q = v.path_configurations(np.linspace(0, 1, frames))  # (F, dof)
    expected = draw.robot_boxes(v.robot, Q).centers.reshape(frames, -1, 3)  # (F, L, 3) where the links stand
    looks = framing.follow_camera(v.robot, Q)[0]  # (F, 3)
    assert len(poses) == frames  # the scene as the recording starts, then one move per frame
    times = np.array([time for time, _ in poses])
    np.testing.assert_allclose(times, np.linspace(0.0, seconds, frames), atol=1e-9)
    for (_, centers), want, look_at in zip(poses, expected, looks):  # drawn slid with the scene (the camera follows)
        np.testing.assert_allclose(centers - (looks.mean(axis=0) - look_at), want, atol=1e-5)
    assert not np.allclose(expected[0], expected[-1], atol=0.1)  # the robot really travels


def test_the_animation_page_is_self_contained(planned):
    document = planned.animation_html(frames=5, seconds=1.0)
    assert document.lstrip().lower().startswith("<!doctype html")
    assert not re.search(r'(src|href)="(https?:)?//', document)  # nothing fetched from elsewhere
    names = {message.get("name") for _, message in recording(document)[0]["messages"]}
    assert {"/workspace/obstacles", "/robot/links", "/plan/path", "/plan/roadmap"} <= names
    assert len(document) < 3_000_000  # a few MB at most in a saved notebook


def slides(document: str) -> dict[str, list[tuple[float, np.ndarray]]]:
    """``{node name: [(time, position (3,)), ...]}``: where a recording places each node, the last word at each time."""
    moves: dict[str, dict] = {}
    for time, message in recording(document)[0]["messages"]:
        if message["type"] == "SetPositionMessage":
            moves.setdefault(message["name"], {})[time] = np.array(message["position"])
    return {name: sorted(at.items(), key=lambda step: step[0]) for name, at in moves.items()}


def cameras(document: str) -> dict[str, np.ndarray]:
    """The camera a page starts with: ``{"look_at": (3,), "position": (3,)}``."""
    found = {}
    for _, message in recording(document)[0]["messages"]:
        if message["type"] == "SetCameraLookAtMessage":
            found["look_at"] = np.array(message["look_at"])
        elif message["type"] == "SetCameraPositionMessage":
            found["position"] = np.array(message["position"])
    return found


def test_the_animation_keeps_the_robot_framed_by_sliding_the_scene_under_the_camera(planned):
    """The scene slides by its frames' poses, the robot's links are drawn where the camera looks: viser's player
    poses a node a drawn frame or more before it reshapes one, and a robot slid by its frame (its links reshaped
    later) left the view for those frames, a quarter of the screenshots under load."""
    v, frames, seconds = planned, 8, 1.0
    document = v.animation_html(frames=frames, seconds=seconds)
    Q = v.path_configurations(np.linspace(0, 1, frames))
    looks, positions = framing.follow_camera(v.robot, Q)  # (F, 3) each
    camera = cameras(document)
    moves = slides(document)
    assert all(len(moves[name]) == 1 for name in ("/lights/key", "/workspace/floor"))  # placed once: the lights stay
    for name, steps in ((name, moves[name]) for name in ("/workspace", "/plan")):
        assert [t for t, _ in steps] == pytest.approx(np.linspace(0.0, seconds, frames)), name  # frame 0's too
        for (_, offset), look_at in zip(steps, looks):
            np.testing.assert_allclose(look_at + offset, camera["look_at"], atol=1e-9)  # the robot, where it looks
    assert "/robot" not in moves  # never posed: whatever the player draws first, the links stay in view
    for _, centers in robot_poses(document):
        np.testing.assert_allclose(centers.mean(axis=0), camera["look_at"], atol=1e-5)
    np.testing.assert_allclose(camera["position"] - camera["look_at"], positions[0] - looks[0])
    np.testing.assert_allclose(looks, v.robot.link_boxes(Q)[0].mean(axis=1))  # the middle of the robot's links
    distance = np.linalg.norm(positions - looks, axis=1)
    np.testing.assert_allclose(distance, framing.ROBOT_SPAN * 0.5 * np.linalg.norm(framing.ROBOT_VIEW))  # chain: 0.5


def test_a_snapshot_starts_framing_the_robot_and_leaves_the_live_camera_alone(planned):
    v = planned
    v.set_configuration(v.path[len(v.path) // 2])
    live = v.server.initial_camera.look_at.copy(), v.server.initial_camera.position.copy()
    camera = cameras(v.html())
    look_at, position = framing.robot_camera(v.robot, v.q, workspace=v.workspace)  # no samples shown
    np.testing.assert_allclose(camera["look_at"], look_at)
    np.testing.assert_allclose(camera["position"], position)
    np.testing.assert_allclose(look_at, v.robot.link_boxes(v.q[None])[0][0].mean(axis=0))  # the middle of the robot
    assert np.linalg.norm(position - look_at) < 4  # close: the 0.5-long chain, not the 11-unit cube
    alone = framing.robot_camera(v.robot, v.q)  # no scene to step round: the snapshot's span, nearer the animation's
    span = np.linalg.norm(alone[1] - alone[0]) / (framing.robot_size(v.robot) * np.linalg.norm(framing.ROBOT_VIEW))
    assert span == pytest.approx(framing.SNAPSHOT_SPAN) and span < framing.ROBOT_SPAN  # reader r15b: 3DC-9 at 60 px
    np.testing.assert_allclose(v.server.initial_camera.look_at, live[0])
    np.testing.assert_allclose(v.server.initial_camera.position, live[1])


def marks_hiding_the_robot(camera: dict, radius: float, points: np.ndarray, sizes: np.ndarray) -> np.ndarray:
    """``(N,)`` bool: the marks in front of the robot (a ball of ``radius`` where the camera looks) that overlap it
    on the picture, by angles: a point at angle ``a`` off the line of sight lands ``tan(a)`` focal lengths from the
    picture's middle, and viser draws a mark of width ``s`` at depth ``z`` ``s / z`` focal lengths either side of it
    (``s H / (z tan(fov / 2))`` pixels wide), the robot ``radius / distance`` of them."""
    sight = camera["look_at"] - camera["position"]
    distance = np.linalg.norm(sight)
    rays = points - camera["position"]  # (N, 3)
    depth = rays @ sight / distance
    angle = np.arccos(np.clip(depth / np.linalg.norm(rays, axis=1), -1.0, 1.0))  # off the line of sight
    return (depth > 0) & (depth < distance) & (np.tan(angle) < sizes / depth + radius / distance)


def test_a_snapshot_looks_at_the_robot_from_where_no_sample_mark_or_block_hides_it(make_viewer):
    """Reader r11b: a mark a few tenths of a unit before the camera covered half the view and hid the chain. Here
    the 3DC-7 scene of chapter 05 with its 2000 uniform samples and, besides, three marks on the default camera's
    line of sight: the snapshot's camera stands where none of them overlaps the robot and no block is in between."""
    v = make_viewer("3dc7", seed=0)
    rest_look, rest_camera = framing.robot_camera(v.robot, v.q)  # where the camera stood before
    in_the_way = rest_look + np.linspace(0.2, 0.8, 3)[:, None] * (rest_camera - rest_look)  # (3, 3) points
    extra = v.robot.sample(np.random.default_rng(1), 3)  # (3, 7): moved so that their marks sit on those points
    extra[:, :3] += in_the_way - draw.config_points(v.robot, extra)
    v.show_samples(np.concatenate([v.robot.sample(np.random.default_rng(0), 2000), extra]))
    points, kinds = v.sample_points
    np.testing.assert_allclose(points[-3:], in_the_way, atol=1e-9)
    sizes = draw.mark_sizes(kinds, draw.POINT_SIZE["3dc"])
    radius = np.max(np.ptp(v.robot.link_aabbs(v.q[None])[0].reshape(-1, 3), axis=0)) / 2  # the chain's half size
    default = {"look_at": rest_look, "position": rest_camera}
    assert marks_hiding_the_robot(default, radius, points, sizes)[-3:].all()  # they would hide it
    document = v.html()
    camera = cameras(document)
    np.testing.assert_allclose(camera["look_at"], rest_look)  # still the robot's middle
    assert not marks_hiding_the_robot(camera, radius, points, sizes).any()
    record, buffers = recording(document)  # and none of the marks the page draws, at the size it draws them
    for _, message in record["messages"]:
        if message["type"] == "PointCloudMessage" and message["name"].startswith("/samples/"):
            props = message["props"]
            drawn = np.frombuffer(buffers[props["points"]["__binary_index"]], props["points"]["dtype"]).reshape(-1, 3)
            assert not marks_hiding_the_robot(camera, radius, drawn.astype(float), props["point_size"]).any()
    sight = camera["position"] + np.linspace(0, 1, 50)[:, None] * (camera["look_at"] - camera["position"])
    lo, hi = v.workspace.boxes[:, 0], v.workspace.boxes[:, 1]  # (K, 3) each
    near_side = np.linalg.norm(sight - camera["look_at"], axis=1) > radius
    assert not np.any(np.all((sight[near_side, None] > lo) & (sight[near_side, None] < hi), axis=-1))
    assert np.linalg.norm(camera["position"] - camera["look_at"]) < 4 * framing.robot_size(v.robot)  # still close


def test_a_sparkle_is_drawn_before_the_mark_it_rings_so_that_the_marks_shape_shows(make_viewer, rng):
    """At one depth the point cloud drawn later covers the earlier one (three.js draws opaque clouds in the order
    their materials were made): the sparkles first, so a circle or a diamond shows inside its sparkle's points."""

    def contrary(workspace):  # a model wrong about every sample
        exact = exact_checker(workspace, scenarios.get("3dc7").robot)
        return type(
            "Contrary",
            (),
            {
                "robot": exact.robot,
                "are_valid": staticmethod(lambda Q: ~exact.are_valid(Q)),
                "probability": staticmethod(lambda Q: 1.0 - exact.are_valid(Q)),
            },
        )()

    v = make_viewer("3dc7", seed=2, predictor=contrary)
    v.sample("raw", 60, seed=0)
    made = [m["name"] for _, m in recording(v.html())[0]["messages"] if m.get("name", "").startswith("/samples/")]
    first = {kind: min(k for k, name in enumerate(made) if name.startswith(f"/samples/{kind}")) for kind in KINDS}
    assert first["model_wrong"] < min(first["valid"], first["in_collision"])  # its clouds near and far


KINDS = ("model_wrong", "valid", "in_collision")  # the samples' clouds on a page: /samples/{kind} and, far, its steps


@pytest.fixture(scope="module")
def chain9():
    """Chapter 05's 3DC-9 scene (cell "Now 3DC-9"): the rest pose bent at its three joints, 500 uniform samples."""
    with viewer.Viewer("3dc9", seed=0, port=0) as v:
        bent = v.q.copy()
        bent[6:] = (1.2, -1.0, 1.2)
        v.set_configuration(bent)
        v.show_samples(v.robot.sample(np.random.default_rng(0), 500))
        yield v


def behind_blocks(camera: np.ndarray, targets: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """``(T,)`` bool: a point of the segment from ``camera (3,)`` to each of ``targets (T, 3)`` lies strictly inside
    one of the blocks ``boxes (K, 2, 3)``, by 2000 points along it (a reference apart from the slab test)."""
    along = camera + np.linspace(0.0, 1.0, 2000)[:, None, None] * (targets - camera)  # (S, T, 3)
    inside = (along[:, :, None] > boxes[:, 0]) & (along[:, :, None] < boxes[:, 1])  # (S, T, K, 3)
    return inside.all(axis=-1).any(axis=(0, 2))


def test_links_hidden_agrees_with_points_along_each_line_of_sight(chain9, rng):
    boxes = chain9.workspace.boxes  # (K, 2, 3)
    cameras = rng.uniform(0.0, 11.0, (40, 3))  # (C, 3)
    links = rng.uniform(3.0, 8.0, (6, 3))  # (L, 3)
    hidden = framing.links_hidden(cameras, links, boxes[:, 0], boxes[:, 1])  # (C, L)
    reference = np.stack([behind_blocks(camera, links, boxes) for camera in cameras])
    assert 0.1 < reference.mean() < 0.9 and np.array_equal(hidden, reference)


def test_the_3dc9_snapshot_shows_every_link_in_front_of_the_blocks(chain9):
    """Reader r13b: chapter 05's 3DC-9 view showed the chain behind a block. clear_view looked along one line, to the
    robot's middle; now it counts, for each camera it tries, the links whose line of sight crosses a block, and
    takes one with the fewest (none here; the camera it took before hid one), the same camera each time."""
    document = chain9.html()
    camera = cameras(document)
    links = chain9.robot.link_boxes(chain9.q[None])[0][0]  # (L, 3) centres
    assert not behind_blocks(camera["position"], links, chain9.workspace.boxes).any()
    np.testing.assert_allclose(cameras(chain9.html())["position"], camera["position"])  # deterministic
    assert np.linalg.norm(camera["position"] - camera["look_at"]) < 4 * framing.robot_size(chain9.robot)  # close


def test_far_marks_on_a_page_are_wide_enough_to_tell_their_shapes_apart(chain9):
    """Reader r13b: viser sizes marks in workspace units, so the far ones of the 3DC-9 view were dots of 2-4 px
    (of 440) whose shape could not be told. On the page, a mark is drawn ``point_size / (z tan(fov / 2))`` view
    heights wide at depth ``z``: every circle before the camera is at least 8 px of a 440 px view, a diamond 1.6
    times that; only marks that were narrower than 9 px (circles) grew, to at most 13; the live view keeps its marks'
    sizes in workspace units."""
    document = chain9.html()
    record, buffers = recording(document)
    camera = cameras(document)
    forward = (camera["look_at"] - camera["position"]) / np.linalg.norm(camera["look_at"] - camera["position"])
    px = lambda size, depth: 440 * size / (depth * np.tan(np.deg2rad(75.0) / 2))  # (n,) pixels of a 440 px view
    seen: dict[str, list[np.ndarray]] = {kind: [] for kind in KINDS}
    drawn = 0  # marks on the page, before the camera or not
    for _, message in record["messages"]:
        if message["type"] == "PointCloudMessage" and message["name"].startswith("/samples/"):
            props = message["props"]
            points = np.frombuffer(buffers[props["points"]["__binary_index"]], props["points"]["dtype"])
            drawn += 0 if message["name"].startswith("/samples/model_wrong") else len(points) // 3
            depth = (points.reshape(-1, 3).astype(float) - camera["position"]) @ forward  # (n,)
            depth = depth[depth > 0.1]  # before the camera
            kind = next(kind for kind in KINDS if message["name"].startswith(f"/samples/{kind}"))
            scale = draw.SAMPLE_SHAPES[kind.replace("_", " ")][1]
            base = draw.POINT_SIZE["3dc"] * scale
            if props["point_size"] > base * 1.001:  # grown: narrow at their own size, not past 13 px
                assert px(base, depth).max() < 9 * scale and px(props["point_size"], depth).max() < 13 * scale
            seen[kind].append(px(props["point_size"], depth))
    widths = {kind: np.concatenate(found) for kind, found in seen.items() if found}
    points, kinds = chain9.sample_points
    assert 0.9 * len(points) <= drawn < len(points)  # a few marks, those over the robot, are left out
    assert sum(len(w) for w in widths.values()) >= 0.75 * drawn  # most marks are before the camera (389 of 488)
    assert widths["valid"].min() >= 8 and widths["in_collision"].min() >= 1.6 * 8, {
        k: w.min() for k, w in widths.items()
    }
    for kind, cloud in chain9.sample_clouds.items():  # the live view as it was
        assert cloud.point_size == pytest.approx(draw.POINT_SIZE["3dc"] * draw.SAMPLE_SHAPES[kind][1])
        assert len(cloud.points) == kinds[kind].sum()


def test_the_animation_leaves_the_robot_and_the_camera_where_they_were(planned):
    v = planned
    v.set_configuration(v.path[0])
    before = np.array(v.nodes["robot"].batched_positions)
    camera = v.server.initial_camera.look_at.copy(), v.server.initial_camera.position.copy()
    v.animation_html(frames=4, seconds=1.0)
    np.testing.assert_allclose(v.q, v.path[0])
    np.testing.assert_allclose(v.nodes["robot"].batched_positions, before)
    assert v.valid
    np.testing.assert_allclose(v.server.initial_camera.look_at, camera[0])
    np.testing.assert_allclose(v.server.initial_camera.position, camera[1])
    assert all(np.allclose(frame.position, 0.0) for frame in v.frames.values())  # the scene back where it belongs
    np.testing.assert_allclose(v.shift, 0.0)  # and the robot drawn where it stands


def test_embed_is_a_static_snapshot_of_the_scene(rng):
    robot = scenarios.get("3dc7").robot
    snippet = viewer.embed("3dc7", seed=2, samples=robot.sample(rng, 40), height=320)
    assert snippet.startswith("<div><iframe") and 'height="320"' in snippet
    names = {message.get("name") for _, message in recording(page_of(snippet))[0]["messages"]}
    assert {"/workspace/obstacles", "/robot/links", "/samples"} <= names


def test_animation_iframe_embeds_the_page_escaped(planned):
    snippet = planned.animation_iframe(300, frames=3, seconds=1.0)
    assert snippet.startswith("<div><iframe srcdoc=") and 'height="' in snippet
    assert len(robot_poses(page_of(snippet))) == 3


def test_the_animation_iframe_is_tall_enough_for_its_whole_still(planned):
    snippet = planned.animation_iframe(300, frames=3, seconds=1.0)  # asked for less than the still needs
    png = base64.b64decode(found(r'src="data:image/png;base64,([^"]*)"', page_of(snippet)))
    still_height = int.from_bytes(png[20:24], "big")  # the PNG header's height, pixels
    assert still_height > 300  # the overview and two close-ups: two rows
    height = int(found(r'height="(\d+)"', snippet))
    assert height >= still_height  # every close-up in view, none cut off
    still_width = int.from_bytes(png[16:20], "big")  # shown at most COLUMN px wide: no blank band under it (r13b)
    assert height <= snapshot.COLUMN * still_height / still_width + snapshot.STILL_CONTROLS + 1


def test_the_animation_is_titled_apart_from_the_scene_and_says_p_valid_in_words(make_viewer):
    class Doubting:  # a model of P(valid) 0.2 at the path's start rising to 0.8 at its end, threshold 0.5
        robot = scenarios.get("3dc7").robot

        def probability(self, Q):
            return np.linspace(0.2, 0.8, len(Q))

        def are_valid(self, Q):
            return self.probability(Q) >= 0.5

    planned_exactly = make_viewer("3dc7", seed=1).plan("BS", seed=0)  # the path, found without the model
    v = make_viewer("3dc7", seed=1, predictor=lambda workspace: Doubting())
    v.show_plan(planned_exactly)
    scene, animation = v.iframe(200), v.animation_iframe(200, frames=5, seconds=1.0)
    titles = [found(r'title="([^"]*)"', snippet) for snippet in (scene, animation)]
    assert titles[0].startswith("3D scene of 3DC-7 (") and titles[1].startswith("3D animation of 3DC-7 (")  # r28e
    assert "with the box chain (7 DoF)" in titles[0]  # the pages' names, not the code's "chain7 robot"
    said = html.unescape(found(r'<p class="scene-summary">([^<]*)</p>', animation))
    assert "The exact checker finds the robot valid at 5 of the 5 frames." in said  # a verified path
    assert "ranges 0.20–0.80 along the path (lowest 0 % of the way along), median 0.50" in said  # 0.2, ..., 0.8
    assert "the model calls the robot colliding (P(valid) below its threshold) at 2 of the 5 frames" in said


def test_srcdoc_iframe_quotes_the_document_and_shows_without_a_warning(recwarn):
    snippet = viewer.srcdoc_iframe('<p title="a & b">x</p>', height=120, summary="A scene of <3 blocks. Samples: 4.")
    assert snippet == (
        '<div><iframe srcdoc="&lt;p title=&quot;a &amp; b&quot;&gt;x&lt;/p&gt;" width="100%" '
        'height="120" style="border:none" title="A scene of &lt;3 blocks"></iframe>'
        '<p class="scene-summary">A scene of &lt;3 blocks. Samples: 4.</p></div>'
    )
    HTML(snippet)  # IPython warns "Consider using IPython.display.IFrame" about markup starting with <iframe
    assert not [w for w in recwarn if "IFrame" in str(w.message)]


def test_an_animation_needs_a_path_and_frames(make_viewer):
    v = make_viewer("2ds")
    with pytest.raises(ValueError, match="no path"):
        v.animation_html()
    v.plan("BS", seed=0)
    with pytest.raises(ValueError, match="frames >= 2"):
        v.animation_html(frames=1)
    with pytest.raises(ValueError, match="seconds > 0"):
        v.animation_html(seconds=0.0)


def test_a_snapshot_prints_nothing(capsys):
    """viser's banner and "Server stopped" would be two stray outputs per snapshot in a notebook."""
    snippet = viewer.embed("2ds", height=200)
    assert "<iframe srcdoc=" in snippet and capsys.readouterr().out == ""


def test_a_saved_scene_names_its_player_controls_and_hides_notices():
    from toolkit.viewer.labels import NAMES, label_controls

    page = label_controls("<html><body><div id=root></div></body></html>")
    assert page.endswith("</script>\n</body></html>") and "display: none !important" in page
    assert all(name in page for name in NAMES.values())
    assert label_controls("<p>no body</p>").startswith("<p>no body</p><style>")


def test_a_saved_scene_carries_a_still_of_itself_shown_until_its_view_has_been_on_screen(rng):
    """A browser without WebGL leaves the view blank, and one draws no view off screen (reader r23b: a page's
    screenshot showed three blank boxes): the page shows a still picture of the same scene (the robot, the samples
    by kind, the path), its alt text saying what it shows, until the view has been on screen a moment; without
    WebGL for good, its note saying why."""
    from toolkit.viewer.labels import DRAWING, ON_SCREEN_MS

    robot = scenarios.get("3dc7").robot
    samples = robot.sample(rng, 40)
    document = page_of(viewer.embed("3dc7", seed=2, samples=samples, height=320))
    still = found(r'(<div id="toolkit-still"[\s\S]*?</div>)', document)
    assert 'id="toolkit-still" hidden' not in still and "toolkit-play" not in still
    assert html.unescape(found(r'id="toolkit-still-note"[^>]*>([^<]*)<', still)) == DRAWING
    alt = html.unescape(found(r'alt="([^"]*)"', still))
    valid = int(
        exact_checker(scenarios.get("3dc7").make_workspace(np.random.default_rng(2)), robot).are_valid(samples).sum()
    )
    assert f"{valid} samples valid (circles), {40 - valid} samples in collision (diamonds)" in alt
    assert "the robot close up among the blocks near it: the robot, valid" in alt
    assert alt.index("as a still: first the robot close up") < alt.index("; then the whole workspace")  # r32e: as drawn
    assert base64.b64decode(found(r'base64,([A-Za-z0-9+/=]+)"', still))[:4] == b"\x89PNG"
    script = document[document.index(still) + len(still) :]
    assert 'getContext("webgl2") || canvas.getContext("webgl")' in script and ".hidden = false" in script
    assert ".textContent = " + json.dumps(NO_WEBGL) in script
    assert "function hide() { still.hidden = true; fit(); }" in script
    assert f"isIntersecting) drawing = setTimeout(hide, {ON_SCREEN_MS});" in script
    assert 'addEventListener("focusin", hide);' in script  # the keyboard goes in
    assert "if (waiting) view.inert = false;" in script  # at once, not only after the view was on screen a while
    assert ".observe(document.documentElement)" in script
    assert "if (!false || !frame) return;" in script  # its frame keeps its height: the still fills it


def test_an_animation_opens_on_its_still_of_the_path_and_the_robot_at_its_start_middle_and_goal(planned):
    """Reader r11b: a screenshot caught the animation blank (software WebGL is slow to draw its first frame). Its
    page opens on the still in every browser, over the view, and a button plays the 3D view; without WebGL the
    button goes and the note says why there is only the still."""
    document = page_of(planned.animation_iframe(300, frames=3, seconds=1.0))
    still = found(r'(<div id="toolkit-still"[\s\S]*?</div>)', document)
    assert 'id="toolkit-still" hidden' not in still and 'id="toolkit-play" type="button"' in still
    note = html.unescape(found(r'id="toolkit-still-note"[^>]*>([^<]*)<', still))  # r18c took it for the animation
    assert note.startswith("A still picture, not the animation") and "Press play in 3D to watch the robot move" in note
    alt = html.unescape(found(r'alt="([^"]*)"', still))
    assert "the path of the robot's base" in alt
    assert re.search(r"close up among the blocks near it: start, valid; goal, valid\.$", alt)
    script = document[document.index(still) + len(still) :]
    assert re.search(
        r'play\.addEventListener\("click", function \(\) \{[^}]*still\.hidden = true;\s*view\.inert = false;', script
    )
    assert "view.inert = !still.hidden;" in script  # the covered view takes no focus
    assert "play.remove();" in script and ".textContent = " + json.dumps(NO_WEBGL) in script


def test_the_office_snapshot_shows_the_youbot_larger_than_its_sample_marks_and_near():
    """Reader r8b: the youBot was about 40 px, smaller than the marks in front of it. Every sample mark but the
    sparkle (which rings a mark) is at most a fifth of the platform's narrower side, and the camera stands within
    three and a half robot sizes of it (it stood at 5.2: in a headless Chromium at 800 x 440 px the platform grew
    from about 60 to about 95 px wide)."""
    robot = scenarios.get("3do").robot
    platform = 2 * np.array(robot.links[0].half_extents[:2])  # (2,) its footprint, workspace units
    for shape, scale in (draw.SAMPLE_SHAPES[kind] for kind in ("valid", "in collision")):
        assert draw.POINT_SIZE["3do"] * scale <= platform.min() / 5, shape
    looks, positions = framing.follow_camera(robot, np.clip(np.zeros(robot.dof), robot.lower, robot.upper)[None])
    assert np.linalg.norm(positions - looks) <= 3.5 * framing.robot_size(robot)


def robot_seen(png: bytes) -> tuple[int, float, float]:
    """In a screenshot of an animation's view: how many pixels show the robot (the palette's valid hue, saturated:
    the path's lighter sky blue and the pale blocks are not), the contrast of their median colour with white (the
    view's background) and with the median of the ring of pixels around them (what the robot is seen against);
    zeros where no pixel shows it."""
    from io import BytesIO

    from matplotlib.colors import rgb_to_hsv
    from PIL import Image
    from scipy import ndimage

    from toolkit.plots.palette import contrast

    image = np.asarray(Image.open(BytesIO(png)).convert("RGB"))[:-40] / 255.0  # (H, W, 3), above the player's bar
    hsv = rgb_to_hsv(image)
    hue = rgb_to_hsv(np.array(draw.VALID) / 255.0)[0]
    robot = (np.abs(hsv[..., 0] - hue) < 0.04) & (hsv[..., 1] > 0.8)  # (H, W)
    if robot.sum() == 0:
        return 0, 0.0, 0.0
    outline = int(np.ceil(draw.LINK_EDGE_PX))  # the links' own ink edges: the robot, not what it is seen against
    ring = ndimage.binary_dilation(robot, iterations=outline + 6) & ~ndimage.binary_dilation(robot, iterations=outline)
    as_hex = lambda pixels: "#" + "".join(f"{round(c * 255):02x}" for c in np.median(pixels, axis=0))
    return (
        int(robot.sum()),
        contrast(as_hex(image[robot]), "#ffffff"),
        contrast(as_hex(image[robot]), as_hex(image[ring])),
    )


@pytest.mark.browser
@pytest.mark.skipif(viewer_browser.find_chromium() is None, reason="no Chromium installed")
def test_the_animation_is_never_washed_out(planned, chromium, tmp_path):
    """WCAG 1.4.11: viser drew the view at 5 % opacity until its environment map had loaded and faded it in over
    five drawn frames, again at each loop of a saved animation; under software WebGL (headless Chromium) most frames
    of chapter 05's animation came out washed out, the robot at 1.1:1 against the blocks (no frame sampled here
    showed it at all). Now the scene is lit without that map, the page keeps the view opaque and 3DC's blocks are
    fainter (the robot inside one stood at 2.5:1): the frames sampled show the robot at 3:1 or more on white and
    against the pixels around it. Every one shows it: a robot slid by its frame used to leave the view for the drawn
    frames between its pose and its links' new shape (up to 4 of these 12 screenshots at a load of 4-5)."""
    page_file = tmp_path / "animation.html"
    page_file.write_text(planned.animation_html(frames=20, seconds=2.0), encoding="utf-8")
    page = chromium.new_page(viewport={"width": 640, "height": 480})
    try:
        page.goto(page_file.as_uri(), wait_until="load")
        page.wait_for_selector("[data-camera-controls-version] canvas")
        deadline = monotonic() + 120  # software WebGL on a busy machine is slow to draw the first frame
        while robot_seen(page.screenshot())[0] < 30:
            assert monotonic() < deadline, "no frame showed the robot"
            page.wait_for_timeout(500)
        frames = []
        for _ in range(12):
            frames.append(robot_seen(page.screenshot()))
            page.wait_for_timeout(400)
    finally:
        page.close()
    assert all(seen >= 30 and white >= 3 and behind >= 3 for seen, white, behind in frames), str(frames)


def test_a_snapshot_under_its_still_shows_a_one_line_note_not_a_second_still(planned):
    """Reader r24b: each still showed twice in a browser without WebGL, once on the page and once, cut at the view's
    height, in the view's place. With ``still_above`` the view's stand-in is one line that points to the still, its
    frame that tall until the view draws (reader r25b)."""
    from toolkit.viewer.labels import ABOVE, NO_WEBGL_ABOVE

    document = page_of(planned.iframe(200, still_above=True))
    still = found(r'(<div id="toolkit-still"[\s\S]*?</div>)', document)
    assert "<img" not in still and "base64," not in still
    assert html.unescape(found(r'id="toolkit-still-note"[^>]*>([^<]*)<', still)) == ABOVE
    script = document[document.index(still) :]
    assert ".textContent = " + json.dumps(NO_WEBGL_ABOVE) in script
    # reader r25b: a 300 px blank box under the note; the frame is as tall as the note until the view draws
    assert "if (!true || !frame) return;" in script
    assert 'frame.style.height = still.hidden ? "" : still.firstElementChild.offsetHeight + "px";' in script
    assert "<img" in page_of(planned.iframe(200))  # by default the still itself stands in
