"""The site's accessibility audit: axe-core on every page, in Chromium, the embedded viewers' frames included.

axe-core (Deque) checks a page against the WCAG 2.0 / 2.1 / 2.2 level A and AA rules; a violation's impact is
minor, moderate, serious or critical. The site must have no serious or critical one (tests/test_site.py).
axe-core comes from the PyPI package ``axe-playwright-python`` (it ships ``axe.min.js``); the browser is
Debian's Chromium driven by Playwright (:func:`toolkit.viewer.browser.find_chromium`), never a downloaded one.

    python -m tools.accessibility SITE_FOLDER     # nodes per rule and impact, pages with violations
"""

from __future__ import annotations

import argparse
import collections
import functools
import http.server
import json
import os
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

WCAG_AA = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa", "wcag22aa"]  # axe tags: WCAG 2.2 AA adds target size (2.5.8)
BLOCKING = ("serious", "critical")


def axe_script() -> str:
    """axe-core's ``axe.min.js`` as the package ``axe-playwright-python`` ships it."""
    from axe_playwright_python.sync_playwright import Axe  # type: ignore[import-untyped]

    return Axe().axe_script


def pages(site: Path) -> list[str]:
    """Every page of the built site (its HTML files but the 404 page), as paths relative to ``site``."""
    return sorted(str(p.relative_to(site)) for p in site.rglob("*.html") if p.name != "404.html")


def start_audit(page, script: str) -> None:
    """Start axe's WCAG 2.0/2.1/2.2 A and AA audit of the loaded ``page``, its frames (the viewers) included, without
    waiting for it: audits of several pages then run at once, each in its own renderer process."""
    for frame in page.frames:  # axe reaches a frame only where it runs too
        frame.evaluate(script)
    options = {"runOnly": {"type": "tag", "values": WCAG_AA}, "resultTypes": ["violations"], "iframes": True}
    page.evaluate("options => { window.__axeAudit = axe.run(document, options); }", options)


def finish_audit(page) -> list[dict]:
    """The violations of the audit :func:`start_audit` began on ``page``: one dict per rule with ``id``, ``impact``
    and ``nodes`` (each with ``target`` and ``html``)."""
    result = page.evaluate("() => window.__axeAudit")
    return [
        {
            "id": v["id"],
            "impact": v["impact"],
            "nodes": [{"target": n["target"], "html": n["html"]} for n in v["nodes"]],
        }
        for v in result["violations"]
    ]


def audit_page(page, script: str) -> list[dict]:
    """axe's violations on the loaded ``page`` (:func:`start_audit`, then :func:`finish_audit`)."""
    start_audit(page, script)
    return finish_audit(page)


@contextmanager
def served(folder: Path) -> Iterator[str]:
    """``folder`` on a free port of 127.0.0.1 (the base URL); the port is free again afterwards."""

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, format, *args):
            pass

    class Server(http.server.ThreadingHTTPServer):
        def handle_error(self, request, client_address):
            if not isinstance(sys.exc_info()[1], ConnectionError):  # a page closed before its last file came
                super().handle_error(request, client_address)

    server = Server(("127.0.0.1", 0), functools.partial(Quiet, directory=str(folder)))
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()
        server.server_close()
        thread.join()


def audit_site(browser, base: str, paths: list[str], at_once: int | None = None) -> dict[str, list[dict]]:
    """Each page's violations (:func:`finish_audit`), by path; ``browser``: a Playwright Chromium. ``at_once`` pages
    are audited together (default: one per core this process may use), since axe's run is most of the time."""
    script, found = axe_script(), {}
    at_once = at_once or len(os.sched_getaffinity(0))
    for first in range(0, len(paths), at_once):
        batch = paths[first : first + at_once]
        opened = [browser.new_page(viewport={"width": 1280, "height": 900}) for _ in batch]
        try:
            for page, path in zip(opened, batch):
                page.goto(base + path, wait_until="load")
                start_audit(page, script)
            for page, path in zip(opened, batch):
                found[path] = finish_audit(page)
        finally:
            for page in opened:
                page.close()
    return found


def blocking(found: dict[str, list[dict]]) -> dict[str, list[str]]:
    """The serious and critical violations, ``{page: ["rule: N nodes", ...]}``, pages without any left out."""
    listed = {
        path: [f"{v['id']} ({v['impact']}): {len(v['nodes'])} nodes" for v in rules if v["impact"] in BLOCKING]
        for path, rules in found.items()
    }
    return {path: rules for path, rules in listed.items() if rules}


def tally(found: dict[str, list[dict]]) -> dict[str, dict]:
    """Per rule: its impact, nodes over all pages and the number of pages it fails on."""
    rules: dict[str, dict] = collections.defaultdict(lambda: {"impact": "", "nodes": 0, "pages": 0})
    for violations in found.values():
        for v in violations:
            rules[v["id"]].update(impact=v["impact"])
            rules[v["id"]]["nodes"] += len(v["nodes"])
            rules[v["id"]]["pages"] += 1
    return dict(sorted(rules.items()))


def main(argv: list[str] | None = None) -> int:
    from playwright.sync_api import sync_playwright

    from toolkit.viewer import browser as viewer_browser

    parser = argparse.ArgumentParser(prog="python -m tools.accessibility", description=__doc__.splitlines()[0])
    parser.add_argument("site", type=Path, help="a built site (python -m tools.site --out SITE)")
    parser.add_argument("--json", type=Path, help="also write every violation's nodes here")
    args = parser.parse_args(argv)
    paths = pages(args.site)
    with served(args.site) as base, sync_playwright() as pw:
        chromium = pw.chromium.launch(executable_path=viewer_browser.find_chromium(), args=viewer_browser.CHROMIUM_ARGS)
        try:
            found = audit_site(chromium, base, paths)
        finally:
            chromium.close()
    if args.json:
        args.json.write_text(json.dumps(found, indent=1))
    rules = tally(found)
    serious = sum(r["nodes"] for r in rules.values() if r["impact"] in BLOCKING)
    print(f"{len(paths)} pages; {serious} serious or critical nodes on {len(blocking(found))} pages")
    for rule, counts in rules.items():
        print(f"  {rule} ({counts['impact']}): {counts['nodes']} nodes on {counts['pages']} pages")
    return 0 if serious == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
