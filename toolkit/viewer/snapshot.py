"""A viewer's scene on a page that needs no server: a snapshot or an animation in an ``<iframe>``, and a still.

``viewer`` is a :class:`toolkit.viewer.scene.Viewer` in every function here (not imported: it imports this).

A saved 3D view needs WebGL to draw, and is not drawn off screen; where a browser has none, and in a snapshot until
its view has been on screen a moment, the page shows a still picture in the view's place
(:func:`toolkit.viewer.labels.with_still`): the whole workspace with the samples and the path the viewer
shows, then the robot close up. An animation opens on its still in every browser, with a button that plays it: a
screenshot, a printed page or a browser that draws 3D slowly (in software) shows a picture, not a view still
loading. Each frame is followed by the scene in words (its text alternative).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from matplotlib.figure import Figure

from toolkit.plots import scenes
from toolkit.viewer import drawing as draw
from toolkit.viewer import framing, models
from toolkit.viewer.labels import with_still
from toolkit.viewer.server import srcdoc_iframe

ANIMATION_STILL = (  # what the still is, and where the moving robot is: a reader took the still for the animation
    "A still picture, not the animation: the path, then the robot at its start and goal, close up. "
    "Press play in 3D to watch the robot move along the path (in a browser that draws 3D)."
)


def scene_still(viewer, poses: dict[str, np.ndarray] | None = None, close: tuple[str, ...] | None = None) -> Figure:
    """``viewer``'s scene as :func:`toolkit.plots.scenes.scene_still` draws it: the whole workspace with the shown
    samples and path, the robot drawn, then the robot close up at ``poses`` ``{label: q (dof,)}`` (default: where
    it stands now), each said valid or in collision by the exact checker; ``close`` names those seen close up
    (default: every one)."""
    poses = {"the robot": viewer.q} if poses is None else poses
    valid = dict(zip(poses, (bool(v) for v in viewer.exact.are_valid(np.stack(list(poses.values()))))))
    trace = None
    if viewer.path is not None:
        dense = viewer.path_configurations(np.linspace(0.0, 1.0, 20 * len(viewer.path)))  # (20 P, dof)
        trace = draw.config_points(viewer.robot, dense, "base")  # (T, 3)
    samples = viewer.sample_points if viewer.visible["samples"] else None
    model = None
    checker = viewer.model
    if isinstance(checker, models.Predicts):  # what the model answers for each pose, in its close-up's title
        Q = np.stack(list(poses.values()))  # (P, dof)
        answers = zip(checker.probability(Q), viewer.model.are_valid(Q))
        model = {label: (float(p), bool(ok)) for label, (p, ok) in zip(poses, answers)}
    return scenes.scene_still(
        viewer.robot, viewer.workspace, poses, valid=valid, samples=samples, trace=trace, model=model, close=close
    )


@contextmanager
def far_marks_grown(viewer, look_at: np.ndarray, position: np.ndarray) -> Iterator[None]:
    """``viewer``'s sample marks grown for a page whose camera stands at ``position`` looking at ``look_at`` (3,) each
    (:func:`toolkit.viewer.drawing.far_scale`: far ones told apart by shape; in a crowded view, near ones shrunk),
    less those that would stand over the robot on its picture (:func:`toolkit.viewer.framing.marks_over_robot`; the
    summary still counts them), while the block runs, then back as the live view draws them (in workspace units: a
    camera that moves cannot size them for itself)."""
    if viewer.sample_points is None or not viewer.visible["samples"]:
        yield
        return
    points, kinds = viewer.sample_points  # (N, 3) and (N,) masks
    size = draw.POINT_SIZE[viewer.workspace.family]
    depth = (points - position) @ ((look_at - position) / np.linalg.norm(look_at - position))  # (N,)
    for cloud in viewer.sample_clouds.values():
        cloud.remove()
    scales = draw.far_scale(depth, size, crowded=len(points) > draw.CROWDED)  # (N,)
    shown = ~framing.marks_over_robot(
        viewer.robot, viewer.q, look_at, position, points, draw.mark_sizes(kinds, size) * scales
    )  # (N,) all but the marks that would cover the robot
    grown = draw.add_samples(
        viewer.server.scene, points[shown], {kind: mask[shown] for kind, mask in kinds.items()}, size, scales[shown]
    )
    try:
        yield
    finally:
        for cloud in grown.values():
            cloud.remove()
        viewer.sample_clouds = draw.add_samples(viewer.server.scene, points, kinds, size)


def iframe(viewer, height: int = 480, *, still_above: bool = False) -> str:
    """``viewer``'s scene as a static snapshot ``<iframe>`` for ``IPython.display.HTML``, then its summary. Its
    stand-in until the view draws is the scene's still, or with ``still_above`` (the page shows that still just
    above, ``Viewer.still``) a one-line note that points to it (``labels.with_still``)."""
    drawn = viewer.robot.dim == 3  # a 3D scene: a still stands in for its view
    picture = scene_still(viewer) if drawn and not still_above else None
    document = with_still(viewer.html(), picture, above=drawn and still_above)
    return srcdoc_iframe(document, height, summary=viewer.summary())


def animation_iframe(viewer, height: int = 480, *, frames: int = 60, seconds: float = 6.0) -> str:
    """``viewer``'s animation along its path (``Viewer.animation_html``) as an ``<iframe>``, its frames in words; it
    opens on its still (:data:`ANIMATION_STILL`), over the 3D view until the reader plays it; ``height`` grows to
    hold the whole still (its overview and every close-up)."""
    Q = viewer.path_configurations(np.linspace(0.0, 1.0, int(frames)))  # (F, dof): the frames' configurations
    told = draw.animation_summary(viewer.workspace, viewer.robot, Q, viewer.exact, viewer.model, viewer.path)
    ends = dict(zip(("start", "middle", "goal"), viewer.path_configurations(np.linspace(0.0, 1.0, 3))))
    picture = scene_still(viewer, ends, close=("start", "goal")) if viewer.robot.dim == 3 else None  # one row
    document = with_still(viewer.animation_html(frames=frames, seconds=seconds), picture, first=ANIMATION_STILL)
    if picture is not None:  # tall enough for the whole still (every close-up) under its note and play button
        drawn = picture.get_tightbbox().padded(0.1)  # as the page shows it: saved tight, savefig's pad_inches round
        height = max(height, round(COLUMN * drawn.height / drawn.width) + STILL_CONTROLS)
    return srcdoc_iframe(document, height, summary=told)


COLUMN = 640  # pixels: the widest the still is shown (its max-width in labels.STILL), a little over a page's 631
STILL_CONTROLS = 100  # pixels: the still's note (two lines) and its play button, above it
