"""Where a student opens a live viewer: this computer's port, or a path through the Jupyter server they work in.

On a laptop the viewer's server is opened directly, ``http://127.0.0.1:PORT``. On a
JupyterHub the student's browser reaches only the hub: jupyter-server-proxy (the
``[hub]`` extra) forwards ``<base URL>proxy/PORT/`` of their Jupyter server to that
port, websocket included, to every user of the machine's ports: the address carries the viewer's
secret after ``proxy/PORT/`` (:mod:`toolkit.viewer.server`). The base URL comes from, first to last:

1. the ``base_url`` argument (``toolkit view --base-url``);
2. ``$TOOLKIT_VIEWER_BASE_URL``, for any Jupyter server started with a base URL;
3. what JupyterHub sets in every user's server: ``$JUPYTERHUB_PUBLIC_URL`` (the server's whole
   address, when the hub's ``public_url`` is configured), else ``$JUPYTERHUB_HOST`` (the hub's
   ``scheme://host``, set with subdomains; else empty) followed by ``$JUPYTERHUB_SERVICE_PREFIX``
   (the path, e.g. ``/user/student/``).

A base URL is a path (``/user/student/``: the address is then relative to the page the
student has open) or an ``http(s)`` address; anything else is a ``ValueError`` naming it.
"""

from __future__ import annotations

import html
import os
from collections.abc import Mapping
from urllib.parse import urlsplit

BASE_URL_VARIABLE = "TOOLKIT_VIEWER_BASE_URL"


def base_url(given: str | None = None, environ: Mapping[str, str] | None = None) -> str | None:
    """The base URL of the Jupyter server the viewer is reached through, ending in ``/``; None: opened directly."""
    environ = os.environ if environ is None else environ
    hub_prefix = environ.get("JUPYTERHUB_SERVICE_PREFIX", "")
    candidates = [
        ("the base URL", given or ""),
        (f"${BASE_URL_VARIABLE}", environ.get(BASE_URL_VARIABLE, "")),
        ("$JUPYTERHUB_PUBLIC_URL", environ.get("JUPYTERHUB_PUBLIC_URL", "")),
        ("$JUPYTERHUB_HOST + $JUPYTERHUB_SERVICE_PREFIX", environ.get("JUPYTERHUB_HOST", "") + hub_prefix),
    ]
    source, value = next(((source, value) for source, value in candidates if value), ("", ""))
    return checked(value, source) if value else None


def checked(url: str, source: str = "the base URL") -> str:
    """``url`` as a base URL ending in ``/``; a ``ValueError`` naming ``source`` and the value if it is none."""
    parts = urlsplit(url)
    as_path = not parts.scheme and not parts.netloc and url.startswith("/") and not url.startswith("//")
    as_address = parts.scheme in ("http", "https") and bool(parts.hostname)
    if not (as_path or as_address) or parts.query or parts.fragment or any(c.isspace() for c in url):
        raise ValueError(
            f"{source} {url!r} is malformed: give a path such as /user/student/ "
            "or an address such as https://hub.example.org/user/student/"
        )
    return url if url.endswith("/") else url + "/"


def proxied(port: int, base: str, path: str = "/") -> str:
    """The address of ``path`` on ``port`` (a viewer's: ``/<secret>/``) through jupyter-server-proxy on the server at
    ``base`` (a checked base URL)."""
    return f"{base}proxy/{int(port)}{path}"


def link_and_frame(url: str, height: int = 480) -> str:
    """HTML for a notebook: a link to the live viewer at ``url`` and the viewer itself in an inline frame."""
    url = html.escape(url, quote=True)
    return (
        f'<div><p>The live viewer: <a href="{url}" target="_blank">{url}</a> (opens in a new tab)</p>'
        f'<iframe src="{url}" title="The live viewer" width="100%" height="{int(height)}" '
        'style="border:none"></iframe></div>'
    )
