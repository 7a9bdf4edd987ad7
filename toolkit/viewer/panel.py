"""The viewer's GUI panel: scenario and seed, one slider per DoF, samples, plan player, layers.

The panel is a listener of a :class:`~toolkit.viewer.scene.Viewer`: it subscribes to the
viewer's events (:data:`~toolkit.viewer.scene.EVENTS`) and follows them: a new workspace
rebuilds the sliders, a move updates them and the status line (exact validity, §III, and
the model's verdict), a plan readies the path player. The viewer does not know the panel.
Every control calls a public method of the viewer, so whatever the panel does a script
can do too. Errors in a callback are shown in the panel's status line instead of
vanishing in viser's worker threads.

The sampler dropdowns offer the samplers registered when the panel is built
(:data:`toolkit.planning.sampling.SAMPLERS`: the paper's four, §III-B, then any given to
``register_sampler``, in that order), so a sampler of your own can be picked, and planned
with, like the paper's.
"""

from __future__ import annotations

import colorsys
import threading
from collections.abc import Callable

import numpy as np

from toolkit import scenarios
from toolkit.planning import sampling
from toolkit.plots.palette import COLORS
from toolkit.viewer.scene import RAW, Viewer

PLAY_SECONDS = 8.0  # a whole path plays in this time
PLAY_FPS = 20

SAMPLE_LEGEND = "Samples: **circles** valid, **diamonds** in collision, **sparkles** where the model is wrong."
LIVE = "<span data-live-status hidden></span>"  # a status line's mark: the page announces its changes (labels.py)
WORDS = "<span data-scene-words hidden></span>"  # the scene in words' mark: it describes the 3D view (labels.py)


