"""The viewer on a JupyterHub: the address it prints, the link and frame in a notebook, and a real proxied page.

(conftest.py removes the hub's variables from the tests' environment; a test sets those it plays.)

A hub's student reaches a port of their server only through jupyter-server-proxy, at
``<base URL>proxy/PORT/``. The last test starts a real Jupyter server with a base URL and
jupyter-server-proxy, starts ``toolkit view`` with the environment JupyterHub gives a
user's server, and has Chromium open the printed address through that Jupyter server.
"""

import os
import re
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import nbformat
import pytest
from nbclient import NotebookClient

from toolkit import viewer
from toolkit.viewer import address
from toolkit.viewer import browser as viewer_browser


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
    assert address.proxied(8081, "https://hub.org/user/ana/") == "https://hub.org/user/ana/proxy/8081/"


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
        assert f"at /user/student/proxy/{v.port}/ — open it" in capsys.readouterr().out
        assert v.url == f"http://127.0.0.1:{v.port}"  # the server itself is where it was
    finally:
        v.stop()


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
    cell = 'from toolkit import viewer\nv = viewer.launch("2ds", port=0, base_url={base!r})\nprint(v.port)\nv.stop()'
    notebook = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell(cell.format(base=base)) for base in ("/user/student/", None)]
    )
    NotebookClient(notebook, timeout=300, kernel_name="python3").execute()
    hub, local = (list(cell.outputs) for cell in notebook.cells)
    port = int("".join(o.get("text", "") for o in hub).split()[-1])
    frames = [o["data"]["text/html"] for o in hub if o.output_type == "display_data"]
    assert frames == [address.link_and_frame(f"/user/student/proxy/{port}/")]
    assert (
        f'<iframe src="/user/student/proxy/{port}/"' in frames[0] and f'href="/user/student/proxy/{port}/"' in frames[0]
    )
    assert all(o.output_type == "stream" for o in local)  # locally: the printed line only
    assert "at http://127.0.0.1:" in "".join(o.text for o in local)


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


@pytest.mark.browser
@pytest.mark.slow
@pytest.mark.skipif(viewer_browser.find_chromium() is None, reason="no Chromium installed (run `make browser`)")
def test_chromium_opens_the_printed_address_through_a_jupyter_server(tmp_path):
    pytest.importorskip("jupyter_server_proxy", reason="jupyter-server-proxy is in the dev and hub extras")
    jupyter_port = free_port()
    root = f"http://127.0.0.1:{jupyter_port}"
    jupyter = start(
        [sys.executable, "-m", "jupyter_server", f"--port={jupyter_port}", "--ServerApp.ip=127.0.0.1"]
        + ["--ServerApp.base_url=/user/student/", "--IdentityProvider.token=", f"--ServerApp.root_dir={tmp_path}"]
        + ["--ServerApp.open_browser=False", "--ServerApp.allow_root=True"],  # CI runs as root
        dict(os.environ),
        tmp_path / "jupyter.log",
    )
    hub_env = dict(
        os.environ, JUPYTERHUB_SERVICE_PREFIX="/user/student/", JUPYTERHUB_PUBLIC_URL=f"{root}/user/student/"
    )
    view = start([sys.executable, "-m", "toolkit", "view", "--scenario", "3do"], hub_env, tmp_path / "view.log")
    try:
        wait_for(f"{root}/user/student/api/status", jupyter, tmp_path / "jupyter.log")
        deadline = time.monotonic() + 300
        while not (printed := re.search(r" at (\S+)", (tmp_path / "view.log").read_text())):
            assert view.poll() is None and time.monotonic() < deadline, (tmp_path / "view.log").read_text()
            time.sleep(0.5)
        url = printed.group(1)
        assert re.fullmatch(rf"{root}/user/student/proxy/\d+/", url)
        viewer_browser.screenshot(url, tmp_path / "hub.png", size=(1100, 700))  # the obstacles: the websocket is up
    finally:
        for process in (view, jupyter):
            process.terminate()
            process.wait(timeout=30)
