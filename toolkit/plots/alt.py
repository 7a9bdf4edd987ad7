"""Text alternatives for figures: what a figure shows, in words, for a reader who cannot see it.

Every figure function of :mod:`toolkit.plots` says what it drew, from its data, with the numbers that carry its
conclusion, in plain words (:func:`describe`; no TeX: a screen reader reads ``$\\|z\\|$`` sign by sign by letter); a
figure made by hand gets one line, ``describe(fig, "...")``. Where nobody did, :func:`alt_text` reads the
figure's own titles and axis labels: a guard, never the description a figure ships with
(``tests/test_plots_accessibility.py`` fails on any figure function whose text starts with :data:`FALLBACK`,
``tests/test_site.py`` on any executed chapter's figure). In a notebook, :func:`register` (run when
:mod:`toolkit.plots` is imported in IPython) attaches the text to every displayed figure as
Jupyter's ``{"image/png": {"alt": ...}}`` output metadata, which JupyterLab, nbconvert
and the course site (mkdocs-jupyter) render as the ``<img>``'s ``alt``.

>>> from matplotlib.figure import Figure
>>> alt_text(describe(Figure(), "two points, both valid"))
'two points, both valid'
"""

from __future__ import annotations

import sys

from matplotlib.figure import Figure

ATTRIBUTE = "toolkit_alt_text"  # where a figure keeps its description
FALLBACK = "Figure with "  # how a text read from titles begins
TEX = ("$", "\\")  # what a plain-words description never holds


def describe(fig: Figure, text: str) -> Figure:
    """Attach the text alternative ``text`` to ``fig`` (replacing any); returns ``fig``."""
    if not text.strip():
        raise ValueError("a figure's text alternative must say something")
    if any(mark in text for mark in TEX):
        raise ValueError(f"a figure's text alternative is plain words, not TeX: {text[:80]!r}")
    setattr(fig, ATTRIBUTE, " ".join(text.split()))
    return fig


def alt_text(fig: Figure) -> str:
    """The text alternative of ``fig``: its description, or one read from its titles and axis labels."""
    described = getattr(fig, ATTRIBUTE, None)
    if described:
        return described
    panels = []
    for ax in fig.axes:
        words = [ax.get_title()] + [
            f"{axis}: {label}" for axis, label in (("x", ax.get_xlabel()), ("y", ax.get_ylabel())) if label
        ]
        if any(words):
            panels.append(", ".join(w for w in words if w))
    title = fig.get_suptitle() if hasattr(fig, "get_suptitle") else ""
    text = "; ".join(p for p in [title, *panels] if p)
    return " ".join(f"{FALLBACK}{len(fig.axes)} panel(s): {text or 'no titles'}".split())


def is_fallback(text: str) -> bool:
    """Whether ``text`` is the guard's, read from titles, rather than a description of the data."""
    return text.startswith(FALLBACK)


def metadata(fig: Figure) -> tuple[dict, dict]:
    """IPython's mime-bundle formatter for a figure: no data of its own (the PNG comes from matplotlib's
    formatter), the alt text as the PNG's metadata."""
    return {}, {"image/png": {"alt": alt_text(fig)}}


def register() -> bool:
    """In an IPython kernel, give every displayed matplotlib figure its alt text; False outside IPython."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is None:
        return False
    shell.display_formatter.mimebundle_formatter.for_type(Figure, metadata)
    return True
