"""The toolkit's colours: one role, one colour, the same in every figure and in the viewer.

One man in twelve sees colour differently, so the colours come from Okabe and Ito's palette
for colour-blind readers (*Color Universal Design*, 2008) and every two roles that a figure
shows together stay apart for deuteranopes, protanopes and tritanopes too (at least
:data:`MIN_DISTANCE` CIEDE2000 apart under simulated dichromacy; ``tests/test_palette.py``
measures it). Colour is never the only cue: validity also has a marker (``o`` valid, ``x`` in
collision) or a hatch, a candidate path is dashed and the final one solid, many lines differ by
line style and marker too (:data:`LINE_STYLES`, :data:`MARKERS`), categories by hatch
(:data:`HATCHES`), and a legend or the title says which is which.

A mark stands out from what it is drawn on (WCAG 2.1, 1.4.11: a contrast of at least 3:1, :func:`contrast`):
by its own colour, or by an outline (:func:`halo`: a black ring, then a white one) where it is drawn on a
picture that runs from dark to light or on colours too near its own. :data:`MARKS_ON` lists, per figure,
the backgrounds and the marks drawn on them; ``tests/test_palette.py`` computes every pair.

- :data:`COLORS` — role name to ``"#rrggbb"`` (``"valid"``, ``"invalid"``, ``"candidate"``, ...);
- :data:`SHOWN_TOGETHER` — the roles each figure (or the viewer) shows side by side;
- :data:`PROBABILITY_CMAP` — the colour map of the viewer's P(valid), dark grey to yellow (monotone in
  lightness, readable in every colour vision; no blue, which means valid), and :func:`probability_rgb`;
- :func:`rgb` — a role's colour as ``(r, g, b)`` bytes, as the viewer draws it;
- :data:`LINE_COLORS`, :data:`LINE_STYLES`, :data:`MARKERS`, :data:`HATCHES` — series a legend names;
- :func:`contrast`, :func:`halo`, :data:`MARKS_ON` — marks that stand out from what they are drawn on;
- :data:`PAGE_WIDTH` — the widest a chapter's figure may be for its text to render at its size.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from matplotlib import patheffects
from matplotlib.colors import LinearSegmentedColormap, to_rgb

OKABE_ITO = {  # Okabe & Ito (2008), the eight colours of Color Universal Design
    "black": "#000000",
    "orange": "#e69f00",
    "sky blue": "#56b4e9",
    "bluish green": "#009e73",
    "yellow": "#f0e442",
    "blue": "#0072b2",
    "vermillion": "#d55e00",
    "reddish purple": "#cc79a7",
}

COLORS: dict[str, str] = {
    # validity (§III): the exact checker's answer
    "valid": OKABE_ITO["blue"],
    "invalid": OKABE_ITO["vermillion"],
    # a classifier's mistakes (§IV-C): kept though in collision, rejected though free
    "dangerous": OKABE_ITO["vermillion"],
    "conservative": OKABE_ITO["sky blue"],
    "boundary": OKABE_ITO["blue"],  # the true C-obstacle's edge
    # planning (notebook 04): roadmap, paths, repairs
    "node": OKABE_ITO["black"],
    "edge": "#7d7d7d",  # 3.1:1 on the C-obstacles' light grey, yet apart from blue for a tritanope
    "candidate": OKABE_ITO["sky blue"],  # dashed: a path the lazy planner has not confirmed yet
    "path": OKABE_ITO["blue"],  # solid: the path returned, checked exactly
    "returned_path": OKABE_ITO["yellow"],  # the path over chapter 03's P(valid) map, where blue outlines the
    # C-obstacles (reader r46c: one blue meant two things)
    "removed": OKABE_ITO["vermillion"],  # what the exact checker rejected during a repair
    "endpoint": OKABE_ITO["black"],  # start (square) and goal (star): roadmap nodes, drawn large
    "rejected": "#4d4d4d",  # samples a sampler threw away: 6:1 on the C-obstacles' grey
    # geometry
    "block": "#888888",  # the workspace's blocks in a figure
    "block_outline": OKABE_ITO["bluish green"],  # blocks over a dark C-space picture: 3.7:1, not "in collision"
    "obstacle": OKABE_ITO["yellow"],  # the viewer's blocks (a hue of their own: the browser test looks for it)
    "trace": OKABE_ITO["sky blue"],  # a path drawn in 3D (the viewer's, and the robot's base in a frame)
    "unchecked": OKABE_ITO["orange"],  # the robot when no validity is given
    "mesh": OKABE_ITO["orange"],
    "voxel": OKABE_ITO["blue"],
    "highlight": OKABE_ITO["vermillion"],  # a region a figure points at (the narrow passage)
    "overlap": OKABE_ITO["yellow"],  # the part of a link inside a block (chapter 01's first check)
    # the CAE's reconstruction errors (§IV-B)
    "phantom": OKABE_ITO["blue"],  # free cell decoded occupied
    "missed": OKABE_ITO["vermillion"],  # occupied cell decoded free
    "ignored": OKABE_ITO["bluish green"],  # a flipped cell decoded as before its flip (review r30b: orange read as
    # the missed cells' vermillion; green is a hue apart from both)
    # lines and shades
    "probability": OKABE_ITO["blue"],  # P(valid) along a path
    "exact": OKABE_ITO["blue"],  # the exact checker's cost (crossover)
    "fcl": "#888888",
    "learned": OKABE_ITO["orange"],  # the network's cost (crossover)
    "ink": OKABE_ITO["black"],  # outlines, reference lines, a curve of its own
    "reference": "#888888",  # a chance or "all free" diagonal, a threshold
    "shade": "#d9d9d9",  # area under a curve
    "free": "#ffffff",  # free space in a C-space picture
    "occupied": "#333333",  # obstacles in a C-space picture or an occupancy grid
    "c_obstacle": "#e0e0e0",  # the C-obstacles behind a roadmap
    "panel_text": "#5c5f66",  # the viewer panel's label text (viser's is 3.3:1 on white; this, 6.3:1)
    "input_border": "#868e96",  # the viewer's input borders (viser's #ced4da is 1.5:1 on white; this, 3.3:1)
    "slider_track": "#868e96",  # the viewer's sliders' unfilled track (viser's #adb5bd is 2.1:1 on white; this, 3.3:1)
}

CATEGORICAL = (OKABE_ITO["blue"], OKABE_ITO["orange"], OKABE_ITO["sky blue"], OKABE_ITO["black"], "#888888", "#ffffff")
"""Colours for filled categories a legend names (furniture kinds, configurations, bars): every two apart, as
roles; each drawn with a black edge and a hatch of its own (:data:`HATCHES`)."""

HATCHES = ("", "//", "..", "xx", "\\\\", "++")
"""Hatches of the categories, in :data:`CATEGORICAL`'s order: a category told without its colour."""

