"""Drawing the paper's scenes with Viser: obstacle boxes, robots, samples, roadmaps (§IV-A).

Everything is drawn in 3D, as batches of boxes (one Viser node per batch, one unit
cube instanced with per-box pose, size and color). A 2D workspace (2DS) becomes a
flat scene: its blocks are extruded to :data:`FLAT_HEIGHT` and the point robot's
square to :data:`FLAT_ROBOT_HEIGHT`, so it pokes out of any block it collides with.

Colors tell validity (§III), from :mod:`toolkit.plots.palette` (Okabe-Ito, apart for colour-blind eyes too):
the valid colour (blue), the invalid one (vermillion) in collision. Samples carry a second cue, their shape
(:data:`SAMPLE_SHAPES`): circles valid, diamonds in collision, and a larger sparkle behind the mark where a learned
model disagrees with the exact checker; on a page, the far ones grow until their shapes can be told, and in a
crowded view the near ones shrink (:func:`far_scale`). A probability of validity is drawn dark grey (0) to
yellow (1), the model's wireframe a box's 12 edges around each link (:func:`add_wireframe`). Blocks and links are
edged in ink (:func:`add_edges`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import numpy as np
import numpy.typing as npt
import trimesh
import viser
import viser.transforms as vtf

from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import Workspace
from toolkit.plots.palette import probability_rgb, rgb
from toolkit.plots.scenes import scene_words

FLAT_HEIGHT = 1.0  # height of a 2D block in the flat 3D scene
FLAT_ROBOT_HEIGHT = 1.5  # height of the 2D point robot's square

OBSTACLE = rgb("obstacle")  # a hue of its own: the browser test looks for it
OBSTACLE_OPACITY = {"3dc": 0.3}  # by family: see through the clutter to the robot inside (0.45: it was 2.5:1 there)
EDGE = rgb("ink")  # every block's and link's edges: an outline at 3:1 or more on the white, the blocks and the links
EDGE_PX = 2.0  # their width on screen, in pixels, near or far
# A link's ink outline sets the robot apart from its colour's edgeless marks: 3.5 px blackened a 0.1-thick link;
# at 1.5 px the robot fell under 3:1 against a see-through block in 2 of 4 runs of the animation's washed-out test.
LINK_EDGE_PX = 2.5
VALID = rgb("valid")
COLLIDING = rgb("invalid")
PREDICTION_PX = 3.0  # the P(valid) wireframe's lines, in pixels: a box's 12 edges around each link (reader r19c: a
#   1-pixel, half see-through wireframe with its faces' diagonals read as a few hair lines against the robot)
MISTAKE = rgb("ink")  # a sample the learned model gets wrong (drawn over its validity colour)
POINT_SIZE = {"2ds": 0.25, "3do": 0.12, "3dc": 0.07}  # sample markers, by workspace family (3DC: dense, seen close)
SAMPLE_SHAPES: dict[str, tuple[Literal["circle", "diamond", "sparkle"], float]] = {
    "valid": ("circle", 1.0),
    "in collision": ("diamond", 1.6),
    "model wrong": ("sparkle", 3.0),
}
# shape and size (times POINT_SIZE) of each kind of sample: a cue besides colour
VIEW_FOV = np.deg2rad(75.0)  # viser's vertical field of view (its default, and the snapshots')
FAR_MARK = 0.02  # on a page, a far mark is drawn at least this share of the view's height wide (9 px of 440)
FAR_STEP = np.sqrt(2.0)  # far marks grow in steps of this factor (one point cloud per step)
CROWDED = 1000  # a page's view of more marks than this is crowded: its far marks grow less, its near ones shrink
CROWDED_MARK = FAR_MARK / FAR_STEP  # there, a far mark grows to 6 to 9 px of 440 (a circle still told from a diamond)
NEAR_MARK = 0.04  # and a near one is at most this share of the view's height wide (18 px of 440)
# the lights' intensities: at 0.4 ambient a link's face turned from the key light drew navy, 2.4:1 at most against
# its ink edges and the dark marks around it (reader r18c); brighter ambient light keeps every face the valid blue's hue
AMBIENT, KEY = 0.9, 0.8
REGION = rgb("ink")
ROADMAP = rgb("edge")
PATH = rgb("trace")

_UNIT_CUBE = trimesh.creation.box(extents=(1.0, 1.0, 1.0))


@dataclass(frozen=True)
class Boxes:
    """Oriented boxes in 3D: centres ``(N, 3)``, rotations ``(N, 3, 3)``, full sizes ``(N, 3)``."""

    centers: np.ndarray
    rotations: np.ndarray
    sizes: np.ndarray

    def __len__(self) -> int:
        return len(self.centers)

    def grown(self, margin: float) -> Boxes:
        """The same boxes, ``margin`` larger on every side, about their centres."""
        return Boxes(self.centers, self.rotations, self.sizes + 2 * margin)

    def moved(self, offset: npt.ArrayLike) -> Boxes:
        """The same boxes, their centres moved by ``offset (3,)``."""
        return Boxes(self.centers + np.asarray(offset, dtype=float), self.rotations, self.sizes)


def obstacle_boxes(workspace: Workspace) -> Boxes:
    """The workspace's ``K`` axis-aligned blocks; 2D blocks are extruded to ``FLAT_HEIGHT``."""
    lo, hi = lift_points(workspace.boxes[:, 0], 0.0), lift_points(workspace.boxes[:, 1], FLAT_HEIGHT)  # (K, 3)
    return Boxes((lo + hi) / 2, np.broadcast_to(np.eye(3), (len(lo), 3, 3)), hi - lo)


