"""Names for the controls viser leaves unnamed: what a screen reader says about a saved scene's player and about
the live viewer's panel.

viser draws its controls without accessible names: a slider's handle has ``aria-label=""``, the number box beside
it and every number input have no label (their visible names are ``<label for>`` the row's own element, not the
input), icon buttons (settings, a notice's close button, a recording's play / pause) have no text, and the logo
has no ``alt``; it may show a notice (e.g. that the browser renders WebGL in software) over the scene. viser has no
option for any of these (``configure_theme`` can only hide the logo and the share button: the panel hides the
share button, which would publish the scene), so a small script names them from the page itself, as React
builds it: each control takes the name of the label of its row (:data:`SCRIPT`). A folder's title, which viser opens
and closes on a click only (the Layers folder starts closed: its checkboxes were out of the keyboard's reach), becomes
a heading (level 2) over a button, its text, that Enter and Space toggle, saying whether it is open (``aria-expanded``);
the live page's heading (level 1) is its title, out of sight (viser's page had no heading). The 3D view, a canvas, is an
image named :data:`VIEW`: on the live page described (``aria-describedby``) by the panel's "The scene in words"
(:meth:`toolkit.viewer.Viewer.summary`, from the scene's data), in a saved scene by the summary after its frame. viser
draws the view at 5 % opacity until its environment map has loaded, then fades it in: the style keeps it opaque
(``toolkit.viewer.drawing.light`` sets no map). Icons are hidden from the screen
reader's tree (they draw what their control's name says), but the connection's, which :data:`ICONS` names. Its
style also outlines a focused input (and a folder's title) as viser outlines a focused button (2 px; viser shows an
input's focus only by its 1 px border's colour), darkens the sliders' min/max labels and a notice's text (viser's
grey is 3.3:1 on white) to 6.4:1, and the inputs' and unticked checkboxes' borders (1.5:1) and the sliders' unfilled
tracks (2.1:1) to 3.3:1 (WCAG 1.4.3, 1.4.11), and makes viser's panel-minimize control and number inputs at
least 24 px (2.5.8). A saved scene's play / pause button is a toggle, pressed while it plays, that Space presses once
(viser's own Space handler undid the button's press).

- :func:`label_controls` adds the script to a saved scene's page (snapshots and animations in notebook 05), and
  hides the notices there (a static page has nothing to notify); the scene's own text alternative is the
  summary beside it (:meth:`toolkit.viewer.Viewer.summary`);
- :func:`with_still` puts a still picture of the scene into a saved scene's page, shown in the view's place
  where the browser has no WebGL (the view would stay blank there), in a snapshot until its view has been on
  screen a moment (a view off screen is not drawn), and, for an animation, first in every browser, with a button
  that plays the 3D view;
- :func:`named_live_page` makes viser's server serve its page with the same script (``toolkit view``): a copy of
  viser's ``client/build/index.html`` with the script in it, served in place of the original.

viser titles every page "Viser": the live page's title (WCAG 2.4.2) says what it is, :data:`PAGE_TITLE`, and the script
puts the scenario the panel's dropdown shows before it ("3D clutter, 7-DoF box chain (3dc7): live viewer, ...").

The panel's status lines carry a mark (``<span data-live-status hidden>``, :data:`toolkit.viewer.panel.LIVE`; viser's
markdown keeps raw HTML) by which the script makes each a live region (``role="status"``): a change of validity
is announced. ``tests/test_viewer_accessibility.py`` runs axe-core on the live viewer.
"""

from __future__ import annotations

import base64
import contextlib
import functools
import html
import io
import json
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path

import viser
import viser.infra
from matplotlib.figure import Figure

from toolkit import scenarios
from toolkit.plots.palette import COLORS