LINE_COLORS = (
    OKABE_ITO["blue"],
    OKABE_ITO["vermillion"],
    OKABE_ITO["black"],
    OKABE_ITO["bluish green"],
    OKABE_ITO["reddish purple"],
    "#7d7d7d",
)
"""Colours of lines and points a legend names (series, models, DoFs): each at least 3:1 on white."""
LINE_STYLES = ("-", "--", "-.", ":")
MARKERS = ("o", "s", "^", "D", "v", "P", "X")
"""Line styles and marker shapes of series, in turn: a series told without its colour (series ``k`` takes
``LINE_COLORS[k % 6]``, ``LINE_STYLES[k % 4]``, ``MARKERS[k % 7]``; :func:`series_style`)."""

MARKER_NAMES = {
    "o": "circles",
    "s": "squares",
    "^": "triangles",
    "D": "diamonds",
    "v": "downward triangles",
    "P": "plus signs",
    "X": "crosses",
}
"""Each of :data:`MARKERS` in words, for a figure's description."""

SHOWN_TOGETHER: dict[str, tuple[str, ...]] = {
    "robot and C-space figures": ("valid", "invalid", "block", "ink"),
    "C-space picture": ("free", "occupied", "block_outline"),
    "C-space slice": ("free", "occupied", "valid", "invalid"),
    "classifier answers": ("free", "occupied", "dangerous", "conservative", "boundary"),
    "classifier probability": ("node", "dangerous", "conservative", "boundary", "returned_path"),
    "sampler figure": ("rejected", "valid", "invalid"),
    "roadmap figure": ("node", "edge", "candidate", "path", "removed", "c_obstacle"),
    "CAE errors": ("phantom", "missed", "occupied"),
    "scene frame": ("valid", "invalid", "trace", "block"),
    "scene frame, unchecked": ("unchecked", "trace", "block"),
    "path profile": ("ink", "probability", "invalid", "reference"),
    "crossover": ("exact", "fcl", "learned"),
    "mesh workspace": ("mesh", "voxel"),
    "viewer": ("valid", "invalid", "obstacle", "trace", "edge", "ink"),
}
"""The roles each figure shows side by side: every two of them must stay apart (``tests/test_palette.py``)."""

PAGE_WIDTH = 6.1  # inches: a chapter page's output column is 631 px at 1280 px (100 dpi; a tight bounding box adds a
# little); a wider figure shrinks, its text with it, so a figure a chapter shows is at most this wide and its text
# stays at 8 pt or more as shown
MIN_DISTANCE = 20.0  # CIEDE2000, between two roles shown together, under each simulated dichromacy
# P(valid): dark grey (0, in collision) to yellow (1, valid), cividis' upper half with its dark blue end greyed
# (reader r50e: blue means valid on the robot the viewer's wireframe is drawn round)
PROBABILITY_CMAP = LinearSegmentedColormap.from_list("P(valid)", ["#4d4d4d", "#7c7b78", "#fee838"])
GREYS_CMAP = "gray_r"  # an occupancy grid: free light, occupied dark
GREY_CMAP = "gray"  # P(valid) under coloured marks (the classifier's mistakes): 0 black, 1 white
SEQUENTIAL_CMAP = "viridis"  # any other quantity on a colour bar


