"""The toolkit's colours: one role, one colour, the same in every figure and in the viewer.

One man in twelve sees colour differently, so the colours come from Okabe and Ito's palette
for colour-blind readers (*Color Universal Design*, 2008) and every two roles that a figure
shows together stay apart for deuteranopes, protanopes and tritanopes too (at least
:data:`MIN_DISTANCE` CIEDE2000 apart under simulated dichromacy; ``tests/test_palette.py``
measures it). Colour is never the only cue: validity also has a marker (``o`` valid, ``x`` in
collision) or a hatch, a candidate path is dashed and the final one solid, and a legend or the
title says which is which.

- :data:`COLORS` — role name to ``"#rrggbb"`` (``"valid"``, ``"invalid"``, ``"candidate"``, ...);
- :data:`SHOWN_TOGETHER` — the roles each figure (or the viewer) shows side by side;
- :data:`PROBABILITY_CMAP` — the colour map of a continuous probability (cividis: monotone in
  lightness, readable in every colour vision), and :func:`probability_rgb` for the viewer;
- :func:`rgb` — a role's colour as ``(r, g, b)`` bytes, as the viewer draws it.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import numpy.typing as npt

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
    "edge": "#888888",
    "candidate": OKABE_ITO["sky blue"],  # dashed: a path the lazy planner has not confirmed yet
    "path": OKABE_ITO["blue"],  # solid: the path returned, checked exactly
    "removed": OKABE_ITO["vermillion"],  # what the exact checker rejected during a repair
    "endpoint": OKABE_ITO["black"],  # start (square) and goal (star): roadmap nodes, drawn large
    "rejected": "#888888",  # samples a sampler threw away
    # geometry
    "block": "#888888",  # the workspace's blocks in a figure
    "block_outline": OKABE_ITO["orange"],  # blocks outlined over a dark C-space picture
    "obstacle": OKABE_ITO["yellow"],  # the viewer's blocks (a hue of their own: the browser test looks for it)
    "trace": OKABE_ITO["sky blue"],  # a path drawn in 3D (the viewer's, and the robot's base in a frame)
    "unchecked": OKABE_ITO["orange"],  # the robot when no validity is given
    "mesh": OKABE_ITO["orange"],
    "voxel": OKABE_ITO["blue"],
    "highlight": OKABE_ITO["vermillion"],  # a region a figure points at (the narrow passage)
    # the CAE's reconstruction errors (§IV-B)
    "phantom": OKABE_ITO["blue"],  # free cell decoded occupied
    "missed": OKABE_ITO["vermillion"],  # occupied cell decoded free
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
}

CATEGORICAL = (OKABE_ITO["blue"], OKABE_ITO["orange"], OKABE_ITO["sky blue"], OKABE_ITO["black"], "#888888", "#ffffff")
"""Colours for categories a legend names (furniture kinds, configurations, series): every two apart, as roles."""

SHOWN_TOGETHER: dict[str, tuple[str, ...]] = {
    "robot and C-space figures": ("valid", "invalid", "block", "ink"),
    "C-space picture": ("free", "occupied", "block_outline"),
    "C-space slice": ("free", "occupied", "valid", "invalid"),
    "classifier answers": ("free", "occupied", "dangerous", "conservative", "boundary"),
    "classifier probability": ("node", "dangerous", "path"),
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

MIN_DISTANCE = 20.0  # CIEDE2000, between two roles shown together, under each simulated dichromacy
PROBABILITY_CMAP = "cividis"  # P(valid): dark blue (0, in collision) to yellow (1, valid)
GREYS_CMAP = "gray_r"  # an occupancy grid: free light, occupied dark
GREY_CMAP = "gray"  # P(valid) under coloured marks (the classifier's mistakes): 0 black, 1 white
SEQUENTIAL_CMAP = "viridis"  # any other quantity on a colour bar


def rgb(role: str) -> tuple[int, int, int]:
    """The colour of ``role`` as ``(r, g, b)`` bytes (the viewer's format)."""
    if role not in COLORS:
        raise KeyError(f"no colour role {role!r}; the roles are {sorted(COLORS)}")
    code = COLORS[role].lstrip("#")
    return int(code[0:2], 16), int(code[2:4], 16), int(code[4:6], 16)


def probability_rgb(probability: npt.ArrayLike) -> np.ndarray:
    """``(N, 3)`` uint8 colours of probabilities ``(N,)`` on :data:`PROBABILITY_CMAP`."""
    p = np.clip(np.asarray(probability, dtype=float), 0.0, 1.0)  # (N,)
    return np.round(matplotlib.colormaps[PROBABILITY_CMAP](p)[:, :3] * 255).astype(np.uint8)
