"""The Viser viewer: a scenario's workspace, robot, samples, roadmap and path in a browser.

::

    from toolkit import viewer
    v = viewer.launch("3do", seed=0)          # the scene and its GUI panel; prints the URL to open
    v.set_configuration(v.robot.lower)        # move the robot; colors follow the checker
    v.stop()                                  # frees the port

The printed URL ends in a random secret of the launch, without which the viewer refuses a browser
(:mod:`toolkit.viewer.server`): on a shared machine no one else opens it. On a JupyterHub it is the port's
path through the hub, ``/user/<name>/proxy/PORT/<secret>/`` (:mod:`toolkit.viewer.address`), and a notebook
shows a link and an inline frame to it.

The robot's link boxes are colored by the exact checker (the palette's valid and
invalid colours, §III; the panel says which in words). With a learned model (``checkpoint=``
from ``toolkit train``) a wireframe around them shows its predicted probability of validity and a
label marks disagreements; samples are colored by exact validity and shaped by kind (circles valid,
diamonds in collision, sparkles where the model is wrong). Planning runs the default
planner, the lazy PRM (``toolkit.planning.prm.DEFAULT``), on a query built by
:func:`toolkit.experiments.problems.build`; with a model, the model decides samples and the
planner stays the same. For a notebook, :meth:`Viewer.iframe` and :func:`embed` give a static snapshot and
:meth:`Viewer.animation_iframe` the robot moving along the planned path, each a self-contained
page that needs no server.

Reading order (each module imports only those above it):

1. :mod:`toolkit.viewer.drawing` — workspaces, robots, samples and paths as Viser meshes and lines;
2. :mod:`toolkit.viewer.framing` — where the camera stands: the workspace, a moving robot, the clearest view of it;
3. :mod:`toolkit.viewer.server` — how a scene reaches a browser: a server on a free port under a secret path, or a
   page inline;
4. :mod:`toolkit.viewer.address` — where a student opens it: the port, or its path through a JupyterHub;
5. :mod:`toolkit.viewer.labels` — names for a saved scene's player controls, for screen readers;
6. :mod:`toolkit.viewer.models` — which learned model a scene shows, and why one is refused;
7. :mod:`toolkit.viewer.snapshot` — a scene on a page without a server: snapshot, animation, a still for no WebGL;
8. :mod:`toolkit.viewer.scene` — :class:`Viewer`: the live scene, and the events it tells its listeners;
9. :mod:`toolkit.viewer.panel` — the GUI panel, one listener: joint sliders, samplers, planning, playback;
10. :mod:`toolkit.viewer.app` — :func:`launch` (the scene with its panel), :func:`serve_forever`, :func:`embed`;
11. :mod:`toolkit.viewer.browser` — the page in headless Chromium: screenshots, what they show.
"""

from toolkit.viewer.app import embed, launch, serve_forever
from toolkit.viewer.panel import Panel
from toolkit.viewer.scene import EVENTS, Viewer
from toolkit.viewer.server import free_port, srcdoc_iframe

__all__ = ["EVENTS", "Panel", "Viewer", "embed", "free_port", "launch", "serve_forever", "srcdoc_iframe"]
