"""The live viewer: a :class:`Viewer` serves one scenario's scene and its GUI panel; snapshots for notebooks."""

from __future__ import annotations

import contextlib
import errno
import html as html_lib
import socket
import threading
import time
from functools import partial
from pathlib import Path
from typing import Callable

import numpy as np
import rich
import viser

from toolkit import scenarios
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.geometry.robots import BASES
from toolkit.geometry.workspace import Workspace
from toolkit.planning import prm, queries
from toolkit.planning.sampling import make_sampler
from toolkit.viewer import drawing as draw
from toolkit.viewer.panel import Panel

Predictor = Callable[[Workspace], CollisionChecker]  # workspace -> checker with are_valid(Q), probability(Q)
LAYERS = ("obstacles", "robot", "prediction", "samples", "roadmap", "path")
HALO = 1.15  # the prediction wireframe is this much larger than the links


class Viewer:
    """A live Viser scene of one scenario and workspace, with its GUI panel.

    ``checkpoint`` (a folder from ``toolkit train``) or ``predictor`` (a function
    workspace -> learned checker) adds the model's predictions. A checkpoint that
    cannot be read, or a host or port that cannot be served on, raises before the
    server starts.
    """

    def __init__(self, scenario: str = "3do", *, seed: int = 0, checkpoint: str | Path | None = None,
                 predictor: Predictor | None = None, host: str = "127.0.0.1", port: int = 8080):
        if checkpoint is not None and predictor is not None:
            raise ValueError("give a checkpoint or a predictor, not both")
        if checkpoint is not None:
            from toolkit.learning.checkpoints import (
                load_models,  # torch: only when a model is asked for
            )
            from toolkit.learning.learned import LearnedChecker

            predictor = partial(LearnedChecker, models=load_models(checkpoint))
        self.predictor = predictor
        port = free_port(host, port)
        with _viser_quiet():  # launch() prints the one line a user needs
            self.server = viser.ViserServer(host=host, port=port, label="Predicting sample collision", verbose=False)
        draw.light(self.server.scene)
        self.lock = threading.RLock()  # GUI callbacks arrive on viser's threads
        self.nodes: dict[str, viser.SceneNodeHandle] = {}
        self.visible = dict.fromkeys(LAYERS, True)
        self.path: np.ndarray | None = None  # (P, dof) the shown solution path
        self.stopped = False
        self.panel = Panel(self)
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
        return f"http://{'127.0.0.1' if host in ('0.0.0.0', '') else host}:{self.port}"

    @property
    def robot(self):
        return self.scenario.robot

    # -- workspace and robot -----------------------------------------------------
    def load(self, scenario: str, seed: int) -> None:
        """Show a new workspace of ``scenario`` drawn from ``seed``; the robot starts at a valid rest pose."""
        self.panel.stop_playing()  # before taking the lock: the player's steps need it
        with self.lock:
            self.scenario, self.seed = scenarios.get(scenario), int(seed)
            rng = np.random.default_rng(self.seed)
            self.workspace = self.scenario.make_workspace(rng)
            self.exact = exact_checker(self.workspace, self.robot)
            self.model, self.model_error = self._load_model()
            for name in ("prediction", "disagreement", "samples", "roadmap", "path"):
                self._remove(name)
            self.path = None
            for layer, handle in draw.draw_workspace(self.server.scene, self.workspace).items():
                self._add(layer, handle)
            self.q = self.valid_configuration(rng, rest=True)
            self._aim_camera(*draw.camera_pose(self.robot, self.workspace, self.q))
            boxes = draw.robot_boxes(self.robot, self.q[None])
            self._add("robot", draw.add_boxes(self.server.scene, "/robot/links", boxes, draw.VALID))
            if self.model is not None:
                self._add("prediction", draw.add_boxes(self.server.scene, "/robot/prediction", boxes.scaled(HALO),
                                                       draw.VALID, wireframe=True))
                self.nodes["disagreement"] = self.server.scene.add_label(
                    "/robot/disagreement", "model disagrees", visible=False)
            self.panel.on_load()
            self.set_configuration(self.q)

    def set_configuration(self, q) -> None:
        """Move the robot to ``q (dof,)`` and recolor it by the exact checker (and the model)."""
        q = self.robot.check_configs(q, "q")[0]
        with self.lock:
            self.q = q
            boxes = draw.robot_boxes(self.robot, q[None])
            self.valid = bool(self.exact.are_valid(q[None])[0])
            draw.move_boxes(self.nodes["robot"], boxes,
                            np.broadcast_to(draw.VALID if self.valid else draw.COLLIDING, (len(boxes), 3)))
            self.probability = self.predicted_valid = None
            if self.model is not None:
                self.probability = float(self.model.probability(q[None])[0])
                self.predicted_valid = bool(self.model.are_valid(q[None])[0])
                draw.move_boxes(self.nodes["prediction"], boxes.scaled(HALO),
                                np.repeat(draw.probability_colors([self.probability]), len(boxes), axis=0))
                self.nodes["disagreement"].position = boxes.centers.max(axis=0) + np.array([0.0, 0.0, 1.0])
                self._show_disagreement()
            self.panel.on_configuration()

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
        """Mark configurations ``Q (N, dof)`` as points colored by exact vs predicted validity; returns the colors."""
        Q = self.robot.check_configs(Q)
        with self.lock:
            valid = self.exact.are_valid(Q)
            predicted = self.model.are_valid(Q) if self.model is not None else None
            colors = draw.validity_colors(valid, predicted)  # (N, 3)
            self._add("samples", self.server.scene.add_point_cloud(
                "/samples", draw.config_points(self.robot, Q, at).astype(np.float32), colors,
                point_size=draw.POINT_SIZE[self.workspace.family], point_shape="circle"))
            return colors

    def sample(self, sampler: str = "raw", n: int = 200, *, seed: int = 0, at: str = "base") -> np.ndarray:
        """Draw ``n`` attempts with ``sampler`` and show them; returns the samples ``(M, dof)``.

        ``'raw'``: uniform configurations, unfiltered (what the model is asked about);
        ``'BS'``, ``'OB'``, ``'G'``, ``'BT'``: the paper's samplers (§III-B), deciding
        validity with the model when one is loaded (Algorithm 1), else exactly.
        """
        rng = np.random.default_rng(seed)
        if sampler == "raw":
            Q = self.robot.sample(rng, n)
        else:
            Q = make_sampler(sampler, self.model or self.exact).sample(n, rng)
        self.show_samples(Q, at=at)
        return Q

    def plan(self, sampler: str = "BS", *, seed: int = 0) -> prm.PlanResult:
        """Solve a paper-style query (§IV-A: valid start and goal far apart, from ``seed``) with PRM and show it.

        With a model loaded this is Algorithm 1; the returned path is verified exactly either way.
        """
        rng = np.random.default_rng(seed)
        start, goal = queries.query_pairs(self.scenario, self.workspace, 1, rng)[0]
        result = prm.plan(self.exact, start, goal, sampler=sampler, checker=self.model,
                          options=queries.default_options(self.scenario, self.model), rng=rng)
        self.show_plan(result)
        return result

    def show_plan(self, result: prm.PlanResult, *, at: str = "base") -> None:
        """Draw a PRM result: roadmap edges as one line-segment node, the path, and move the robot to its start."""
        nodes, edges = np.asarray(result.roadmap.nodes), np.asarray(result.roadmap.edges).reshape(-1, 2)
        with self.lock:
            points = draw.config_points(self.robot, nodes, at)  # (V, 3)
            self._add("roadmap", self.server.scene.add_line_segments(
                "/plan/roadmap", draw.edge_segments(points, edges), draw.ROADMAP, thickness=1.0,
                thickness_units="screen"))
            self._remove("path")
            self.path = None
            if len(result.path) > 1:
                self.path = self.robot.check_configs(result.path, "path")
                dense = self.path_configurations(np.linspace(0.0, 1.0, 20 * len(self.path)))
                self._add("path", self.server.scene.add_line_segments(
                    "/plan/path", draw.polyline_segments(draw.config_points(self.robot, dense, at)), draw.PATH,
                    thickness=4.0, thickness_units="screen"))
                self.set_configuration(self.path[0])
            self.panel.on_plan(result)

    def path_configurations(self, t) -> np.ndarray:
        """``(T, dof)`` configurations at fractions ``t`` (T,) of the shown path's length."""
        if self.path is None:
            raise ValueError("no path is shown; plan or show_plan first")
        lengths = self.robot.distance(self.path[:-1], self.path[1:])  # (P-1,)
        ends = np.cumsum(lengths)
        at = np.clip(np.asarray(t, dtype=float).reshape(-1), 0.0, 1.0) * ends[-1]  # (T,) distance travelled
        segment = np.minimum(np.searchsorted(ends, at), len(lengths) - 1)  # (T,)
        fraction = (at - (ends[segment] - lengths[segment])) / np.maximum(lengths[segment], 1e-12)
        return np.stack([self.robot.interpolate(self.path[s], self.path[s + 1], [f])[0]
                         for s, f in zip(segment, np.clip(fraction, 0.0, 1.0))])

    # -- layers, export, shutdown --------------------------------------------------------
    def set_visible(self, layer: str, visible: bool) -> None:
        """Show or hide one of :data:`LAYERS`."""
        if layer not in LAYERS:
            raise ValueError(f"unknown layer {layer!r}; choose one of {LAYERS}")
        with self.lock:
            self.visible[layer] = bool(visible)
            if layer in self.nodes:
                self.nodes[layer].visible = bool(visible)
            if layer == "prediction" and self.model is not None:
                self._show_disagreement()

    def html(self) -> str:
        """The current scene as one self-contained HTML document (no server needed to view it)."""
        with self.lock:
            return self.server.scene.as_html()

    def iframe(self, height: int = 480) -> str:
        """The current scene as an ``<iframe>`` for ``IPython.display.HTML`` (a static snapshot)."""
        return srcdoc_iframe(self.html(), height)

    def animation_html(self, *, frames: int = 60, seconds: float = 6.0) -> str:
        """The robot moving along the shown path, as one self-contained HTML document (no server needed).

        A recording made with viser's scene serializer: the scene as it is now, then
        ``frames`` configurations evenly spaced along the path (:meth:`path_configurations`),
        ``seconds / (frames - 1)`` apart, each colored by the exact checker (and the model's
        wireframe, if one is loaded). The camera starts framing the whole motion
        (:func:`toolkit.viewer.drawing.path_camera`); the page plays the recording in a loop,
        with a timeline to pause and scrub. The robot and the camera are put back afterwards.
        """
        if frames < 2 or not seconds > 0:
            raise ValueError(f"an animation needs frames >= 2 and seconds > 0, got {frames} and {seconds}")
        configurations = self.path_configurations(np.linspace(0.0, 1.0, int(frames)))  # (F, dof)
        camera = self.server.initial_camera
        with self.lock:
            before = self.q, camera.look_at, camera.position
            self.set_configuration(configurations[0])
            camera.look_at, camera.position = draw.path_camera(self.robot, configurations)
            recording = self.server.get_scene_serializer()  # the scene now, then every scene message
            for q in configurations[1:]:
                recording.insert_sleep(seconds / (frames - 1))
                self.set_configuration(q)
            document = recording.as_html()  # stops the recording
            self.set_configuration(before[0])
            camera.look_at, camera.position = before[1:]
        return document

    def animation_iframe(self, height: int = 480, *, frames: int = 60, seconds: float = 6.0) -> str:
        """:meth:`animation_html` as an ``<iframe>`` for ``IPython.display.HTML``."""
        return srcdoc_iframe(self.animation_html(frames=frames, seconds=seconds), height)

    def stop(self) -> None:
        """Stop the GUI's player and the server; the port is free afterwards. Stopping twice is harmless."""
        if self.stopped:
            return
        self.stopped = True
        self.panel.stop_playing()
        with _viser_quiet():
            self.server.stop()

    def __enter__(self) -> "Viewer":
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    # -- internals ------------------------------------------------------------------------
    def _load_model(self) -> tuple[CollisionChecker | None, str]:
        """The predictor's checker for this workspace, or None and why it does not apply."""
        if self.predictor is None:
            return None, ""
        try:
            model = self.predictor(self.workspace)
        except (ValueError, FileNotFoundError) as err:  # e.g. a checkpoint of another scenario
            return None, str(err)
        if model.robot.name != self.robot.name:
            return None, f"the model is for robot {model.robot.name!r}, this scenario's is {self.robot.name!r}"
        return model, ""

    def _show_disagreement(self) -> None:
        self.nodes["disagreement"].visible = self.visible["prediction"] and self.predicted_valid != self.valid

    def _aim_camera(self, look_at: np.ndarray, position: np.ndarray) -> None:
        self.server.initial_camera.look_at, self.server.initial_camera.position = look_at, position
        for client in self.server.get_clients().values():
            client.camera.look_at, client.camera.position = look_at, position

    def _add(self, layer: str, handle: viser.SceneNodeHandle) -> None:
        handle.visible = self.visible.get(layer, True)
        self.nodes[layer] = handle

    def _remove(self, name: str) -> None:
        handle = self.nodes.pop(name, None)
        if handle is not None:
            handle.remove()