class Panel:
    """Builds the GUI of ``viewer``, shows its current state and follows its events from then on."""

    def __init__(self, viewer: Viewer):
        self.viewer = viewer
        self._syncing = False  # set while the panel writes slider values itself
        self._player: threading.Thread | None = None
        self._stop_playing = threading.Event()
        with viewer.lock:  # no event slips between building the controls and subscribing
            self._build(viewer.server.gui)
            self.on_load()
            self.along.disabled = viewer.path is None  # a path planned before the panel came can be played
            self.on_configuration()
            for event, callback in (
                ("loading", self.stop_playing),
                ("loaded", self.on_load),
                ("moved", self.on_configuration),
                ("sampled", self.on_scene),
                ("planned", self.on_plan),
                ("stopping", self.stop_playing),
            ):
                viewer.subscribe(event, callback)

    def _build(self, gui) -> None:
        """The controls, in the panel's order, each wired to a public method of the viewer."""
        viewer = self.viewer
        # no share button (it would publish the scene through viser's servers); buttons, sliders and the focus ring
        # in the palette's dark blue: white text on it at 5.2:1, the sliders and ring 5.2:1 on white
        gui.configure_theme(show_share_button=False, brand_color=brand_color(COLORS["path"]))
        planners = sampler_choices()

        with gui.add_folder("Workspace"):
            self.scenario = gui.add_dropdown("scenario", sorted(scenarios.SCENARIOS))
            self.seed = gui.add_number("seed", 0, min=0, step=1)
            self.new_workspace = gui.add_button("new workspace", hint="next seed")
        self.status = gui.add_markdown("")
        self.configuration = gui.add_folder("Configuration")
        self.sliders: list = []
        with gui.add_folder("Samples"):
            self.sampler = gui.add_dropdown("sampler", (RAW,) + planners, initial_value=RAW)
            self.n_samples = gui.add_number("attempts", 500, min=1, max=20000, step=1)
            self.mark = gui.add_dropdown("mark at", ("base", "tip"))
            self.sample = gui.add_button("sample")
            gui.add_markdown(SAMPLE_LEGEND)
        with gui.add_folder("Plan"):
            self.planner_sampler = gui.add_dropdown("PRM sampler", planners)
            self.plan = gui.add_button("plan (PRM)", hint="a new start / goal query")
            self.plan_status = gui.add_markdown("")
            self.play = gui.add_button("play / pause")
            self.along = gui.add_slider("along path", 0.0, 1.0, 0.001, 0.0, disabled=True)
        with gui.add_folder("Layers", expand_by_default=False):
            self.layers = {layer: gui.add_checkbox(layer, True) for layer in viewer.visible}
        with gui.add_folder("The scene in words", expand_by_default=False):
            self.words = gui.add_markdown("")  # the 3D view's description (the page's script points it there)

        self.scenario.on_update(self._guarded(self._reload))
        self.seed.on_update(self._guarded(self._reload))
        self.new_workspace.on_click(self._guarded(lambda _: setattr(self.seed, "value", int(self.seed.value) + 1)))
        self.sample.on_click(
            self._guarded(
                lambda _: viewer.sample(
                    self.sampler.value, int(self.n_samples.value), seed=self._next_seed(), at=self.mark.value
                )
            )
        )
        self.plan.on_click(self._guarded(self._plan))
        self.play.on_click(self._guarded(lambda _: self.toggle_play()))
        self.along.on_update(self._guarded(lambda _: self._follow_path()))
        for layer, box in self.layers.items():
            box.on_update(self._guarded(lambda event, layer=layer: viewer.set_visible(layer, event.target.value)))

    # -- what the panel does on the viewer's events ------------------------------------
    def on_load(self) -> None:
        """A new workspace: sync the scenario / seed inputs and rebuild one slider per DoF."""
        viewer = self.viewer
        self._rng = np.random.default_rng(viewer.seed)  # each press of "random", "sample", "plan" draws anew
        self._syncing = True
        self.scenario.value, self.seed.value = viewer.scenario.name, viewer.seed
        self.configuration.remove()
        gui, robot = viewer.server.gui, viewer.robot
        self.configuration = gui.add_folder("Configuration", order=self.status.order + 0.5)
        with self.configuration:
            self.sliders = [
                gui.add_slider(name, float(lo), float(hi), _step(lo, hi), float(lo), marks=_ends(lo, hi))
                for name, lo, hi in zip(robot.dof_names, robot.lower, robot.upper)
            ]
            self.random = gui.add_button("random valid configuration")
        for slider in self.sliders:
            slider.precision = max(0, round(-np.log10(slider.step)))  # viser's covered its ends': 2.51284 for a yaw
            slider.on_update(self._guarded(lambda _: self._follow_sliders()))
        self.random.on_click(self._guarded(lambda _: viewer.set_configuration(viewer.valid_configuration(self._rng))))
        self.along.value, self.along.disabled = 0.0, True
        self._syncing = False

    def on_configuration(self) -> None:
        """The robot moved: sliders and status line follow."""
        viewer = self.viewer
        self._syncing = True
        for slider, value in zip(self.sliders, viewer.q):
            slider.value = float(value)
        self._syncing = False
        text = f"**{viewer.scenario.title}**, seed {viewer.seed} — exact: " + (
            "**valid**" if viewer.valid else "**in collision**"
        )
        if viewer.probability is not None:
            verdict = "agrees" if viewer.predicted_valid == viewer.valid else "**disagrees**"
            text += f"; model: p(valid) = {viewer.probability:.2f}, {verdict}"
        elif viewer.model_error:
            text += f"; model not used: {viewer.model_error}"
        self.status.content = text + LIVE
        self.on_scene()

    def on_scene(self) -> None:
        """What the 3D view shows changed: its description follows (:meth:`Viewer.summary`, from the scene's data)."""
        self.words.content = self.viewer.summary() + WORDS

    def on_plan(self, result) -> None:
        """A plan is shown: report it and ready the path slider."""
        stats = result.stats
        self.plan_status.content = (
            f"{'path of ' + str(len(result.path)) + ' nodes' if result.success else '**no path found**'}; "
            f"roadmap {len(result.roadmap.nodes)} nodes, {stats.get('rounds', '?')} rounds, "
            f"{stats.get('total_s', 0.0):.2f} s{LIVE}"
        )
        self._syncing = True
        self.along.value, self.along.disabled = 0.0, self.viewer.path is None
        self._syncing = False
        self.on_scene()

    def show_error(self, err: Exception) -> None:
        """Show ``err`` in the status line."""
        self.status.content = f"**error:** {err}{LIVE}"

    # -- path player --------------------------------------------------------------------
    def toggle_play(self) -> None:
        """Play the robot along the path from the slider's place, or pause it."""
        if self.playing:
            self.stop_playing()
            return
        if self.viewer.path is None:
            raise ValueError("no path to play: press 'plan (PRM)' first")
        self._stop_playing.clear()
        self._player = threading.Thread(target=self._play, daemon=True)
        self._player.start()

    @property
    def playing(self) -> bool:
        """Whether the robot is moving along the path."""
        return self._player is not None and self._player.is_alive()

    def stop_playing(self) -> None:
        """Pause the player and wait for it (the viewer's ``loading`` and ``stopping`` events call this)."""
        self._stop_playing.set()
        if self._player is not None and self._player is not threading.current_thread():
            self._player.join()
        self._player = None

    def _play(self) -> None:
        step = 1.0 / (PLAY_SECONDS * PLAY_FPS)
        start = 0.0 if self.along.value >= 1.0 else float(self.along.value)
        for t in np.arange(start + step, 1.0 + step, step):
            if self._stop_playing.wait(1.0 / PLAY_FPS):
                return
            self.along.value = float(min(t, 1.0))

    # -- callbacks -----------------------------------------------------------------------
    def _plan(self, _event) -> None:
        self.plan_status.content = "planning…" + LIVE
        self.viewer.plan(self.planner_sampler.value, seed=self._next_seed())

    def _next_seed(self) -> int:
        return int(self._rng.integers(2**31))

    def _reload(self, _event) -> None:
        if not self._syncing:
            self.viewer.load(self.scenario.value, int(self.seed.value))

    def _follow_sliders(self) -> None:
        if not self._syncing:
            self.viewer.set_configuration(np.array([slider.value for slider in self.sliders]))

    def _follow_path(self) -> None:
        if not self._syncing and self.viewer.path is not None:
            self.viewer.set_configuration(self.viewer.path_configurations([self.along.value])[0])

    def _guarded(self, callback: Callable) -> Callable:
        """``callback`` with any error shown in the status line."""

        def run(event) -> None:
            try:
                callback(event)
            except Exception as err:
                self.show_error(err)

        return run


