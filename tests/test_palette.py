"""The palette (:mod:`toolkit.plots.palette`): colours a colour-blind student tells apart, used everywhere.

Distances are CIEDE2000 (colour-science) between colours as a dichromat sees them, simulated by Brettel,
Viénot and Mollon (1997) at full severity (daltonlens).
"""

from __future__ import annotations

import ast
import itertools
import re
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from matplotlib.colors import to_hex

from toolkit.plots import palette

colour = pytest.importorskip("colour")
simulate = pytest.importorskip("daltonlens.simulate")

ROOT = Path(__file__).resolve().parents[1]
DEFICIENCIES = {"deuteranopia": "DEUTAN", "protanopia": "PROTAN", "tritanopia": "TRITAN"}


def seen_as(hex_colors: list[str], deficiency: str | None) -> np.ndarray:
    """``(N, 3)`` sRGB bytes of ``hex_colors`` as a dichromat with ``deficiency`` sees them (None: as given)."""
    pixels = np.array([[int(h[i : i + 2], 16) for i in (1, 3, 5)] for h in hex_colors], dtype=np.uint8)[None]
    if deficiency is not None:
        simulator = simulate.Simulator_Brettel1997()
        pixels = simulator.simulate_cvd(pixels, getattr(simulate.Deficiency, DEFICIENCIES[deficiency]), severity=1.0)
    return pixels[0]


def ciede2000(a: np.ndarray, b: np.ndarray) -> float:
    lab = [colour.XYZ_to_Lab(colour.sRGB_to_XYZ(np.asarray(c, float) / 255)) for c in (a, b)]
    return float(colour.delta_E(*lab, method="CIE 2000"))


def closest_pair(roles: tuple[str, ...], deficiency: str | None) -> tuple[float, tuple[str, str]]:
    seen = dict(zip(roles, seen_as([palette.COLORS[r] for r in roles], deficiency)))
    return min((ciede2000(seen[a], seen[b]), (a, b)) for a, b in itertools.combinations(roles, 2))


def test_the_distance_is_ciede2000_and_the_simulation_is_brettels():
    assert ciede2000(np.array([0, 0, 0]), np.array([255, 255, 255])) == pytest.approx(100, abs=0.1)
    # the measurement: matplotlib's tab:green / tab:red look alike to a deuteranope
    green, red = seen_as(["#2ca02c", "#d62728"], "deuteranopia")
    assert ciede2000(green, red) < 10 < ciede2000(*seen_as(["#2ca02c", "#d62728"], None))


@pytest.mark.parametrize("deficiency", [None, *DEFICIENCIES])
def test_every_two_roles_shown_together_stay_apart(deficiency):
    for figure, roles in palette.SHOWN_TOGETHER.items():
        assert set(roles) <= set(palette.COLORS), figure
        distance, pair = closest_pair(roles, deficiency)
        assert distance >= palette.MIN_DISTANCE, f"{figure}: {pair} {distance:.1f} apart for {deficiency}"


@pytest.mark.parametrize("deficiency", [None, *DEFICIENCIES])
def test_the_categorical_colours_stay_apart(deficiency):
    seen = seen_as(list(palette.CATEGORICAL), deficiency)
    distance = min(ciede2000(a, b) for a, b in itertools.combinations(seen, 2))
    assert distance >= palette.MIN_DISTANCE, f"{distance:.1f} for {deficiency}"


def test_valid_and_invalid_are_okabe_ito_and_roles_read_as_bytes():
    assert {palette.COLORS["valid"], palette.COLORS["invalid"]} <= set(palette.OKABE_ITO.values())
    assert palette.rgb("invalid") == (0xD5, 0x5E, 0x00)
    with pytest.raises(KeyError, match="no colour role 'green'"):
        palette.rgb("green")
    ends = palette.probability_rgb([0.0, 1.0])
    assert ends.shape == (2, 3) and ends[0].sum() < ends[1].sum()  # dark grey at 0, yellow at 1
    assert all(b <= max(r, g) for r, g, b in palette.probability_rgb(np.linspace(0, 1, 65)))  # never blue (r50e)


# ---- no colour outside the palette ----

NAMED = {"red", "green", "blue", "orange", "gold", "purple", "cyan", "magenta", "yellow", "gray", "grey", "black"}
NAMED |= {"white", "brown", "pink", "limegreen", "lightgray", "deepskyblue", "navy", "teal", "olive", "violet"}
LITERAL = re.compile(r"^(tab:\w+|c\d|#[0-9a-f]{3}([0-9a-f]{3})?)$")
COLOUR_ARGUMENT = re.compile(r"^(c|colou?rs?|\w*colou?rs?|cmap|fc|ec|mfc|mec)$", re.I)