def robot_boxes(robot: BoxRobot, Q) -> Boxes:
    """Link boxes of every configuration in ``Q (N, dof)``, ``N * L`` boxes (configuration-major)."""
    centers, rotations, half = robot.link_boxes(Q)  # (N, L, D), (N, L, D, D), (L, D)
    n, links = centers.shape[:2]
    sizes = np.broadcast_to(2 * half, (n, links, robot.dim))  # (N, L, D)
    if robot.dim == 2:
        centers = lift_points(centers, FLAT_ROBOT_HEIGHT / 2)
        lifted = np.broadcast_to(np.eye(3), (n, links, 3, 3)).copy()
        lifted[..., :2, :2] = rotations
        rotations = lifted
        sizes = lift_points(sizes, FLAT_ROBOT_HEIGHT)
    return Boxes(centers.reshape(-1, 3), rotations.reshape(-1, 3, 3), sizes.reshape(-1, 3))


def config_points(robot: BoxRobot, Q, at: str = "base") -> np.ndarray:
    """One point per configuration, ``(N, 3)``: the centre of its first (``"base"``) or last (``"tip"``) link."""
    if at not in ("base", "tip"):
        raise ValueError(f"mark configurations at 'base' or 'tip', not {at!r}")
    centers = robot.link_boxes(Q)[0][:, 0 if at == "base" else -1]  # (N, D)
    return lift_points(centers, FLAT_ROBOT_HEIGHT) if robot.dim == 2 else centers


_CORNERS = np.array([[(i >> d) & 1 for d in range(3)] for i in range(8)])  # (8, 3) a unit cube's corners, 0 or 1
_CUBE_EDGES = np.array([(i, i | (1 << d)) for i in range(8) for d in range(3) if not (i >> d) & 1])  # (12, 2)


def box_edges(boxes: Boxes) -> np.ndarray:
    """The 12 edges of each of the ``N`` (oriented) ``boxes``, as segments ``(12 N, 2, 3)``."""
    offsets = (_CORNERS - 0.5) * boxes.sizes[:, None]  # (N, 8, 3) corners about the centre, in the box's frame
    corners = boxes.centers[:, None] + np.einsum("nij,nkj->nki", boxes.rotations, offsets)  # (N, 8, 3)
    return corners[:, _CUBE_EDGES].reshape(-1, 2, 3)


def region_edges(workspace: Workspace) -> np.ndarray:
    """The 12 edges of the workspace region, ``(12, 2, 3)`` (2D: the extruded region)."""
    lo, hi = lift_points(workspace.lower, 0.0), lift_points(workspace.upper, FLAT_HEIGHT)
    return box_edges(Boxes(((lo + hi) / 2)[None], np.eye(3)[None], (hi - lo)[None]))


def obstacle_edges(workspace: Workspace) -> np.ndarray:
    """The 12 edges of each of the workspace's ``K`` blocks, ``(12 K, 2, 3)`` (2D: the extruded blocks)."""
    return box_edges(obstacle_boxes(workspace))


def edge_segments(points: np.ndarray, edges: np.ndarray) -> np.ndarray:
    """Segments ``(E, 2, 3)`` joining ``points (V, 3)`` along ``edges (E, 2)`` of vertex indices."""
    return np.asarray(points, dtype=float)[np.asarray(edges, dtype=int).reshape(-1, 2)]