@contextlib.contextmanager
def _viser_quiet():
    """Silence viser's own banner and "Server stopped" (printed with rich, which comes with viser).

    In a notebook each would be an extra output naming a server that a snapshot has already stopped.
    """
    console = rich.get_console()
    quiet, console.quiet = console.quiet, True
    try:
        yield
    finally:
        console.quiet = quiet


def free_port(host: str, port: int, tries: int = 100) -> int:
    """The first port from ``port`` on that ``host`` can serve on (0: let the system choose one).

    Checked here because viser, given a port out of range or an address this computer
    does not have, waits forever; here it is a ``ValueError`` that says why.
    """
    if not 0 <= port <= 65535:
        raise ValueError(f"port must be 0..65535, got {port}")
    try:
        family, kind, proto, _, address = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)[0]
    except socket.gaierror as err:
        raise ValueError(f"cannot serve on host {host!r}: {err.strerror}") from None
    for candidate in range(port, min(port + tries, 65536)) if port else [0]:
        with socket.socket(family, kind, proto) as probe:
            probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as the server's own socket does
            try:
                probe.bind((address[0], candidate, *address[2:]))
                return candidate
            except OSError as err:
                if err.errno != errno.EADDRINUSE:
                    raise ValueError(f"cannot serve on {host}:{candidate}: {err.strerror}") from None
    raise ValueError(f"ports {port}..{min(port + tries, 65536) - 1} on {host} are all busy; choose another port")


