"""How a scene reaches a browser: served live from a port of this computer, or inlined in a notebook's page.

A live scene is a viser server (a web server and a websocket in threads of this
process) bound to ``host:port``, by default 127.0.0.1: only this computer can open it.
:func:`start_server` finds a free port first (:func:`free_port`), so a busy or impossible
address is a clear error and not a server that waits forever; :func:`stop_server` frees
the port. A snapshot needs no server at all: :func:`srcdoc_iframe` carries a whole page,
scene included, inside one ``<iframe>``.

A live server is its owner's alone. "Only this computer" is everyone on a shared machine: on a
single-machine JupyterHub every student's jupyter-server-proxy forwards ``/proxy/PORT/`` to any
port of the machine, and viser has no login. So each server answers only under a path that is a
random secret of its launch, ``/<secret>/`` (:func:`page_path`), the one the printed address
ends in; any other request, page or websocket, gets :data:`REFUSAL` (403), which says why. The
check sits in the hook viser's web server answers through, websockets' ``process_request``:
while :func:`start_server` builds a server, :func:`_gated_serve` (in place of
``websockets.asyncio.server.serve``, which viser calls) wraps viser's handler in :func:`_gate`.
"""

from __future__ import annotations

import contextlib
import dataclasses
import errno
import hmac
import html as html_lib
import http
import secrets
import socket
import threading
import weakref
from collections.abc import Callable, Iterator

import rich
import viser
import websockets.asyncio.server
from websockets.datastructures import Headers
from websockets.http11 import Request, Response

LABEL = "Predicting sample collision"  # the page's title
SECRET_BYTES = 16  # a launch's secret: 128 random bits, 22 URL-safe characters
REFUSAL = """<!doctype html><html lang="en"><head><meta charset="utf-8"><title>Not this viewer's address</title></head>
<body><h1>Not this viewer's address</h1>
<p>A viewer opens only at the whole address <code>toolkit view</code> printed when it started: it ends in a secret
of that launch, <code>http://127.0.0.1:PORT/<i>secret</i>/</code> or, on a JupyterHub,
<code>&hellip;/proxy/PORT/<i>secret</i>/</code>. Copy that whole address from where it was printed.</p>
<p>If you did not start a viewer on this port, it is someone else's, and stays theirs. Start your own with
<code>python -m toolkit view</code> (it takes a free port and prints its address).</p></body></html>
"""

_original_serve = websockets.asyncio.server.serve
_secrets: weakref.WeakKeyDictionary[viser.ViserServer, str] = weakref.WeakKeyDictionary()
_starting = threading.Lock()  # one server is built at a time: its secret is the one _gated_serve reads
_secret_of_start: str | None = None  # the secret of the server being built, while it is


def start_server(host: str = "127.0.0.1", port: int = 8080) -> viser.ViserServer:
    """A viser server on ``host`` and the first free port from ``port`` (0: any free port), answering only under
    :func:`page_path`."""
    global _secret_of_start
    with _starting:
        port = free_port(host, port)
        # viser's one hook (the module's docstring); any other server passes through _gated_serve unchanged
        websockets.asyncio.server.serve = _gated_serve  # type: ignore[misc,assignment]
        _secret_of_start = secrets.token_urlsafe(SECRET_BYTES)
        try:
            with _viser_quiet():  # launch() prints the one line a user needs
                server = viser.ViserServer(host=host, port=port, label=LABEL, verbose=False)
            _secrets[server] = _secret_of_start
        finally:
            _secret_of_start = None
    return server


def page_path(server: viser.ViserServer) -> str:
    """The path ``server`` answers under, ``/<secret>/``: its page's address is ``http://host:port`` followed by it."""
    return f"/{_secrets[server]}/"


def stop_server(server: viser.ViserServer) -> None:
    """Stop ``server``; its port is free afterwards."""
    with _viser_quiet():
        server.stop()


def _gated_serve(*args, **kwargs):
    """``websockets.asyncio.server.serve``; while :func:`start_server` builds a server, with its request handler
    behind :func:`_gate`."""
    if _secret_of_start is not None:
        kwargs["process_request"] = _gate(kwargs.get("process_request"), _secret_of_start)
    return _original_serve(*args, **kwargs)


Handler = Callable[[websockets.asyncio.server.ServerConnection, Request], Response | None]


def _gate(handler: Handler | None, secret: str) -> Handler:
    """``handler`` (viser's: its page, or None to go on to the websocket) for a request whose path starts with
    ``/<secret>``, seen without that prefix; :data:`REFUSAL` for any other."""

    def gate(connection: websockets.asyncio.server.ServerConnection, request: Request) -> Response | None:
        first, _, rest = request.path.removeprefix("/").partition("/")
        first = first.partition("?")[0]
        if not hmac.compare_digest(first.encode(), secret.encode()):
            body = REFUSAL.encode()
            headers = Headers(
                [
                    ("Content-Type", "text/html; charset=utf-8"),
                    ("Content-Length", str(len(body))),
                    ("Cache-Control", "no-store"),
                ]
            )
            return Response(http.HTTPStatus.FORBIDDEN, "Forbidden", headers, body)
        inner = dataclasses.replace(request, path="/" + rest)
        return None if handler is None else handler(connection, inner)

    return gate


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