def sampler_choices() -> tuple[str, ...]:
    """The names of the samplers registered now: the paper's four first, then the registered ones (the registry
    keeps the order names were added in)."""
    return tuple(sampling.SAMPLERS)


def brand_color(color: str) -> tuple[int, int, int]:
    """The brand colour to give viser for its controls to draw ``color`` (``#rrggbb``).

    viser makes ten shades of the colour it is given, from lightness 0.9 (shade 0) to the colour's own (shade 8),
    and its light theme draws shade 6 (Mantine's primary shade): given ``color`` itself, the sliders and the focus
    ring came out lighter (#009ff8 for the palette's blue, 2.9:1 on white). This is the colour, same hue and
    saturation, whose shade 6 is ``color``."""
    hue, lightness, saturation = colorsys.rgb_to_hls(*(int(color[i : i + 2], 16) / 255 for i in (1, 3, 5)))
    given = 0.9 - (0.9 - lightness) * 8 / 6  # shade 6 lies 6/8 of the way from 0.9 to the given lightness
    return tuple(round(channel * 255) for channel in colorsys.hls_to_rgb(hue, given, saturation))  # type: ignore[return-value]


def _step(lo: float, hi: float) -> float:
    """A DoF slider's step: the power of ten under 1/500 of its range (0.01 for the youBot's), the decimals its number
    box shows (a step of 0.0126 and the ends' 3.141593 filled the yaw's box with 2.51284, cut off)."""
    return float(10 ** np.floor(np.log10((hi - lo) / 500)))


def _ends(lo: float, hi: float) -> tuple[tuple[float, str], ...]:
    """A DoF slider's end marks, labelled with two decimals (viser's labelled the yaw's -3.141593 and 3.141593)."""
    return tuple((float(v), f"{v:.2f}".rstrip("0").rstrip(".")) for v in (lo, hi))