HALO = ("ink", "free")  # a mark's outline, inside out: a black ring, then a white one
MARKS_ON: dict[str, tuple[tuple[str, ...], dict[str, tuple[str, ...]]]] = {
    # figure: (what its marks are drawn on, {mark: its outline rings, inside out}); a name is a role, a colour
    # map ("cmap:NAME", sampled over its range) or a colour
    "classifier probability": (
        ("cmap:" + GREY_CMAP,),
        {"boundary": HALO, "dangerous": HALO, "conservative": HALO, "node": ("free",), "returned_path": HALO},
    ),
    "classifier answers": (
        ("free", "conservative", "occupied", "dangerous"),
        {"boundary": HALO, "conservative": HALO, "dangerous": HALO},  # the mistakes' marks over the cells
    ),
    "classifier mistakes": (("dangerous", "conservative"), {"ink": ()}),  # markers on the wrong cells
    "CAE errors": (("phantom", "missed"), {"ink": ()}),  # markers on the wrongly decoded cells
    "sampler figure": (("free", "c_obstacle"), {"rejected": (), "valid": (), "invalid": HALO, "node": ()}),
    "roadmap figure": (
        ("free", "c_obstacle"),
        {"node": (), "edge": (), "path": (), "candidate": HALO, "removed": HALO, "endpoint": (), "occupied": ()},
    ),
    "narrow passage": (("free", "c_obstacle"), {"highlight": HALO}),
    "C-space picture": (("occupied",), {"block_outline": ()}),  # a block lies inside its C-obstacle
    "C-space slice": (("free", "occupied"), {"valid": ("free",), "invalid": ("free",)}),
    "crossover": (("free",), {"exact": (), "fcl": (), "learned": HALO, "reference": ()}),
    "path profile": (("free", "shade"), {"ink": (), "probability": (), "occupied": ()}),
    "scene frame": (("free",), {"trace": HALO, "ink": ()}),
    "series": (("free",), dict.fromkeys(LINE_COLORS, ())),
}
"""The marks of each figure and what they are drawn on: each stands out at :data:`MIN_CONTRAST` or more."""
MIN_CONTRAST = 3.0  # WCAG 2.1, 1.4.11 (non-text contrast)


def luminance(color: str) -> float:
    """Relative luminance of ``color`` (WCAG 2.1): 0 black, 1 white."""
    channels = np.array(to_rgb(color))
    linear = np.where(channels <= 0.04045, channels / 12.92, ((channels + 0.055) / 1.055) ** 2.4)
    return float(linear @ (0.2126, 0.7152, 0.0722))


def contrast(a: str, b: str) -> float:
    """WCAG 2.1's contrast ratio of two colours (roles or colours): 1 (the same) to 21 (black on white)."""
    low, high = sorted(luminance(COLORS.get(c, c)) for c in (a, b))
    return (high + 0.05) / (low + 0.05)


def halo(linewidth: float = 1.0, rings: tuple[str, ...] = HALO) -> list:
    """Path effects that outline a mark of ``linewidth`` points with ``rings`` (roles, inside out; default a black
    ring, then a white one): it then stands out on any background, dark or light."""
    effects = [
        patheffects.Stroke(linewidth=linewidth + 1.6 * (k + 1), foreground=COLORS[role]) for k, role in enumerate(rings)
    ]
    return effects[::-1] + [patheffects.Normal()]  # the outer ring first, the mark on top


def scene_label() -> dict:
    """Keyword arguments of ``annotate`` for a label on a 3D scene's picture (a block's name, a gap's length): ink
    9-point text, ringed in white so it reads over edges, never clipped by the axes, above the drawing."""
    return dict(fontsize=9, color=COLORS["ink"], zorder=10.0, annotation_clip=False, path_effects=halo(1.0, ("free",)))


def series_style(k: int) -> dict:
    """Colour, line style and marker of the ``k``-th series a legend names (``plot(..., **series_style(k))``)."""
    return dict(
        color=LINE_COLORS[k % len(LINE_COLORS)],
        linestyle=LINE_STYLES[k % len(LINE_STYLES)],
        marker=MARKERS[k % len(MARKERS)],
    )


def rgb(role: str) -> tuple[int, int, int]:
    """The colour of ``role`` as ``(r, g, b)`` bytes (the viewer's format)."""
    if role not in COLORS:
        raise KeyError(f"no colour role {role!r}; the roles are {sorted(COLORS)}")
    code = COLORS[role].lstrip("#")
    return int(code[0:2], 16), int(code[2:4], 16), int(code[4:6], 16)


def probability_rgb(probability: npt.ArrayLike) -> np.ndarray:
    """``(N, 3)`` uint8 colours of probabilities ``(N,)`` on :data:`PROBABILITY_CMAP`."""
    p = np.clip(np.asarray(probability, dtype=float), 0.0, 1.0)  # (N,)
    return np.round(PROBABILITY_CMAP(p)[:, :3] * 255).astype(np.uint8)