NAMES = {  # CSS selector -> accessible name (aria-label), for the controls without a visible label
    ".tabler-icon-adjustments": "viewer settings",
    ".tabler-icon-share": "share the scene",
    ".mantine-Notification-closeButton": "close this notice",
}
PLAY_PAUSE = "play the recording"  # a saved scene's play / pause button: a toggle, pressed while it plays
RECORDING_NAMES = {  # and on a saved scene's player, after those
    ".mantine-ActionIcon-root:not([aria-label]):not([title])": PLAY_PAUSE,
    "input[inputmode=decimal]:not([aria-label])": "time in the recording (seconds)",
    "input[role=combobox]:not([aria-label])": "playback speed",
    "button:not([aria-label]):not([title])": "viewer control",
}
LOGO_ALT = "viser"  # the logo in the panel's corner
ICONS = {  # an icon's class -> its name, for the icons that tell something; every other icon is hidden from the tree
    "tabler-icon-cloud-check": "connected to the viewer's server",
    "tabler-icon-cloud-off": "not connected to the viewer's server",
}
HIDDEN = ".mantine-Notifications-root, .mantine-Notification-root"  # notices over a saved scene
PAGE_TITLE = "live viewer, Predicting Sample Collision with Neural Networks"  # the page's title (viser's: "Viser")
VIEW = {  # the 3D view's name (its canvas), live (described in the panel) and saved (described beside its frame)
    "live": "3D view of the scene (described in the panel's folder 'The scene in words')",
    "saved": "3D view of the scene (described in the text after it)",
}
DIMMED = COLORS["panel_text"]  # viser's dimmed label text (3.3:1 on white) made darker

BORDER = COLORS["input_border"]  # an input's border, darker than viser's
TRACK = COLORS["slider_track"]  # a slider's unfilled track, darker than viser's

