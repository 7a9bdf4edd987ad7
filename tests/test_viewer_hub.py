"""The viewer on a JupyterHub: the address it prints, the link and frame in a notebook, and a real proxied page.

(conftest.py removes the hub's variables from the tests' environment; a test sets those it plays.)

A hub's student reaches a port of their server only through jupyter-server-proxy, at
``<base URL>proxy/PORT/``, and so does every other student of a single-machine hub: the
address carries the launch's secret, and the viewer refuses any other. The last test starts
two users' real Jupyter servers with base URLs and jupyter-server-proxy, a ``toolkit view`` in
each with the environment JupyterHub gives a user's server, and has Chromium open the first's
printed address through its Jupyter server (the scene draws) and what the second can reach of
it through theirs (refused).
"""

import asyncio
import os
import re
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

import nbformat
import pytest
import viser
import websockets
from nbclient import NotebookClient
from websockets.typing import Subprotocol

from toolkit import viewer
from toolkit.viewer import address
from toolkit.viewer import browser as viewer_browser
from toolkit.viewer.server import REFUSAL, page_path


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.parametrize(
    "given, environ, expected",
    [
        (None, {}, None),  # a laptop: the port itself
        (None, {"JUPYTERHUB_SERVICE_PREFIX": "/user/student/"}, "/user/student/"),
        (  # a hub with subdomains: its host before the prefix
            None,
            {"JUPYTERHUB_SERVICE_PREFIX": "/user/ana/", "JUPYTERHUB_HOST": "https://ana.hub.org"},
            "https://ana.hub.org/user/ana/",
        ),
        (
            None,
            {"JUPYTERHUB_SERVICE_PREFIX": "/user/ana/", "JUPYTERHUB_PUBLIC_URL": "https://hub.org/user/ana/"},
            "https://hub.org/user/ana/",
        ),
        (None, {"JUPYTERHUB_SERVICE_PREFIX": "/user/ana/", "TOOLKIT_VIEWER_BASE_URL": "/lab-base"}, "/lab-base/"),
        ("/mine/", {"JUPYTERHUB_SERVICE_PREFIX": "/user/ana/", "TOOLKIT_VIEWER_BASE_URL": "/lab-base"}, "/mine/"),
    ],
)
def test_the_base_url_comes_from_the_argument_then_the_environment(given, environ, expected):
    assert address.base_url(given, environ) == expected


def test_the_proxied_address():
    assert address.proxied(8081, "/user/student/") == "/user/student/proxy/8081/"
    assert (
        address.proxied(8081, "https://hub.org/user/ana/", "/s3cret/") == "https://hub.org/user/ana/proxy/8081/s3cret/"
    )


@pytest.mark.parametrize("bad", ["hub.org/user/ana/", "user/ana", "ftp://hub.org/", "//hub.org/x", "/a b/", "/x?y=1"])
def test_a_malformed_base_url_is_an_error_naming_it_and_where_it_came_from(bad):
    with pytest.raises(ValueError, match=re.escape(f"the base URL {bad!r} is malformed")):
        address.base_url(bad, {})
    with pytest.raises(ValueError, match=re.escape(f"$JUPYTERHUB_PUBLIC_URL {bad!r} is malformed")):
        address.base_url(None, {"JUPYTERHUB_PUBLIC_URL": bad})


def test_launch_prints_the_proxied_address_of_the_port_it_got(monkeypatch, capsys):
    monkeypatch.setenv("JUPYTERHUB_SERVICE_PREFIX", "/user/student/")
    v = viewer.launch("2ds", port=0)  # any free port (a busy one moves on: test_viewer.py)
    try:
        secret = page_path(v.server)
        assert re.fullmatch(r"/[A-Za-z0-9_-]{22}/", secret)  # 128 random bits
        assert f"at /user/student/proxy/{v.port}{secret} — open it" in capsys.readouterr().out
        assert v.url == f"http://127.0.0.1:{v.port}{secret}"  # the server itself is where it was
    finally:
        v.stop()


def _get(url: str) -> tuple[int, str]:
    try:
        with urllib.request.urlopen(url, timeout=30) as page:
            return page.status, page.read().decode()
    except urllib.error.HTTPError as refused:
        return refused.code, refused.read().decode()


