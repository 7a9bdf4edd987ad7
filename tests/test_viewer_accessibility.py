"""The live viewer (``toolkit view``) for a screen-reader user: every control named, the logo described, the
status lines announced, text at AA contrast (axe-core in Chromium, as ``tools/accessibility.py`` audits the
site), against viser's page as it comes, which fails."""

from __future__ import annotations

import time
from urllib.request import urlopen

import numpy as np
import pytest

from toolkit.viewer import Panel, Viewer, app, labels
from toolkit.viewer import browser as viewer_browser
from tools import accessibility

needs_chromium = pytest.mark.skipif(viewer_browser.find_chromium() is None, reason="no Chromium installed")


def test_the_live_page_is_vipers_with_the_naming_script_and_only_while_asked():
    viewer = app.launch("2ds", port=0, quiet=True)
    try:
        page = urlopen(viewer.url, timeout=30).read().decode()
        assert page.count(labels.script()) == 1 and page.index(labels.script()) < page.index("</body>")
    finally:
        viewer.stop()
    plain = Viewer("2ds", port=0)  # a snapshot's server: viser's page as it comes
    try:
        assert labels.script() not in urlopen(plain.url, timeout=30).read().decode()
    finally:
        plain.stop()


def test_a_saved_scene_gets_the_names_of_its_player_too():
    page = labels.label_controls("<html><body><div id=root></div></body></html>")
    assert all(name in page for name in {**labels.NAMES, **labels.RECORDING_NAMES}.values())
    assert "display: none !important" in page and page.endswith("</script>\n</body></html>")


def audit(chromium, viewer: Viewer) -> tuple[dict, object]:
    """axe's violations on the viewer's page once its panel is built, by rule (impact and node count); the page."""
    page = chromium.new_page(viewport={"width": 1280, "height": 900})
    page.goto(viewer.url, wait_until="load")
    page.get_by_text("random valid configuration").first.wait_for(timeout=60_000)
    time.sleep(0.5)  # the naming script runs as React adds nodes
    found = accessibility.audit_page(page, accessibility.axe_script())
    return {v["id"]: (v["impact"], len(v["nodes"])) for v in found}, page


@pytest.mark.browser
@needs_chromium
def test_vipers_own_page_fails_the_audit(chromium):
    viewer = Viewer("3do", port=0)
    Panel(viewer)
    try:
        found, page = audit(chromium, viewer)
        page.close()
    finally:
        viewer.stop()
    assert {"label", "button-name", "image-alt", "aria-input-field-name", "color-contrast"} <= set(found)


@pytest.mark.browser
@needs_chromium
def test_the_live_viewer_passes_the_audit_and_announces_validity(chromium):
    viewer = app.launch("3do", port=0, quiet=True)
    try:
        found, page = audit(chromium, viewer)
        try:
            assert found == {}  # no WCAG 2.1 A / AA violation of any impact
            sliders = page.locator("[role=slider]").evaluate_all("all => all.map(s => s.getAttribute('aria-label'))")
            assert sliders[: viewer.robot.dof] == list(viewer.robot.dof_names)
            typed = page.get_by_label(f"{viewer.robot.dof_names[0]}, typed value")
            assert typed.count() == 1
            status = page.locator("[role=status][aria-live=polite]").first
            assert "exact: valid" in status.inner_text()
            collides = next(
                q for q in viewer.robot.sample(np.random.default_rng(0), 500) if not viewer.exact.are_valid(q[None])[0]
            )
            viewer.set_configuration(collides)
            page.wait_for_function(
                "() => document.querySelector('[role=status]').innerText.includes('exact: in collision')"
            )
            assert page.get_by_alt_text(labels.LOGO_ALT).count() >= 1
        finally:
            page.close()
    finally:
        viewer.stop()
