"""How a scene reaches a browser: served live from a port of this computer, or inlined in a notebook's page.

A live scene is a viser server (a web server and a websocket in threads of this
process) bound to ``host:port``, by default 127.0.0.1: only this computer can open it.
:func:`start_server` finds a free port first (:func:`free_port`), so a busy or impossible
address is a clear error and not a server that waits forever; :func:`stop_server` frees
the port. A snapshot needs no server at all: :func:`srcdoc_iframe` carries a whole page,
scene included, inside one ``<iframe>``.
"""

from __future__ import annotations

import contextlib
import errno
import html as html_lib
import socket
from collections.abc import Iterator

import rich
import viser

LABEL = "Predicting sample collision"  # the page's title


def start_server(host: str = "127.0.0.1", port: int = 8080) -> viser.ViserServer:
    """A viser server on ``host`` and the first free port from ``port`` (0: any free port)."""
    port = free_port(host, port)
    with _viser_quiet():  # launch() prints the one line a user needs
        return viser.ViserServer(host=host, port=port, label=LABEL, verbose=False)


def stop_server(server: viser.ViserServer) -> None:
    """Stop ``server``; its port is free afterwards."""
    with _viser_quiet():
        server.stop()


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


@contextlib.contextmanager
def camera_at(server: viser.ViserServer, look_at, position) -> Iterator[None]:
    """The server's initial camera at ``position``, looking at ``look_at`` (3,) each, while the block runs (a page
    serialized meanwhile starts there), then back where it was."""
    camera = server.initial_camera
    before = camera.look_at, camera.position
    camera.position, camera.look_at = position, look_at  # viser moves what it looks at with the position: that last
    try:
        yield
    finally:
        camera.position, camera.look_at = before[1], before[0]


def srcdoc_iframe(document: str, height: int = 480, *, summary: str = "3D scene") -> str:
    """An ``<iframe>`` holding a whole HTML ``document`` inline (``srcdoc``): it needs no server or file.

    Titled by the first sentence of ``summary`` and followed by all of it (the text alternative of the scene);
    wrapped in a ``<div>``: ``IPython.display.HTML`` warns about markup that starts with ``<iframe``.
    """
    title = html_lib.escape(summary.split(". ")[0].rstrip("."), quote=True)
    return (
        f'<div><iframe srcdoc="{html_lib.escape(document, quote=True)}" width="100%" '
        f'height="{int(height)}" style="border:none" title="{title}"></iframe>'
        f'<p class="scene-summary">{html_lib.escape(summary)}</p></div>'
    )