SCRIPT = """<style>:root { --mantine-color-dimmed: %(dimmed)s !important; }
[data-camera-controls-version] canvas { opacity: 1 !important; }
.mantine-Slider-markLabel, .mantine-Notification-description { color: %(dimmed)s !important; }
.mantine-Slider-markLabel { font-size: 12px !important; }
.mantine-Input-input:not(:focus), .mantine-Checkbox-input:not(:checked) { border-color: %(border)s !important; }
.mantine-Slider-root { --slider-track-bg: %(track)s !important; }
.mantine-Slider-track::before { background-color: %(track)s !important; }
input:focus-visible, [role=button][tabindex]:focus-visible {
  outline: 2px solid var(--mantine-primary-color-filled) !important; outline-offset: 1px; }
[data-dock-minimize], .mantine-NumberInput-input { min-width: 24px !important; min-height: 24px !important; }</style>
<script>
(() => {
  const names = %(names)s;
  const icons = %(icons)s;
  const titles = %(titles)s;
  const view = %(view)s;
  const play = (target) => target?.closest?.(`button[aria-label="${%(play)s}"]`);  // a saved scene's play / pause
  window.addEventListener("keydown", (event) => {  // Space presses it once (the player's own Space undid the press)
    if (event.key !== " " || !play(event.target)) return;
    event.preventDefault();
    event.stopImmediatePropagation();
    if (!event.repeat) play(event.target).click();
  }, true);
  window.addEventListener("keyup", (event) => event.key === " " && play(event.target) && event.preventDefault(), true);
  const rowLabel = (control) => {  // the text of the one <label> of the nearest row around the control
    for (let node = control.parentElement, depth = 0; node && depth < 8; node = node.parentElement, depth++) {
      const labels = node.querySelectorAll("label");
      if (labels.length > 1) return null;
      if (labels.length === 1 && labels[0].textContent.trim()) return labels[0].textContent.trim();
    }
    return null;
  };
  const unnamed = (element) => !element.getAttribute("aria-label") && !element.getAttribute("aria-labelledby");
  const name = () => {
    for (const slider of document.querySelectorAll("[role=slider]")) {
      const label = unnamed(slider) && rowLabel(slider);
      if (label) slider.setAttribute("aria-label", label);
    }
    for (const input of document.querySelectorAll("input:not([type=hidden])")) {
      if (!unnamed(input) || (input.labels && input.labels.length)) continue;
      const label = rowLabel(input);
      const besideSlider = input.closest(".mantine-Flex-root")?.querySelector("[role=slider]");
      if (label) input.setAttribute("aria-label", besideSlider ? label + ", typed value" : label);
    }
    for (const [selector, label] of Object.entries(names)) {
      for (const found of document.querySelectorAll(selector)) {
        const control = found.closest("button, input") || found;
        if (unnamed(control) && (!control.textContent.trim() || control.tagName === "INPUT")) {
          control.setAttribute("aria-label", label);
        }
      }
    }
    for (const button of document.querySelectorAll(`button[aria-label="${%(play)s}"]`)) {  // pressed while playing
      const playing = String(!!button.querySelector("[class*=tabler-icon-player-pause]"));
      if (button.getAttribute("aria-pressed") !== playing) button.setAttribute("aria-pressed", playing);
    }
    for (const image of document.querySelectorAll("img:not([alt])")) image.setAttribute("alt", %(logo)s);
    for (const icon of document.querySelectorAll("svg:not([aria-hidden]):not([aria-label])")) {
      const status = Object.entries(icons).find(([kind]) => icon.classList.contains(kind));
      if (status) {  // an icon that tells something: an image with a name
        icon.setAttribute("role", "img");
        icon.setAttribute("aria-label", status[1]);
      } else icon.setAttribute("aria-hidden", "true");  // the rest draw what their control's name says
    }
    for (const chevron of document.querySelectorAll("svg.tabler-icon-chevron-up, svg.tabler-icon-chevron-down")) {
      const header = chevron.parentElement;  // a folder's title: it opens and closes the folder, on a click only
      if (!header || header.style.cursor !== "pointer") continue;
      let toggle = header.querySelector(":scope > [data-toggle]");
      if (!toggle) {  // a heading (level 2) holding a button, the title's text: Enter and Space click the title
        const text = [...header.childNodes].find((node) => node.nodeType === Node.TEXT_NODE);
        if (!text) continue;
        toggle = document.createElement("span");
        toggle.dataset.toggle = "1";
        toggle.setAttribute("role", "button");
        toggle.setAttribute("tabindex", "0");
        header.insertBefore(toggle, text);
        toggle.appendChild(text);  // React keeps the node and may change its text; the click reaches the title
        toggle.addEventListener("keydown", (event) => {
          if (event.key === "Enter" || event.key === " ") {
            event.preventDefault();
            toggle.click();
          }
        });
        header.setAttribute("role", "heading");
        header.setAttribute("aria-level", "2");
      }
      const open = String(chevron.classList.contains("tabler-icon-chevron-up"));
      if (toggle.getAttribute("aria-expanded") !== open) toggle.setAttribute("aria-expanded", open);
    }
    const words = document.querySelector("[data-scene-words]")?.closest("div");  // the scene in words (panel.py)
    if (words && !words.id) words.id = "toolkit-scene-words";
    for (const canvas of document.querySelectorAll("canvas")) {  // the 3D view: an image, described by those words
      if (!canvas.closest("[data-camera-controls-version]")) {  // viser's empty overlay
        if (!canvas.getAttribute("aria-hidden")) canvas.setAttribute("aria-hidden", "true");
      } else if (canvas.getAttribute("aria-label") !== view[words ? "live" : "saved"]) {
        canvas.removeAttribute("aria-hidden");  // (hidden by a run before its container had its mark)
        canvas.setAttribute("role", "img");
        canvas.setAttribute("aria-label", view[words ? "live" : "saved"]);
      }
      if (canvas.getAttribute("role") === "img" && words && !canvas.getAttribute("aria-describedby")) {
        canvas.setAttribute("aria-describedby", words.id);
      }
    }
    const scenario = [...document.querySelectorAll("input[role=combobox]")]  // the panel's dropdown
      .find((input) => [...(input.labels || [])].some((label) => label.textContent.trim() === "scenario"))?.value;
    const title = titles[scenario] && `${titles[scenario]} (${scenario}): ${%(page)s}`;
    if (title && document.title !== title) document.title = title;  // (a change of title is a mutation too)
    if (title) {  // the page's heading: its title, for a screen reader (the panel's own title shows it, shorter)
      let heading = document.getElementById("toolkit-heading");
      if (!heading) {
        heading = document.createElement("h1");
        heading.id = "toolkit-heading";
        heading.style.cssText = "position:absolute;width:1px;height:1px;overflow:hidden;clip-path:inset(50%%);margin:0";
        document.body.prepend(heading);  // outside React's root, before it
      }
      if (heading.textContent !== title) heading.textContent = title;
    }
    for (const mark of document.querySelectorAll("[data-live-status]")) {  // a status line: announce its changes
      const line = mark.closest("div");
      if (line && !line.getAttribute("role")) {
        line.setAttribute("role", "status");
        line.setAttribute("aria-live", "polite");
      }
    }
  };
  new MutationObserver(name).observe(document.documentElement, {childList: true, subtree: true});
  name();
})();
</script>
"""


