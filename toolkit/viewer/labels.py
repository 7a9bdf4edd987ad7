"""Names for the controls of a saved scene: what a screen reader says about a snapshot's or animation's player.

viser draws a saved scene's player (play / pause, the time, the playback speed) with icon buttons and inputs
that carry no accessible name, and may show a notice (e.g. that the browser renders WebGL in software) over
the scene. :func:`label_controls` adds a small script to the document that names each control as the page
builds it and hides the notices (a static page has nothing to notify); the scene's own text alternative is the
summary beside it (:meth:`toolkit.viewer.Viewer.summary`).
"""

from __future__ import annotations

import json

NAMES = {  # CSS selector -> accessible name (aria-label), for the controls viser leaves unnamed
    ".mantine-ActionIcon-root:not([aria-label]):not([title])": "play or pause the recording",
    "input[inputmode=decimal]:not([aria-label])": "time in the recording (seconds)",
    "input[role=combobox]:not([aria-label])": "playback speed",
    "button:not([aria-label]):not([title])": "viewer control",
}
HIDDEN = ".mantine-Notifications-root, .mantine-Notification-root"  # notices over the scene

SCRIPT = """<style>%(hidden)s { display: none !important; }</style>
<script>
(() => {
  const names = %(names)s;
  const name = () => {
    for (const [selector, label] of Object.entries(names)) {
      for (const element of document.querySelectorAll(selector)) {
        if (!element.textContent.trim() || element.tagName === "INPUT") element.setAttribute("aria-label", label);
      }
    }
  };
  new MutationObserver(name).observe(document.documentElement, {childList: true, subtree: true});
  name();
})();
</script>
"""


def label_controls(document: str) -> str:
    """``document`` (a saved scene's HTML) with the script that names its controls, placed before ``</body>``."""
    script = SCRIPT % {"hidden": HIDDEN, "names": json.dumps(NAMES)}
    head, found, tail = document.rpartition("</body>")
    return head + script + found + tail if found else document + script
