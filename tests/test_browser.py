"""The viewer in a real headless Chromium: the page comes to show the scene, not a blank or "connecting" page.

Each test waits on what the page shows: ``screenshot`` photographs it until the
colors the scene must have appear (5 minutes at most), so a busy machine makes a
test slower, not failed. Skipped only where no Chromium is installed (``make test``
installs Debian's).
"""

import numpy as np
import pytest

from toolkit import viewer
from toolkit.viewer import browser as viewer_browser
from toolkit.viewer import drawing as draw

pytestmark = [
    pytest.mark.browser,
    pytest.mark.slow,
    pytest.mark.skipif(
        viewer_browser.find_chromium() is None,
        reason="no Chromium installed (run `make browser` or `apt-get install chromium`)",
    ),
]


def share(png, rgb) -> float:
    return viewer_browser.color_share(png, rgb)


SIZE = (1100, 700)  # window (width, height): smaller renders faster in software WebGL
FOCUS_OUTLINE = "parseFloat(getComputedStyle(document.activeElement).outlineWidth)"  # px, of the focused element


def test_the_office_renders_with_its_samples(make_viewer, tmp_path):
    v = make_viewer("3do", seed=0)
    v.sample("raw", 400, seed=0)
    viewer_browser.screenshot(
        v.url,
        tmp_path / "office.png",
        size=SIZE,
        ready=lambda png: (
            share(png, draw.OBSTACLE) > 0.03  # furniture covers much of the canvas
            and share(png, draw.VALID) > 0.003  # valid samples (blue circles)
            and share(png, draw.COLLIDING) > 0.0005  # samples in collision (vermillion diamonds)
        ),
    )


def test_a_colliding_robot_shows_red(make_viewer, tmp_path):
    v = make_viewer("2ds", seed=0)
    centers = v.workspace.boxes.mean(axis=1)  # (K, 2)
    block = centers[np.argmin(np.linalg.norm(centers - v.q, axis=1))]  # the block nearest the robot: in view
    v.set_configuration(block)  # the robot's square inside the block: it pokes out of it, in the invalid colour
    assert not v.valid
    png = viewer_browser.screenshot(
        v.url,
        tmp_path / "colliding.png",
        size=SIZE,
        ready=lambda png: (
            share(png, draw.COLLIDING) > 5e-5  # the robot, ~100 px
            and share(png, draw.OBSTACLE) > 0.01  # and the scene
        ),
    )
    assert share(png, draw.VALID) == 0.0  # nothing in the valid colour


def test_the_embedded_snapshot_renders_without_a_server(tmp_path):
    page = tmp_path / "snapshot.html"
    with viewer.Viewer("3dc7", seed=0, port=0) as v:
        page.write_text(v.html())
    viewer_browser.screenshot(
        page.as_uri(), tmp_path / "snapshot.png", size=SIZE, ready=lambda png: share(png, draw.OBSTACLE) > 0.01
    )


def test_a_page_that_never_shows_the_scene_times_out(tmp_path):
    page = tmp_path / "blank.html"
    page.write_text("<html><body>connecting...</body></html>")
    with pytest.raises(TimeoutError, match="did not show what was expected within 15 s"):
        viewer_browser.screenshot(page.as_uri(), tmp_path / "blank.png", size=SIZE, budget_s=15)


def test_an_animation_opens_on_its_still_and_plays_at_a_press_without_webgl_only_the_still(tmp_path):
    """Reader r11b: screenshots caught the animation blank. Its page shows the still first, over the view, in a
    browser that draws 3D; the button hides it. Without WebGL the still stays, with no button and a note why."""
    import html
    import re

    from playwright.sync_api import sync_playwright

    from toolkit.viewer.labels import NO_WEBGL

    page_file = tmp_path / "animation.html"
    with viewer.Viewer("3dc7", seed=1, port=0) as v:
        v.plan("BS", seed=0)
        snippet = v.animation_iframe(300, frames=3, seconds=1.0)
    page_file.write_text(html.unescape(re.search(r'srcdoc="([^"]*)"', snippet).group(1)))
    with sync_playwright() as playwright:
        for webgl in (True, False):
            args = viewer_browser.CHROMIUM_ARGS + ([] if webgl else ["--disable-webgl", "--disable-3d-apis"])
            browser = playwright.chromium.launch(executable_path=viewer_browser.find_chromium(), args=args)
            page = browser.new_page(viewport={"width": 640, "height": 440})
            page.goto(page_file.as_uri(), timeout=120_000)
            still, play = page.locator("#toolkit-still"), page.get_by_role("button", name="play in 3D")
            assert still.locator("img").is_visible(), webgl
            assert page.evaluate("document.getElementById('root').inert")  # no focus under the still
            if webgl:
                play.focus()
                assert page.evaluate(FOCUS_OUTLINE) >= 2
                play.press("Enter")
                assert still.is_hidden() and not page.evaluate("document.getElementById('root').inert")
            else:
                assert play.count() == 0 and page.locator("#toolkit-still-note").inner_text() == NO_WEBGL
            browser.close()


def test_the_animations_play_pause_button_says_whether_it_plays_and_space_and_enter_toggle_it(tmp_path):
    """WCAG 4.1.2 and 2.1.1 (a11y10): the saved player's play / pause button kept one name and no state, and Space did
    not toggle it (the player's own Space handler undid the button's press). It is a toggle now, pressed while the
    recording plays; Space and Enter each toggle it, and the recording's time stops and moves again with it."""
    import html
    import re

    from playwright.sync_api import sync_playwright

    from toolkit.viewer.labels import PLAY_PAUSE

    page_file = tmp_path / "animation.html"
    with viewer.Viewer("3dc7", seed=1, port=0) as v:
        v.plan("BS", seed=0)
        snippet = v.animation_iframe(300, frames=6, seconds=3.0)
    page_file.write_text(html.unescape(re.search(r'srcdoc="([^"]*)"', snippet).group(1)))
    time = "document.querySelector('input[aria-label^=time]').value"
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(
            executable_path=viewer_browser.find_chromium(), args=viewer_browser.CHROMIUM_ARGS
        )
        page = browser.new_page(viewport={"width": 640, "height": 440})
        page.goto(page_file.as_uri(), timeout=120_000)
        page.get_by_role("button", name="play in 3D").press("Enter")
        button = page.get_by_role("button", name=PLAY_PAUSE)
        page.wait_for_function("() => document.activeElement.getAttribute('aria-pressed') === 'true'", timeout=60_000)
        states = []
        for key in ("Space", "Space", "Enter", "Enter"):
            page.keyboard.press(key)
            page.wait_for_timeout(300)
            before = page.evaluate(time)
            page.wait_for_timeout(1200)
            states.append((key, button.get_attribute("aria-pressed"), page.evaluate(time) != before))
        browser.close()
    assert states == [
        ("Space", "false", False),
        ("Space", "true", True),
        ("Enter", "false", False),
        ("Enter", "true", True),
    ]