async def _first_message(url: str) -> str:
    """What a websocket client at ``url`` gets first: viser's first message, or the refusal of the handshake (or its
    closing)."""
    try:
        async with websockets.connect(url, subprotocols=[Subprotocol(f"viser-v{viser.__version__}")]) as socket_:
            return f"a message of {len(await asyncio.wait_for(socket_.recv(), 30))} bytes"
    except websockets.InvalidStatus as refused:
        return f"refused: {refused.response.status_code}"
    except websockets.ConnectionClosed:  # jupyter-server-proxy accepts, then closes when the viewer refuses it
        return "closed before any message"


def test_each_launch_serves_its_page_and_websocket_only_under_its_own_secret():
    first, second = viewer.Viewer("2ds", port=0), viewer.Viewer("2ds", port=0)
    try:
        assert page_path(first.server) != page_path(second.server)
        status, page = _get(first.url)
        assert status == 200 and "<html" in page.lower()
        root = f"http://127.0.0.1:{first.port}"
        guesses = ["/", "/index.html", page_path(second.server), page_path(first.server)[:-2] + "/", "/x/../"]
        for guess in guesses:
            assert _get(root + guess) == (403, REFUSAL), guess
        assert "toolkit view" in REFUSAL and "someone else's" in REFUSAL  # it says why, and what to do
        ws = first.url.replace("http://", "ws://")
        assert asyncio.run(_first_message(ws.rstrip("/"))).startswith("a message of")  # as viser's client connects
        assert asyncio.run(_first_message(f"ws://127.0.0.1:{first.port}")) == "refused: 403"
        assert asyncio.run(_first_message(f"ws://127.0.0.1:{first.port}{page_path(second.server)}")) == "refused: 403"
    finally:
        first.stop()
        second.stop()


def test_launch_refuses_a_malformed_base_url_before_serving(monkeypatch, capsys):
    monkeypatch.setenv(address.BASE_URL_VARIABLE, "hub.org/user/ana")
    with pytest.raises(ValueError, match=r"\$TOOLKIT_VIEWER_BASE_URL 'hub.org/user/ana' is malformed"):
        viewer.launch("2ds", port=0)
    assert capsys.readouterr().out == ""


def test_toolkit_view_names_a_malformed_base_url():
    done = subprocess.run(
        [sys.executable, "-m", "toolkit", "view", "--base-url", "www.hub.org/user/x/", "--port", "0"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 2
    assert "the base URL 'www.hub.org/user/x/' is malformed: give a path such as /user/student/" in done.stderr


def test_a_notebook_on_a_hub_shows_a_link_and_a_frame_and_locally_only_the_address():
    cell = (
        "from toolkit import viewer\nfrom toolkit.viewer.server import page_path\n"
        'v = viewer.launch("2ds", port=0, base_url={base!r})\nprint(v.port, page_path(v.server))\nv.stop()'
    )
    notebook = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell(cell.format(base=base)) for base in ("/user/student/", None)]
    )
    NotebookClient(notebook, timeout=300, kernel_name="python3").execute()
    hub, local = (list(cell.outputs) for cell in notebook.cells)
    port, secret = "".join(o.get("text", "") for o in hub).split()[-2:]
    frames = [o["data"]["text/html"] for o in hub if o.output_type == "display_data"]
    url = f"/user/student/proxy/{port}{secret}"
    assert frames == [address.link_and_frame(url)]
    assert f'<iframe src="{url}"' in frames[0] and f'href="{url}"' in frames[0]
    assert all(o.output_type == "stream" for o in local)  # locally: the printed line only
    assert "at http://127.0.0.1:" in "".join(o.text for o in local)
    assert "the viewer's stop() stops it" in "".join(o.text for o in local)  # no Ctrl-C in a notebook


def wait_for(url: str, server: subprocess.Popen, log: Path, budget_s: float = 120.0) -> None:
    """Until ``url`` answers 200: the ``server`` writing ``log`` has started."""
    deadline = time.monotonic() + budget_s
    while True:
        try:
            with urllib.request.urlopen(url, timeout=5) as page:
                if page.status == 200:
                    return
        except OSError:
            assert server.poll() is None and time.monotonic() < deadline, log.read_text()
        time.sleep(0.5)


def start(command: list[str], env: dict[str, str], log: Path) -> subprocess.Popen:
    with log.open("w") as out:
        return subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, env=env, text=True)