def colour_literals(source: str) -> list[str]:
    """Colours written into ``source``: named or coded colours in strings, and strings, numbers or RGB
    tuples given to a colour argument (``color=``, ``edgecolor=``, ``cmap=``, ...)."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            text = node.value.strip().lower()
            if text in NAMED or LITERAL.match(text):
                found.append(f"line {node.lineno}: {node.value!r}")
        elif isinstance(node, ast.JoinedStr) and re.match(r"C\{", ast.unparse(node)[2:]):
            found.append(f"line {node.lineno}: {ast.unparse(node)}")
        elif isinstance(node, ast.keyword) and node.arg and COLOUR_ARGUMENT.match(node.arg):
            value = node.value
            items = value.elts if isinstance(value, ast.Tuple | ast.List) else [value]
            if any(isinstance(v, ast.JoinedStr) or (isinstance(v, ast.Constant) and v.value != "none") for v in items):
                found.append(f"line {node.lineno}: {node.arg}={ast.unparse(node.value)}")
    for node in ast.parse(source).body:  # a module's constant (r, g, b) bytes
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Tuple) and len(node.value.elts) == 3:
            values = [e.value for e in node.value.elts if isinstance(e, ast.Constant) and isinstance(e.value, int)]
            if len(values) == 3 and all(0 <= v <= 255 for v in values) and max(values) > 1:
                found.append(f"line {node.lineno}: {ast.unparse(node)}")
    return found


def test_the_literal_finder_finds_each_kind_of_colour():
    source = (
        'a = "tab:red"\nb = "#00ff00"\nf(color="0.5")\nf(edgecolor=(0.2, 0.2, 0.2))\nc = "green"\n'
        "PATH = (0, 170, 200)\nf(cmap='viridis')\nd = f'C{i}'\n"
    )
    assert len(colour_literals(source)) == 8
    assert colour_literals('f(color=COLORS["valid"], shape=(3, 4, 5), label="k", x="C-space")') == []


def test_no_colour_is_written_outside_the_palette():
    sources = [p for folder in ("toolkit/plots", "toolkit/viewer") for p in sorted((ROOT / folder).glob("*.py"))]
    found = {
        str(p.relative_to(ROOT)): hits
        for p in sources
        if p.name != "palette.py" and (hits := colour_literals(p.read_text()))
    }
    assert found == {}


# ---- marks that stand out (WCAG 2.1, 1.4.11: 3:1 against what they are drawn on) ----


def backgrounds(names: tuple[str, ...]) -> list[str]:
    """The colours of ``names``: roles, colours, or a colour map sampled at 65 points over its range."""
    found = []
    for name in names:
        if name.startswith("cmap:"):
            found += [to_hex(c) for c in matplotlib.colormaps[name[5:]](np.linspace(0, 1, 65))]
        else:
            found.append(palette.COLORS.get(name, name))
    return found


def stands_out(mark: str, rings: tuple[str, ...], background: str) -> bool:
    """Whether ``mark`` is told from ``background`` at 3:1: by its own colour, or by one of its outline's rings that
    every boundary inside it (mark to first ring, ring to ring) keeps at 3:1 too."""
    layers = [palette.COLORS.get(mark, mark), *(palette.COLORS[r] for r in rings)]
    for k, layer in enumerate(layers):
        if k and palette.contrast(layers[k - 1], layer) < palette.MIN_CONTRAST:
            return False
        if palette.contrast(layer, background) >= palette.MIN_CONTRAST:
            return True
    return False


def test_the_contrast_is_wcag_s():
    assert palette.contrast("#000000", "#ffffff") == pytest.approx(21.0)
    assert palette.contrast("#767676", "#ffffff") == pytest.approx(4.54, abs=0.01)  # WebAIM's AA grey on white
    assert palette.contrast("valid", "valid") == 1.0
    # the measurements: the candidate path on white, the crossover's orange
    assert palette.contrast("candidate", "free") == pytest.approx(2.31, abs=0.01)
    assert palette.contrast("learned", "free") == pytest.approx(2.25, abs=0.01)
    assert not stands_out("candidate", (), "#ffffff") and stands_out("candidate", palette.HALO, "#ffffff")


def test_an_outline_makes_a_mark_stand_out_on_any_grey():
    greys = backgrounds(("cmap:gray",))
    assert not all(stands_out("conservative", (), g) for g in greys)
    assert all(stands_out(mark, palette.HALO, g) for mark in ("valid", "invalid", "conservative") for g in greys)


@pytest.mark.parametrize("figure", sorted(palette.MARKS_ON))
def test_every_mark_stands_out_from_what_it_is_drawn_on(figure):
    drawn_on, marks = palette.MARKS_ON[figure]
    faint = [
        f"{mark} on {bg}: {palette.contrast(palette.COLORS.get(mark, mark), bg):.2f}"
        for mark, rings in marks.items()
        for bg in backgrounds(drawn_on)
        if not stands_out(mark, rings, bg)
    ]
    assert faint == []


def test_series_colours_stand_out_on_white_and_the_halo_draws_its_rings():
    assert all(palette.contrast(c, "#ffffff") >= palette.MIN_CONTRAST for c in palette.LINE_COLORS)
    inner, outer = palette.halo(2.0)[1], palette.halo(2.0)[0]  # drawn outer ring first, the mark last
    assert (inner._gc["foreground"], outer._gc["foreground"]) == (palette.COLORS["ink"], palette.COLORS["free"])
    assert inner._offset == outer._offset == (0, 0)