def script(names: dict[str, str] = NAMES) -> str:
    """The style and script that name the controls: each by its row's label, else by ``names`` (a CSS selector
    to a name), the logo by :data:`LOGO_ALT`."""
    return SCRIPT % {
        "dimmed": DIMMED,
        "border": BORDER,
        "track": TRACK,
        "names": json.dumps(names),
        "icons": json.dumps(ICONS),
        "logo": json.dumps(LOGO_ALT),
        "titles": json.dumps({name: scenario.title for name, scenario in scenarios.SCENARIOS.items()}),
        "page": json.dumps(PAGE_TITLE),
        "view": json.dumps(VIEW),
        "play": json.dumps(PLAY_PAUSE),
    }


def _before_body_end(document: str, addition: str) -> str:
    head, found, tail = document.rpartition("</body>")
    return head + addition + found + tail if found else document + addition


def label_controls(document: str) -> str:
    """``document`` (a saved scene's HTML) with the script that names its controls and hides its notices, placed
    before ``</body>``."""
    hidden = f"<style>{HIDDEN} {{ display: none !important; }}</style>\n"
    return _before_body_end(document, hidden + script(NAMES | RECORDING_NAMES))


STILL = """<style>#toolkit-play:focus-visible { outline: 2px solid %(ink)s; outline-offset: 2px; }</style>
<div id="toolkit-still"%(hidden)s
 style="position:fixed;inset:0;overflow:auto;background:#fff;z-index:2147483647">
<p style="position:sticky;top:0;margin:0;padding:4px 8px;background:#fff;font:14px sans-serif">
<span id="toolkit-still-note">%(note)s</span>%(play)s</p>
%(picture)s</div>
<script>(function () {
  var canvas = document.createElement("canvas"), still = document.getElementById("toolkit-still");
  var play = document.getElementById("toolkit-play"), view = document.getElementById("root") || {}, waiting = false;
  var frame = null;  // the page's <iframe>, where this page may reach it (a srcdoc frame, not sandboxed)
  try { frame = window.frameElement; } catch (error) {}
  function fit() {  // a one-line note only: the frame as tall as the note until the view draws (reader r25b: a
    if (!%(collapse)s || !frame) return;  // 300 px blank box under it), then as tall as the page made it
    frame.style.height = still.hidden ? "" : still.firstElementChild.offsetHeight + "px";
  }
  function hide() { still.hidden = true; fit(); }
  if (!(canvas.getContext("webgl2") || canvas.getContext("webgl"))) {
    document.getElementById("toolkit-still-note").textContent = %(no_webgl)s;
    if (play) play.remove();
    still.hidden = false;
  } else if (!play && window.IntersectionObserver) {  // a snapshot: the still until the view has been on screen
    waiting = true;
    var drawing = null;  // a while (a view off screen is not drawn: a screenshot showed blank boxes)
    new IntersectionObserver(function (entries) {
      clearTimeout(drawing);
      if (entries[entries.length - 1].isIntersecting) drawing = setTimeout(hide, %(on_screen_ms)d);
    }).observe(document.documentElement);
    document.addEventListener("focusin", hide);  // the keyboard in: the view at once
  } else if (!play) {
    still.hidden = true;
  }
  fit();
  view.inert = !still.hidden;  // no focus on controls the still covers
  if (waiting) view.inert = false;  // unless it only waits for the view to draw: the keyboard may go in at once
  if (play) play.addEventListener("click", function () {  // the focus goes on to the player's play / pause
    still.hidden = true;
    view.inert = false;
    var control = document.querySelector("[aria-label='" + %(play_pause)s + "']");
    if (control) control.focus();
  });
})();</script>
"""
NO_WEBGL = "This browser draws no 3D (no WebGL): the scene as a still picture."
NO_WEBGL_ABOVE = "3D view: this browser draws no 3D (no WebGL); the still picture above shows this scene."
ABOVE = "3D view of the still picture above: in a browser with WebGL it draws here once it has been on screen a moment."
PICTURE = '<img src="data:image/png;base64,%(png)s" alt="%(alt)s" style="width:100%%;max-width:640px;height:auto">'
DRAWING = (
    "A still picture of the scene: in a browser with WebGL the 3D view replaces it once it has been on screen a moment."
)
ON_SCREEN_MS = 1500  # milliseconds a snapshot's view is on screen before it replaces its still (it draws by then)
PLAY = (
    ' <button id="toolkit-play" type="button" style="font:inherit;font-weight:bold;margin-left:8px;padding:2px 10px;'
    'border:2px solid %(ink)s;border-radius:4px;background:#fff;color:%(ink)s;cursor:pointer">%(play)s</button>'
)


