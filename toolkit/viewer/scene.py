"""The live scene: a :class:`Viewer` shows one scenario's workspace, robot, samples, roadmap and path.

The scene answers the paper's §III in colors (:mod:`toolkit.plots.palette`) and words: link boxes take the valid or
the invalid colour by the exact checker (the panel says which); a model's (``checkpoint=`` or ``predictor=``)
wireframe shows P(valid); samples are shaped by kind. :meth:`Viewer.plan` runs the planner named (default the lazy
PRM) on a query from :func:`toolkit.experiments.problems.build`; with a model loaded, the model decides samples.
The viewer knows nothing of a GUI: it tells *listeners* what happened (:data:`EVENTS`, :meth:`Viewer.subscribe`),
the panel (:mod:`toolkit.viewer.panel`) among them, and any of them changes the scene through its public methods.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from pathlib import Path

import numpy as np
import viser
from matplotlib.figure import Figure

from toolkit import scenarios
from toolkit.experiments import problems, query_sets
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.robots import BASES
from toolkit.planning import prm
from toolkit.planning.local_planner import path_at
from toolkit.planning.sampling import make_sampler
from toolkit.viewer import drawing as draw
from toolkit.viewer import framing, models, snapshot
from toolkit.viewer.labels import label_controls
from toolkit.viewer.models import Predictor
from toolkit.viewer.server import camera_at, page_path, start_server, stop_server

LAYERS = ("obstacles", "robot", "prediction", "samples", "roadmap", "path")
# nodes shown and hidden with a layer, not its children (viser would draw a see-through node's child see-through)
ALONG = {"obstacle_edges": "obstacles", "link_edges": "robot"}
HALO = 0.5  # the prediction wireframe stands this share of the thinnest link clear of the links: apart from their edges
SLIDING = ("/workspace", "/plan")  # frames an animation slides so the camera follows the robot; it is drawn moved
RAW = "raw"  # the "sampler" of uniform configurations, unfiltered: what a model is asked about

EVENTS = {  # what a Viewer tells its listeners, and the arguments a listener's callback receives
    "loading": "before a new workspace replaces the scene (outside the lock: a listener may wait for its threads); ()",
    "loaded": "a new workspace, robot and checkers are in place; ()",
    "moved": "the robot moved: q, valid, probability, predicted_valid are current; ()",
    "sampled": "samples are shown: sample_counts is current; ()",
    "planned": "a PRM result is drawn (path holds its path, or None); (result,)",
    "stopping": "before the server stops (outside the lock); ()",
}


class Viewer:
    """A live Viser scene of one scenario and workspace, served on ``host:port``.

    ``checkpoint`` (a folder from ``toolkit train``) or ``predictor`` (a function workspace -> learned checker) adds
    the model's predictions. A checkpoint that cannot be read, or a host or port that cannot be served on, raises
    before the server starts. The scene has no GUI of its own: :func:`toolkit.viewer.launch` adds the panel.
    """

    def __init__(
        self,
        scenario: str | scenarios.Scenario = "3do",
        *,
        seed: int = 0,
        checkpoint: str | Path | None = None,
        predictor: Predictor | None = None,
        host: str = "127.0.0.1",
        port: int = 8080,
    ):
        self.predictor = models.predictor(checkpoint, predictor)
        self.server = start_server(host, port)
        draw.light(self.server.scene)
        self.lock = threading.RLock()  # GUI callbacks arrive on viser's threads
        self.listeners: dict[str, list[Callable]] = {event: [] for event in EVENTS}
        self.nodes: dict[str, viser.SceneNodeHandle] = {}
        self.visible = dict.fromkeys(LAYERS, True)
        self.path: np.ndarray | None = None  # (P, dof) the shown solution path
        self.sample_counts: dict[str, int] = {}  # shown samples by kind (drawing.SAMPLE_SHAPES)
        self.sample_clouds: dict[str, viser.PointCloudHandle] = {}  # and their point clouds
        self.sample_points: tuple[np.ndarray, dict[str, np.ndarray]] | None = None  # (N, 3) and masks by kind
        self.stopped = False
        self.frames = {name: self.server.scene.add_frame(name, show_axes=False) for name in (*SLIDING, "/robot")}
        self.shift = np.zeros(3)  # the robot is drawn this far from where it stands (an animation's slide)
        try:
            self.load(scenario, seed)
        except BaseException:  # e.g. an unknown scenario: leave no server behind
            self.stop()
            raise

    @property
    def port(self) -> int:
        return self.server.get_port()

    @property
    def url(self) -> str:
        host = self.server.get_host()
        return f"http://{'127.0.0.1' if host in ('0.0.0.0', '') else host}:{self.port}{page_path(self.server)}"

    @property
    def robot(self):
        return self.scenario.robot

    @property
    def _halo(self) -> float:
        """How far the prediction wireframe stands clear of the links, in workspace units (:data:`HALO`)."""
        return HALO * 2 * float(np.min(self.robot.half_extents))

    # -- listeners ---------------------------------------------------------------------
    def subscribe(self, event: str, callback: Callable) -> None:
        """Call ``callback`` whenever ``event`` (one of :data:`EVENTS`) happens, with the arguments listed there.

        A listener that subscribes after the viewer started reads its current state itself.
        """
        if event not in EVENTS:
            raise ValueError(f"unknown event {event!r}; choose one of {tuple(EVENTS)}")
        if not callable(callback):
            raise TypeError(f"a listener must be callable, got {callback!r}")
        self.listeners[event].append(callback)

    def _notify(self, event: str, *args) -> None:
        for callback in list(self.listeners[event]):
            callback(*args)

    # -- workspace and robot -----------------------------------------------------
    def load(self, scenario: str | scenarios.Scenario, seed: int) -> None:
        """Show a new workspace of ``scenario`` (a name or a scenario) drawn from ``seed``; the robot starts at a
        valid rest pose."""
        self._notify("loading")  # before taking the lock: a listener may wait for a thread that needs it
        with self.lock:
            self.scenario = scenarios.get(scenario) if isinstance(scenario, str) else scenario
            self.seed = int(seed)
            rng = np.random.default_rng(self.seed)
            self.workspace = self.scenario.make_workspace(rng)
            self.exact = exact_checker(self.workspace, self.robot)
            self.model, self.model_error = models.model_for(self.predictor, self.workspace, self.robot)
            for name in ("prediction", "disagreement", "samples", "roadmap", "path"):
                self._remove(name)
            self.path, self.sample_counts, self.sample_clouds, self.sample_points = None, {}, {}, None
            for layer, handle in draw.draw_workspace(self.server.scene, self.workspace).items():
                self._add(layer, handle)
            self.q = self.valid_configuration(rng, rest=True)
            self._aim_camera(*framing.camera_pose(self.robot, self.workspace, self.q))
            boxes = draw.robot_boxes(self.robot, self.q[None])
            self._add("robot", draw.add_boxes(self.server.scene, "/robot/links", boxes, colors=draw.VALID))
            self._add("link_edges", draw.add_edges(self.server.scene, "/robot/link_edges", boxes, draw.LINK_EDGE_PX))
            if self.model is not None:
                grown = boxes.grown(self._halo)  # the wireframe clear of the links' edges
                self._add("prediction", draw.add_wireframe(self.server.scene, "/robot/prediction", grown, draw.VALID))
                self.nodes["disagreement"] = self.server.scene.add_label(
                    "/robot/disagreement", "model disagrees", visible=False
                )
            self._notify("loaded")
            self.set_configuration(self.q)

    def set_configuration(self, q) -> None:
        """Move the robot to ``q (dof,)`` and color it by validity (§III): valid or invalid colour, by the exact
        checker; the model's wireframe dark grey (p = 0) to yellow (p = 1)."""
        q = self.robot.check_configs(q, "q")[0]
        with self.lock:
            self.q = q
            boxes = draw.robot_boxes(self.robot, q[None]).moved(self.shift)
            self.valid = bool(self.exact.are_valid(q[None])[0])
            draw.move_boxes(
                self.nodes["robot"],
                boxes,
                np.broadcast_to(draw.VALID if self.valid else draw.COLLIDING, (len(boxes), 3)),
                self.nodes["link_edges"],
            )
            self.probability = self.predicted_valid = None
            if isinstance(self.model, models.Predicts):  # every model model_for keeps
                self.probability = float(self.model.probability(q[None])[0])
                self.predicted_valid = bool(self.model.are_valid(q[None])[0])
                draw.move_wireframe(
                    self.nodes["prediction"], boxes.grown(self._halo), draw.probability_colors([self.probability])[0]
                )
                above = 0.8 * framing.robot_size(self.robot)  # robot sizes above its top: clear of it (0.5 touched)
                self.nodes["disagreement"].position = boxes.centers.max(axis=0) + np.array([0.0, 0.0, above])
                self._show_disagreement()
            self._notify("moved")

    def valid_configuration(self, rng: np.random.Generator, *, rest: bool = False, tries: int = 512) -> np.ndarray:
        """A valid configuration ``(dof,)`` drawn with ``rng``.

        ``rest``: the arm at rest (joints 0, within limits) and, of the valid candidates,
        the one whose base is nearest the middle of the workspace (easy to find on screen).
        If none of ``tries`` candidates is valid, the first one (it is shown red).
        """
        Q = self.robot.sample(rng, tries)  # (tries, dof)
        if rest:
            n_base = len(BASES[self.robot.base][0])
            Q[:, n_base:] = np.clip(0.0, self.robot.lower[n_base:], self.robot.upper[n_base:])
        valid = np.flatnonzero(self.exact.are_valid(Q))
        if not len(valid) or not rest:
            return Q[valid[0]] if len(valid) else Q[0]
        middle = (self.workspace.lower + self.workspace.upper) / 2
        bases = self.robot.link_boxes(Q[valid])[0][:, 0]  # (V, D)
        return Q[valid[np.argmin(np.linalg.norm(bases - middle, axis=1))]]

    # -- samples, roadmap, path ------------------------------------------------------
    def show_samples(self, Q, *, at: str = "base") -> np.ndarray:
        """Mark configurations ``Q (N, dof)`` as points colored by exact validity (§III), shaped by kind
        (:func:`~toolkit.viewer.drawing.add_samples`); returns the ``(N, 3)`` colors."""
        Q = self.robot.check_configs(Q)
        with self.lock:
            valid = self.exact.are_valid(Q)
            predicted = self.model.are_valid(Q) if self.model is not None else None
            kinds = draw.sample_kinds(valid, predicted)
            self._remove("samples")
            self._add("samples", self.server.scene.add_frame("/samples", show_axes=False))  # the clouds' parent
            points, size = draw.config_points(self.robot, Q, at), draw.POINT_SIZE[self.workspace.family]  # (N, 3)
            self.sample_clouds = draw.add_samples(self.server.scene, points, kinds, size)
            self.sample_counts = {kind: int(mask.sum()) for kind, mask in kinds.items()}
            self.sample_points = (points, kinds)
            self._notify("sampled")
            return draw.validity_colors(valid)

    def sample(self, sampler: str = RAW, n: int = 200, *, seed: int = 0, at: str = "base") -> np.ndarray:
        """Draw ``n`` attempts with ``sampler`` and show them; returns the samples ``(M, dof)``.

        ``'raw'``: uniform configurations, unfiltered (what the model is asked about);
        ``'BS'``, ``'OB'``, ``'G'``, ``'BT'`` (the paper's samplers, §III-B) or any name given
        to :func:`toolkit.planning.sampling.register_sampler`: validity decided by the model
        when one is loaded (Algorithm 1, lines 2-3), else exactly.
        """
        rng, checker = np.random.default_rng(seed), self.model or self.exact
        Q = self.robot.sample(rng, n) if sampler == RAW else make_sampler(sampler, checker).sample(n, rng)
        self.show_samples(Q, at=at)
        return Q

    def plan(self, sampler: str = "BS", *, seed: int = 0, planner: str | None = None) -> prm.PlanResult:
        """Solve a paper-style query (§IV-A: valid start and goal far apart, from ``seed``) with ``planner`` (a name;
        None: ``toolkit.planning.prm.DEFAULT``), a loaded model deciding samples, and show it (verified exactly).
        ``sampler``: any name :meth:`sample` takes but ``'raw'``."""
        rng = np.random.default_rng(seed)
        query = query_sets.Query(0, self.workspace, *query_sets.query_pairs(self.scenario, self.workspace, 1, rng)[0])
        result = problems.build(
            self.scenario, query, sampler=sampler, planner=planner, checker=self.model, exact=self.exact
        ).solve(rng)
        self.show_plan(result)
        return result

    def show_plan(self, result: prm.PlanResult, *, at: str = "base") -> None:
        """Draw a PRM result: roadmap edges as one line-segment node, the path, and move the robot to its start."""
        nodes, edges = np.asarray(result.roadmap.nodes), np.asarray(result.roadmap.edges).reshape(-1, 2)
        with self.lock:
            points = draw.config_points(self.robot, nodes, at)  # (V, 3)
            self._add(
                "roadmap",
                self.server.scene.add_line_segments(
                    "/plan/roadmap",
                    draw.edge_segments(points, edges),
                    draw.ROADMAP,
                    thickness=1.0,
                    thickness_units="screen",
                ),
            )
            self._remove("path")
            self.path = None
            if len(result.path) > 1:
                self.path = self.robot.check_configs(result.path, "path")
                dense = self.path_configurations(np.linspace(0.0, 1.0, 20 * len(self.path)))
                self._add(
                    "path",
                    self.server.scene.add_line_segments(
                        "/plan/path",
                        draw.polyline_segments(draw.config_points(self.robot, dense, at)),
                        draw.PATH,
                        thickness=4.0,
                        thickness_units="screen",
                    ),
                )
                self.set_configuration(self.path[0])
            self._notify("planned", result)

    def path_configurations(self, t) -> np.ndarray:
        """``(T, dof)`` configurations at fractions ``t`` (T,) of the shown path's length."""
        if self.path is None:
            raise ValueError("no path is shown; plan or show_plan first")
        return path_at(self.robot, self.path, t)

    # -- layers, pages, shutdown -----------------------------------------------------------
    def set_visible(self, layer: str, visible: bool) -> None:
        """Show or hide one of :data:`LAYERS`."""
        if layer not in LAYERS:
            raise ValueError(f"unknown layer {layer!r}; choose one of {LAYERS}")
        with self.lock:
            self.visible[layer] = bool(visible)
            for name in (layer, *(node for node, along in ALONG.items() if along == layer)):
                if name in self.nodes:
                    self.nodes[name].visible = bool(visible)
            if layer == "prediction" and self.model is not None:
                self._show_disagreement()

    def html(self) -> str:
        """The current scene as one self-contained HTML document (no server needed), its camera framing the robot
        from where the fewest links stand behind blocks and no sample mark hides it (``framing.robot_camera``), the
        far marks grown to be told apart (:func:`~toolkit.viewer.drawing.far_scale`)."""
        with self.lock:
            points, sizes, size = None, np.zeros(0), draw.POINT_SIZE[self.workspace.family]
            if self.sample_points is not None and self.visible["samples"]:
                points, kinds = self.sample_points
                sizes = draw.mark_sizes(kinds, size)  # (N,)
            camera = framing.robot_camera(
                self.robot, self.q, workspace=self.workspace, points=points, sizes=sizes, size=size
            )
            with camera_at(self.server, *camera), snapshot.far_marks_grown(self, *camera):
                return label_controls(self.server.scene.as_html())

    def summary(self) -> str:
        """The scene in words, the text alternative of a snapshot: workspace, robot, samples, path."""
        counts = {**self.sample_counts, **({} if self.model else {"model wrong": None})}  # None: no model judged
        return draw.scene_summary(self.workspace, self.robot, bool(self.valid), counts, self.path)

    def iframe(self, height: int = 480, *, still_above: bool = False) -> str:
        """The scene as a static snapshot ``<iframe>`` for ``IPython.display.HTML``: :func:`snapshot.iframe`; with
        ``still_above`` (the page shows :meth:`still` just above it), a one-line note in place of a second still."""
        return snapshot.iframe(self, height, still_above=still_above)

    def animation_html(self, *, frames: int = 60, seconds: float = 6.0) -> str:
        """The robot moving along the shown path, as one self-contained HTML document (no server needed).

        A recording made with viser's scene serializer: the scene as it is now, then ``frames`` configurations
        evenly spaced along the path (:meth:`path_configurations`), ``seconds / (frames - 1)`` apart, colored as
        :meth:`set_configuration` colors them. The camera follows the robot (``framing.follow_camera``): a recording
        cannot move a browser's camera, so the scene slides under it (:meth:`_slide`), and a student can still turn
        the view. The page loops, with a timeline to pause and scrub; all is put back.
        """
        if frames < 2 or not seconds > 0:
            raise ValueError(f"an animation needs frames >= 2 and seconds > 0, got {frames} and {seconds}")
        configurations = self.path_configurations(np.linspace(0.0, 1.0, int(frames)))  # (F, dof)
        looks, positions = framing.follow_camera(self.robot, configurations)  # (F, 3) each
        middle, before = looks.mean(axis=0), self.q  # the camera looks at the middle; the robot slides there
        with self.lock, camera_at(self.server, middle, middle + positions[0] - looks[0]):
            recording = self.server.get_scene_serializer()  # the scene now, then every scene message
            for k, (q, look_at) in enumerate(zip(configurations, looks)):
                recording.insert_sleep(seconds / (frames - 1) if k else 0.0)
                self._slide(middle - look_at)  # frame 0's too: each loop of the page starts from it
                self.set_configuration(q)
            document = label_controls(recording.as_html())  # stops the recording
            self._slide(np.zeros(3))
            self.set_configuration(before)
        return document

    def animation_iframe(self, height: int = 480, *, frames: int = 60, seconds: float = 6.0) -> str:
        """:meth:`animation_html` as an ``<iframe>`` with its frames in words: :func:`snapshot.animation_iframe`."""
        return snapshot.animation_iframe(self, height, frames=frames, seconds=seconds)

    def still(self, poses: dict[str, np.ndarray] | None = None) -> Figure:
        """The scene as a still picture, the robot close up at ``poses`` ``{label: q}`` (default: where it stands):
        :func:`toolkit.viewer.snapshot.scene_still`, what a 3D scene's page shows where a browser has no WebGL or
        has not drawn the view yet."""
        return snapshot.scene_still(self, poses)

    def stop(self) -> None:
        """Tell the listeners, then stop the server; the port is free afterwards. Stopping twice is harmless."""
        if self.stopped:
            return
        self.stopped = True
        self._notify("stopping")
        stop_server(self.server)

    def __enter__(self) -> Viewer:
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    # -- internals ------------------------------------------------------------------------
    def _show_disagreement(self) -> None:
        self.nodes["disagreement"].visible = self.visible["prediction"] and self.predicted_valid != self.valid

    def _slide(self, offset: np.ndarray) -> None:
        """Move all but the lights by ``offset (3,)`` (zero: where it belongs): :data:`SLIDING` and the samples by pose,
        the robot drawn moved (a page's player poses before it reshapes: a robot slid by its frame left the view)."""
        moving = [self.frames[name] for name in SLIDING] + [self.nodes[n] for n in ("samples",) if n in self.nodes]
        for handle in moving:
            handle.position = offset
        self.shift = np.asarray(offset, dtype=float)

    def _aim_camera(self, look_at: np.ndarray, position: np.ndarray) -> None:
        self.server.initial_camera.look_at, self.server.initial_camera.position = look_at, position
        for client in self.server.get_clients().values():
            client.camera.look_at, client.camera.position = look_at, position

    def _add(self, layer: str, handle: viser.SceneNodeHandle) -> None:
        handle.visible = self.visible.get(ALONG.get(layer, layer), True)
        self.nodes[layer] = handle

    def _remove(self, name: str) -> None:
        handle = self.nodes.pop(name, None)
        if handle is not None:
            handle.remove()