def polyline_segments(points: np.ndarray) -> np.ndarray:
    """Segments ``(P - 1, 2, 3)`` joining consecutive ``points (P, 3)``."""
    points = np.asarray(points, dtype=float)
    return np.stack([points[:-1], points[1:]], axis=1)


def validity_colors(valid: np.ndarray) -> np.ndarray:
    """``(N, 3)`` uint8 colors by exact validity ``(N,)``: :data:`VALID` or :data:`COLLIDING`."""
    valid = np.asarray(valid, dtype=bool)
    return np.where(valid[:, None], VALID, COLLIDING).astype(np.uint8)


def sample_kinds(valid: np.ndarray, predicted: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """Masks ``(N,)`` of each kind of sample in :data:`SAMPLE_SHAPES`: valid, in collision (by the exact checker)
    and, when a model's answers ``predicted (N,)`` are given, the ones it gets wrong."""
    valid = np.asarray(valid, dtype=bool)
    wrong = np.zeros_like(valid) if predicted is None else np.asarray(predicted, dtype=bool) != valid
    return {"valid": valid, "in collision": ~valid, "model wrong": wrong}


def mark_sizes(kinds: dict[str, np.ndarray], size: float) -> np.ndarray:
    """``(N,)`` the width of the widest mark drawn at each sample (:func:`add_samples`), in workspace units."""
    widths = [np.where(mask, size * SAMPLE_SHAPES[kind][1], 0.0) for kind, mask in kinds.items()]
    return np.max(widths, axis=0)


def far_scale(depth: npt.ArrayLike, size: npt.ArrayLike, crowded: bool = False) -> np.ndarray:
    """``(N,)`` how many times its ``size`` (one or ``(N,)``) a mark at ``depth (N,)`` before a page's camera is drawn.

    viser sizes a mark in workspace units: of width ``s`` at depth ``z``, it is ``s / (z tan(fov / 2))`` view heights
    wide, and a far one shrinks to a dot whose shape cannot be told. Near, 1; far, the least power of
    :data:`FAR_STEP` that draws it :data:`FAR_MARK` view heights wide. In a ``crowded`` view (:data:`CROWDED`) the
    grown marks would bury the robot: a far one grows only to :data:`CROWDED_MARK` (its shape just told) and a near
    one shrinks, by the same steps, to :data:`NEAR_MARK` at most."""
    unit = np.maximum(np.asarray(depth, dtype=float), 1e-9) * np.tan(VIEW_FOV / 2) / size  # (N,) view heights⁻¹
    low, high = (CROWDED_MARK, NEAR_MARK) if crowded else (FAR_MARK, np.inf)
    grow = np.ceil(np.log(np.maximum(low * unit, 1.0)) / np.log(FAR_STEP) - 1e-9)  # (N,) steps, 0 or more
    shrink = np.floor(np.log(np.minimum(high * unit, 1.0)) / np.log(FAR_STEP) + 1e-9)  # (N,) steps, 0 or fewer
    return FAR_STEP ** (grow + shrink)


def add_samples(
    scene: viser.SceneApi, points: np.ndarray, kinds: dict[str, np.ndarray], size: float, scales=1.0
) -> dict[str, viser.PointCloudHandle]:
    """Point clouds of the samples under ``/samples``, by kind (:func:`sample_kinds`): ``points (N, 3)`` in their
    validity colour (a model's mistakes in :data:`MISTAKE`), shaped and sized by :data:`SAMPLE_SHAPES`; a sparkle
    behind the mark it rings, whose shape still says valid or in collision. ``scales`` (one or ``(N,)``, from
    :func:`far_scale`) grows or shrinks marks: one cloud per kind and scale, keyed ``kind`` at scale 1, else
    ``kind far k`` (``FAR_STEP ** k`` times larger; ``k`` below 0: smaller)."""
    colors = validity_colors(kinds["valid"])  # (N, 3)
    steps = np.rint(np.log(np.broadcast_to(scales, kinds["valid"].shape)) / np.log(FAR_STEP)).astype(int)  # (N,)
    clouds = {}
    for kind, mask in sorted(kinds.items(), key=lambda item: -SAMPLE_SHAPES[item[0]][1]):  # the widest first:
        shape, scale = SAMPLE_SHAPES[kind]  # at one depth the mark drawn later covers the earlier: a sparkle rings
        for step in np.unique(steps[mask]):  # the mark it is on
            group = mask & (steps == step)
            shown = np.broadcast_to(MISTAKE, (int(group.sum()), 3)) if kind == "model wrong" else colors[group]
            key = kind if step == 0 else f"{kind} far {step}"
            clouds[key] = scene.add_point_cloud(
                f"/samples/{key.replace(' ', '_')}",
                points[group].astype(np.float32),
                shown,
                point_size=size * scale * FAR_STEP**step,
                point_shape=shape,
            )
    return clouds


def scene_summary(
    workspace: Workspace, robot: BoxRobot, valid: bool, samples: Mapping[str, int | None], path: np.ndarray | None
) -> str:
    """The scene in words, the text alternative of its picture: workspace, robot and its validity, ``samples`` by
    kind (:func:`sample_kinds`; ``"model wrong": None`` when no model judged them) and the ``path (P, dof)``."""
    words = [
        f"3D scene of {scene_words(workspace, robot)} at a configuration that is "
        f"{'valid' if valid else 'in collision'}."
    ]
    if samples.get("valid") is not None:
        words.append(f"Samples: {samples['valid']} valid (circles), {samples['in collision']} in collision (diamonds)")
        wrong = samples.get("model wrong")
        words[-1] += "." if wrong is None else f", {wrong} the model gets wrong (sparkles)."
    if path is not None:
        words.append(_path_words(path))
    return " ".join(words)


def animation_summary(
    workspace: Workspace, robot: BoxRobot, configurations: np.ndarray, exact, model, path: np.ndarray | None
) -> str:
    """The animation of the robot along ``path (P, dof)`` in words, the text alternative of its picture (its first
    sentence titles the page): how many of the frames' ``configurations (F, dof)`` the ``exact`` checker finds valid
    and, where ``model`` gives ``probability(Q)`` (shown only as the wireframe's colour), its P(valid) along the path
    and how many frames it calls colliding."""
    frames, n_valid = len(configurations), int(np.sum(exact.are_valid(configurations)))
    words = [
        f"3D animation of {scene_words(workspace, robot)} moving along a planned path in {frames} frames.",
        f"The exact checker finds the robot valid at {n_valid} of the {frames} frames.",
    ]
    if hasattr(model, "probability"):
        p = np.asarray(model.probability(configurations), dtype=float)  # (F,)
        doubted = frames - int(np.sum(model.are_valid(configurations)))
        words.append(
            f"The model's P(valid), the colour of the wireframe around the links (dark grey low, yellow high), ranges "
            f"{p.min():.2f}–{p.max():.2f} along the path (lowest {100 * np.argmin(p) / max(frames - 1, 1):.0f} % of "
            f"the way along), median {np.median(p):.2f}; the model calls the robot "
            f"colliding (P(valid) below its threshold) at {doubted} of the {frames} frames."
        )
    return " ".join(words + ([] if path is None else [_path_words(path)]))


def _path_words(path: np.ndarray) -> str:
    """The path in words: how many configurations it passes (a length would add workspace units to radians)."""
    return f"Path: {len(path)} configurations, drawn from start to goal."


def probability_colors(probability: npt.ArrayLike) -> np.ndarray:
    """``(N, 3)`` uint8 colors of P(valid) ``(N,)`` on ``palette.PROBABILITY_CMAP`` (p = 0 dark grey, p = 1 yellow)."""
    return probability_rgb(probability)


def add_boxes(
    scene: viser.SceneApi,
    name: str,
    boxes: Boxes,
    *,
    colors,
    opacity: float | None = None,
    visible: bool = True,
) -> viser.BatchedMeshHandle:
    """One batched-mesh node drawing ``boxes``; ``colors`` is one RGB or ``(N, 3)``."""
    return scene.add_batched_meshes_simple(
        name,
        _UNIT_CUBE.vertices,
        _UNIT_CUBE.faces,
        batched_wxyzs=_quaternions(boxes.rotations),
        batched_positions=boxes.centers,
        batched_scales=boxes.sizes,
        batched_colors=np.asarray(colors, dtype=np.uint8),
        opacity=opacity,
        flat_shading=True,
        lod="off",
        visible=visible,
    )


def add_edges(scene: viser.SceneApi, name: str, boxes: Boxes, width: float = EDGE_PX) -> viser.LineSegmentsHandle:
    """The edges of ``boxes`` (:func:`box_edges`), :data:`EDGE` lines :data:`EDGE_PX` pixels wide: each box reads as
    a box, see-through or seen far. A node of its own (as the boxes' child, viser would draw it see-through like
    see-through boxes); :func:`move_boxes` moves it with them."""
    return scene.add_line_segments(name, box_edges(boxes), EDGE, thickness=width, thickness_units="screen")


def add_wireframe(scene: viser.SceneApi, name: str, boxes: Boxes, color) -> viser.LineSegmentsHandle:
    """The 12 edges of each of ``boxes`` as lines :data:`PREDICTION_PX` pixels wide in one ``color`` (a model's
    P(valid), :func:`probability_colors`): no face, no diagonal; :func:`move_wireframe` moves it."""
    return scene.add_line_segments(
        name, box_edges(boxes), np.asarray(color, dtype=np.uint8), thickness=PREDICTION_PX, thickness_units="screen"
    )


def move_wireframe(handle: viser.SceneNodeHandle, boxes: Boxes, color) -> None:
    """Move a wireframe made by :func:`add_wireframe` to ``boxes`` (as many as before) and colour it ``color``."""
    if not isinstance(handle, viser.LineSegmentsHandle):
        raise TypeError(f"move_wireframe moves a node made by add_wireframe, got a {type(handle).__name__}")
    handle.points = box_edges(boxes).astype(np.float32)
    handle.colors = np.asarray(color, dtype=np.uint8)


def move_boxes(handle: viser.SceneNodeHandle, boxes: Boxes, colors, edges: viser.SceneNodeHandle | None = None) -> None:
    """Update the poses and colors of a node made by :func:`add_boxes` (same number of boxes), and their ``edges``
    (a node made by :func:`add_edges`) where given."""
    if not isinstance(handle, viser.BatchedMeshHandle):
        raise TypeError(f"move_boxes moves a node made by add_boxes, got a {type(handle).__name__}")
    if not isinstance(edges, (viser.LineSegmentsHandle, type(None))):
        raise TypeError(f"move_boxes moves edges made by add_edges, got a {type(edges).__name__}")
    handle.batched_positions = boxes.centers.astype(np.float32)
    handle.batched_wxyzs = _quaternions(boxes.rotations)
    handle.batched_colors = np.asarray(colors, dtype=np.uint8)
    if edges is not None:
        edges.points = box_edges(boxes).astype(np.float32)


def draw_workspace(scene: viser.SceneApi, workspace: Workspace) -> dict[str, viser.SceneNodeHandle]:
    """Obstacles (one batched node of ``K`` boxes), their edges, the region's outline and a floor grid, by layer name.

    A block's faces alone hardly stand out: the obstacle's yellow is 1.3:1 on the white and a see-through 3DC
    block fainter still (WCAG 1.4.11 asks 3:1 of a shape's boundary). Its edges (:func:`add_edges`) outline it.
    """
    width, depth = (workspace.upper - workspace.lower)[:2]
    center = np.append((workspace.lower + workspace.upper)[:2] / 2, 0.0)
    return {
        "obstacles": add_boxes(
            scene,
            "/workspace/obstacles",
            obstacle_boxes(workspace),
            colors=OBSTACLE,
            opacity=OBSTACLE_OPACITY.get(workspace.family),
        ),
        "region": scene.add_line_segments("/workspace/region", region_edges(workspace), REGION, thickness=0.05),
        "obstacle_edges": add_edges(scene, "/workspace/obstacle_edges", obstacle_boxes(workspace)),
        "floor": scene.add_grid(
            "/workspace/floor", width=width, height=depth, cell_size=1.0, section_size=5.0, position=center
        ),
    }


def light(scene: viser.SceneApi) -> None:
    """Soft light from the front-left: viser's default lights wash the tops of boxes out to white.

    No environment map: viser draws the view at 5 % opacity until its map has loaded, then fades it in over five
    drawn frames, and a saved animation loads it again each loop; under software WebGL the fade seldom ended and
    about 40 % of chapter 05's frames came out washed out (the robot at 1.1:1 on the blocks)."""
    scene.configure_default_lights(enabled=False)
    scene.configure_environment_map(hdri=None)
    scene.add_light_ambient("/lights/ambient", intensity=AMBIENT)
    scene.add_light_directional("/lights/key", intensity=KEY, position=(-1.0, -2.0, 3.0))


def _quaternions(rotations: np.ndarray) -> np.ndarray:
    """Rotation matrices ``(N, 3, 3)`` as wxyz quaternions ``(N, 4)``."""
    return vtf.SO3.from_matrix(np.asarray(rotations, dtype=float)).wxyz.astype(np.float32)


def lift_points(points: np.ndarray, z: float) -> np.ndarray:
    """``(..., D)`` points as ``(..., 3)``: 2D points get height ``z``, 3D points are unchanged."""
    points = np.asarray(points, dtype=float)
    if points.shape[-1] == 3:
        return points
    return np.concatenate([points, np.full(points.shape[:-1] + (1,), z)], axis=-1)