def with_still(
    document: str, fig: Figure | None, *, first: str | None = None, play: str = "play in 3D", above: bool = False
) -> str:
    """``document`` (a saved scene's HTML) with ``fig``, a still picture of its scene, over the view (the picture's
    alt text from the figure): where the browser has no WebGL (the view would stay blank there) and, given
    ``first`` (what the still shows, in words), in every browser until the reader presses ``play``: a screenshot
    or a printed page then shows the still, not a view that has not drawn yet. Without ``first`` (a snapshot) the
    still stays until the view has been on screen :data:`ON_SCREEN_MS`: a browser draws no view off screen, so a
    page's screenshot showed blank boxes there (reader r23b). The view's controls take no focus
    while the still covers them; pressing ``play`` moves the focus to the player's play / pause button.
    With ``above`` (the page shows the same still just above the view), a one-line note stands in for the picture
    (:data:`ABOVE`, :data:`NO_WEBGL_ABOVE`): reader r24b saw the still twice, the second copy cut at the view's height;
    the frame is then as tall as that line until the view draws (reader r25b: a 300 px blank box under the note).
    ``document`` as it is without a figure, unless ``above`` (which needs none)."""
    if fig is None and not above:
        return document
    from toolkit.plots.alt import alt_text

    if above or fig is None:
        picture = ""
    else:
        buffer = io.BytesIO()
        fig.savefig(buffer, format="png", dpi=100, bbox_inches="tight")
        picture = PICTURE % {
            "png": base64.b64encode(buffer.getvalue()).decode(),
            "alt": html.escape(alt_text(fig), quote=True),
        }
    filled = {
        "picture": picture,
        "hidden": "",  # shown until the view draws (a snapshot) or the reader plays it (``first``)
        "note": html.escape(ABOVE if above else DRAWING if first is None else first),
        "on_screen_ms": ON_SCREEN_MS,
        "play": "" if first is None else PLAY % {"ink": COLORS["ink"], "play": html.escape(play)},
        "no_webgl": json.dumps(NO_WEBGL_ABOVE if above else NO_WEBGL),
        "ink": COLORS["ink"],
        "play_pause": json.dumps(PLAY_PAUSE),
        "collapse": json.dumps(above),  # a one-line note: the frame that tall until its view draws
    }
    return _before_body_end(document, STILL % filled)


@functools.cache
def _named_client() -> Path:
    """A folder holding viser's page with :func:`script` in it (made once a process; viser's build is one file)."""
    build = Path(viser.__file__).resolve().parent / "client" / "build"
    folder = Path(tempfile.mkdtemp(prefix="toolkit-viewer-page-"))
    for source in build.iterdir():
        if source.is_file():
            text = source.read_text(encoding="utf-8") if source.name == "index.html" else None
            target = folder / source.name
            if text is None:
                target.write_bytes(source.read_bytes())
            else:
                title = html.escape(PAGE_TITLE[0].upper() + PAGE_TITLE[1:])
                titled = text.replace("<title>Viser</title>", f"<title>{title}</title>")
                target.write_text(_before_body_end(titled, script()), encoding="utf-8")
    return folder


_serving = threading.Lock()  # one server built at a time while viser's page is swapped


@contextlib.contextmanager
def named_live_page() -> Iterator[None]:
    """While the block runs, a ``viser.ViserServer`` built in it serves viser's page with :func:`script` added.

    viser takes the folder it serves from its own install, with no option to change it: the block gives its
    server class (``viser.infra.WebsockServer``) the named copy (:func:`_named_client`) instead.
    """
    original = viser.infra.WebsockServer
    root = _named_client()

    def serving_named_page(*args, **kwargs):
        kwargs["http_server_root"] = root
        return original(*args, **kwargs)

    with _serving:
        viser.infra.WebsockServer = serving_named_page  # type: ignore[assignment,misc]
        try:
            yield
        finally:
            viser.infra.WebsockServer = original  # type: ignore[misc]