def launch(scenario: str = "3do", *, seed: int = 0, checkpoint: str | Path | None = None,
           predictor: Predictor | None = None, host: str = "127.0.0.1", port: int = 8080,
           quiet: bool = False) -> Viewer:
    """Start a :class:`Viewer` and print the URL to open (and whether the port was busy)."""
    viewer = Viewer(scenario, seed=seed, checkpoint=checkpoint, predictor=predictor, host=host, port=port)
    if not quiet:
        busy = f" (port {port} was busy)" if port and viewer.port != port else ""
        print(f"toolkit view: {scenario} (seed {seed}) at {viewer.url}{busy} — open it in a browser; Ctrl-C stops",
              flush=True)
    return viewer


def serve_forever(viewer: Viewer) -> None:
    """Keep serving until Ctrl-C, then stop the viewer."""
    try:
        while True:
            time.sleep(0.5)
    except KeyboardInterrupt:
        pass
    finally:
        viewer.stop()


def srcdoc_iframe(document: str, height: int = 480) -> str:
    """An ``<iframe>`` holding a whole HTML ``document`` inline (``srcdoc``): it needs no server or file.

    Wrapped in a ``<div>``: ``IPython.display.HTML`` warns about markup that starts with ``<iframe``.
    """
    return (f'<div><iframe srcdoc="{html_lib.escape(document, quote=True)}" width="100%" '
            f'height="{int(height)}" style="border:none"></iframe></div>')


def embed(scenario: str = "3do", *, seed: int = 0, q=None, samples=None, height: int = 480) -> str:
    """A static snapshot of a scenario (robot at ``q``, optional ``samples (N, dof)``) as an ``<iframe>``.

    For notebooks: ``IPython.display.HTML(viewer.embed("3do"))``. A server runs on a
    free port only while the snapshot is taken; nothing opens a browser.
    """
    with Viewer(scenario, seed=seed, port=0) as viewer:
        if q is not None:
            viewer.set_configuration(q)
        if samples is not None:
            viewer.show_samples(samples)
        return viewer.iframe(height)
