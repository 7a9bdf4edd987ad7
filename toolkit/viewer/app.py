"""Starting a viewer: the live one with its GUI panel (``toolkit view``), or a one-off snapshot for a notebook.

:func:`launch` builds the two halves and joins them: a :class:`~toolkit.viewer.scene.Viewer`
(the scene) and a :class:`~toolkit.viewer.panel.Panel` that listens to it. This is the one
module that knows both; the scene never imports the panel. :func:`serve_forever` keeps the
process serving until Ctrl-C. :func:`embed` takes a snapshot with no panel and no server
left behind.
"""

from __future__ import annotations

import time
from pathlib import Path

from toolkit.scenarios import Scenario
from toolkit.viewer import address
from toolkit.viewer.labels import named_live_page
from toolkit.viewer.models import Predictor
from toolkit.viewer.panel import Panel
from toolkit.viewer.scene import Viewer
from toolkit.viewer.server import page_path


def launch(
    scenario: str | Scenario = "3do",
    *,
    seed: int = 0,
    checkpoint: str | Path | None = None,
    predictor: Predictor | None = None,
    host: str = "127.0.0.1",
    port: int = 8080,
    base_url: str | None = None,
    quiet: bool = False,
) -> Viewer:
    """Start a :class:`Viewer` with its GUI panel and print the URL to open (and whether the port was busy): it ends
    in the launch's secret (:func:`toolkit.viewer.server.page_path`), without which the viewer refuses a browser.

    Behind a Jupyter server (``base_url``, else the environment's: :func:`toolkit.viewer.address.base_url`) that URL
    is the port's path through jupyter-server-proxy, and in a notebook a link and an inline frame to it are shown.
    """
    base = address.base_url(base_url)  # a malformed one is an error before anything is served
    with named_live_page():  # viser's page with its controls named for screen readers (labels.py)
        viewer = Viewer(scenario, seed=seed, checkpoint=checkpoint, predictor=predictor, host=host, port=port)
    try:
        Panel(viewer)  # it subscribes to the viewer's events: the viewer keeps it
    except BaseException:
        viewer.stop()
        raise
    if not quiet:
        url = address.proxied(viewer.port, base, page_path(viewer.server)) if base else viewer.url
        busy = f" (port {port} was busy)" if port and viewer.port != port else ""
        stops = "the viewer's stop() stops it" if _in_notebook() else "Ctrl-C stops"
        print(f"toolkit view: {scenario} (seed {seed}) at {url}{busy} — open it in a browser; {stops}", flush=True)
        if base and _in_notebook():
            from IPython.display import HTML, display

            display(HTML(address.link_and_frame(url)))  # a link, and the viewer in an inline frame
    return viewer


def _in_notebook() -> bool:
    """Whether this runs in a notebook's kernel (not a terminal)."""
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    return getattr(get_ipython(), "kernel", None) is not None


def serve_forever(viewer: Viewer) -> None:
    """Keep serving until Ctrl-C, then stop the viewer."""
    try:
        while True:
            time.sleep(0.5)
    except KeyboardInterrupt:
        pass
    finally:
        viewer.stop()


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