def jupyter_server(user: str, tmp_path: Path) -> tuple[subprocess.Popen, str]:
    """A user's Jupyter server with jupyter-server-proxy, as a hub starts it (base URL ``/user/<user>/``, no token:
    the hub's login stands before it); it and its root address ``http://127.0.0.1:PORT``."""
    port = free_port()
    (tmp_path / user).mkdir()
    server = start(
        [sys.executable, "-m", "jupyter_server", f"--port={port}", "--ServerApp.ip=127.0.0.1"]
        + [
            f"--ServerApp.base_url=/user/{user}/",
            "--IdentityProvider.token=",
            f"--ServerApp.root_dir={tmp_path / user}",
        ]
        + ["--ServerApp.open_browser=False", "--ServerApp.allow_root=True"],  # CI runs as root
        dict(os.environ),
        tmp_path / f"jupyter-{user}.log",
    )
    return server, f"http://127.0.0.1:{port}"


def toolkit_view(user: str, root: str, tmp_path: Path) -> tuple[subprocess.Popen, str]:
    """``toolkit view`` started in ``user``'s server (the environment JupyterHub gives it); it and the address it
    printed."""
    log = tmp_path / f"view-{user}.log"
    hub_env = dict(os.environ, JUPYTERHUB_SERVICE_PREFIX=f"/user/{user}/", JUPYTERHUB_PUBLIC_URL=f"{root}/user/{user}/")
    view = start([sys.executable, "-m", "toolkit", "view", "--scenario", "3do"], hub_env, log)
    deadline = time.monotonic() + 300
    while not (printed := re.search(r" at (\S+)", log.read_text())):
        assert view.poll() is None and time.monotonic() < deadline, log.read_text()
        time.sleep(0.5)
    return view, printed.group(1)


def in_chromium(url: str) -> tuple[int, str]:
    """What Chromium gets at ``url``: the status and the page's text."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=viewer_browser.find_chromium(), args=viewer_browser.CHROMIUM_ARGS
        )
        page = browser.new_page()
        response = page.goto(url, timeout=120_000)
        assert response is not None
        return response.status, page.inner_text("body")


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.skipif(viewer_browser.find_chromium() is None, reason="no Chromium installed (run `make browser`)")
def test_on_a_shared_machine_a_student_opens_their_own_viewer_and_not_anothers(tmp_path):
    """Two students' servers on one machine, as on a single-machine hub: each one's jupyter-server-proxy forwards
    ``/proxy/PORT/`` to any port of the machine, the other's viewer's too. The owner's printed address draws the
    scene (through the proxy, websocket included); what the other student can reach of it is refused, in words."""
    pytest.importorskip("jupyter_server_proxy", reason="jupyter-server-proxy is in the dev and hub extras")
    processes = []
    try:
        (jupyter, root), (jupyter2, root2) = (jupyter_server(user, tmp_path) for user in ("student", "student2"))
        processes += [jupyter, jupyter2]
        (view, url), (view2, url2) = (toolkit_view(u, r, tmp_path) for u, r in (("student", root), ("student2", root2)))
        processes += [view, view2]
        for user, server, base in (("student", jupyter, root), ("student2", jupyter2, root2)):
            wait_for(f"{base}/user/{user}/api/status", server, tmp_path / f"jupyter-{user}.log")
        port, secret = re.fullmatch(rf"{root}/user/student/proxy/(\d+)(/[A-Za-z0-9_-]{{22}}/)", url).groups()
        port2, secret2 = re.fullmatch(rf"{root2}/user/student2/proxy/(\d+)(/[A-Za-z0-9_-]{{22}}/)", url2).groups()
        assert port != port2 and secret != secret2
        for theirs in (f"{root2}/user/student2/proxy/{port}/", f"{root2}/user/student2/proxy/{port}{secret2}"):
            status, text = in_chromium(theirs)  # student2 at student's port: bare, or with their own secret
            assert status == 403 and "Not this viewer's address" in text and "someone else's" in text, (theirs, text)
        refused = asyncio.run(_first_message(f"ws://127.0.0.1:{root2.rsplit(':', 1)[1]}/user/student2/proxy/{port}"))
        assert refused == "closed before any message", refused  # nor its websocket
        viewer_browser.screenshot(url, tmp_path / "hub.png", size=(1100, 700))  # the obstacles: the websocket is up
        assert _get(url2)[0] == 200  # and student2's own viewer is theirs
    finally:
        for process in reversed(processes):
            process.terminate()
            process.wait(timeout=30)
