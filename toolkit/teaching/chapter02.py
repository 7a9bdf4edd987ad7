"""Chapter 02's verdicts in words, built here so that the page shows one call, not its formatting (reader r30b: a
20-line helper cell and the answer-filling cell were plumbing on a student page).

- :func:`gap_points`: a score minus its "all free" baseline, in points, as a reader subtracts the printed values;
- :func:`memorized`: section 5's sentence on a CAE's scores: memorized, not yet, or above "all free" on new grids;
- :func:`against_all_free`: one split of a CAE's recorded scores beside "all free"; :func:`beside_all_free` the same
  from a score and its baseline;
- :func:`correlation_in_words`: the size of a correlation in a word (section 7);
- :func:`answer`: the table and the answer at the top of the page, in this run's numbers: the verdict from the new
  grids, the test grids beside it.

Scores are shares (0.866, not 86.6) and come in mappings with the keys of
:func:`toolkit.learning.training.evaluate`'s CAE part: ``seen_acc``, ``unseen_acc``, ``seen_all_free``,
``unseen_all_free``.
"""

from __future__ import annotations

from collections.abc import Mapping

Scores = Mapping[str, float]

MEMORIZED = 0.98  # a CAE at or above this share of its training grids' cells has stored them
COUPLE = 0.02  # "no better than 'all free'": under two points above it


def gap_points(share: float, baseline: float) -> float:
    """``share - baseline`` in percentage points, from the two as printed with one decimal, so that a reader's
    subtraction of the printed values gives the printed gap (review r27b)."""
    return round(float(f"{share:.1%}"[:-1]) - float(f"{baseline:.1%}"[:-1]), 1)


def memorized(scores: Scores, steps: int = 1500) -> str:
    """What a CAE's scores say: not memorized yet (below :data:`MEMORIZED` on its training grids; memorizing takes
    more steps, the full-size run trains ``steps``), memorized (and no better than "all free" on new grids), or near
    perfect on its training grids and above "all free" on new ones."""
    seen, unseen = scores["seen_acc"], scores["unseen_acc"]
    seen_free, unseen_free = scores["seen_all_free"], scores["unseen_all_free"]
    said = f"seen {seen:.1%} (all free {seen_free:.1%}), unseen {unseen:.1%} (all free {unseen_free:.1%})"
    if seen < MEMORIZED:
        return (
            f"{said}: not memorized yet. On its training grids it scores {gap_points(seen, seen_free):+.1f} points "
            f"against answering 'all free'; memorizing takes more steps (the full-size run trains {steps:,})."
        )
    if unseen < unseen_free + COUPLE:
        return f"{said}: memorized. Near perfect on its training grids, no better than 'all free' on new ones."
    return f"{said}: near perfect on its training grids, and above 'all free' on new ones."


def against_all_free(scores: Scores, split: str) -> str:
    """``"seen 89.2% (all free 88.6%: +0.6 points, about level with it)"``: one split's score beside its baseline, the
    gap as the difference of the printed values, and its side in words (level within a point)."""
    acc, free = scores[f"{split}_acc"], scores[f"{split}_all_free"]
    gap = gap_points(acc, free)
    where = "about level with it" if abs(gap) < 1 else ("above it" if gap > 0 else "below it")
    return f"{split} {acc:.1%} (all free {free:.1%}: {gap:+.1f} points, {where})"


def correlation_in_words(r: float) -> str:
    """The size of a correlation ``r`` in a word: weak below 0.3, moderate below 0.7, strong from 0.7 (its sign
    ignored: a principal direction can point either way)."""
    size = abs(r)
    return "weak" if size < 0.3 else ("moderate" if size < 0.7 else "strong")


def answer(
    paper: Scores,
    long: Scores,
    preset: Scores,
    many: Scores,
    new: Scores,
    *,
    n_seen: int,
    n_test: int,
    steps: int,
    many_name: str,
    n_new: int,
    quick: bool,
) -> str:
    """The table and the answer at the top of the page, as Markdown (reader r33b: the verdict read from the test of
    ``n_new`` new grids, not from the ``n_test`` test grids alone; each column says which grids it scores).

    ``paper``: Table 1's 2DS row (``seen_acc``, ``unseen_acc``); ``long``: CAE-long (``steps`` steps on ``n_seen``
    grids) on its training grids and the test grids; ``preset``: CAE-preset's recorded scores; ``many``: the CAE on
    ``many_name``, ``seen`` being ``n_new`` of its own training grids and ``unseen`` the ``n_new`` new grids.
    ``new``: on those new grids, CAE-long's and CAE-preset's accuracy (``long_acc``, ``preset_acc``; reader r34b:
    CAE-preset is loaded, so scoring it there is a forward pass) and how many of them CAE-long rebuilds better than
    "all free" (``long_above``); the many-grids CAE's accuracy on the test grids (``many_test``); CAE-long's lowest and
    highest gap to "all free" on single test grids in points (``low``, ``high``). What each CAE's codes follow is said
    in sections 7 and 8 only (reader r35b: the opening to one screen)."""
    free = many["unseen_all_free"]  # "all free" on the new grids, the same for every CAE scored there
    table = [
        f"| CAE (2DS) | its training grids | the {n_test} unseen test grids | {n_new} new grids (the first {n_test} "
        "the test grids) |",
        "| --- | --- | --- | --- |",
        f"| paper, Table 1 | {paper['seen_acc']:.0%} | {paper['unseen_acc']:.0%} | not reported |",
        f"| CAE-long: the paper's layer sizes and loss, {n_seen} grids, {steps:,} steps (this page) "
        f"| {_cell(long['seen_acc'], long['seen_all_free'])} | {_cell(long['unseen_acc'], long['unseen_all_free'])} "
        f"| {_cell(new['long_acc'], free)} |",
        "| CAE-preset: the same, stopped early by the `paper` preset (loaded; chapters 03–04 use it) "
        f"| {_cell(preset['seen_acc'], preset['seen_all_free'])} "
        f"| {_cell(preset['unseen_acc'], preset['unseen_all_free'])} | {_cell(new['preset_acc'], free)} |",
        f"| the same layer sizes on {many_name} (not the paper's recipe, section 8) "
        f"| {n_new} of them: {_cell(many['seen_acc'], many['seen_all_free'])} "
        f"| {_cell(new['many_test'], long['unseen_all_free'])} | {_cell(many['unseen_acc'], free)} |",
    ]
    return (
        "\n".join(table) + "\n\n" + _in_numbers(paper, long, preset, many, new, n_seen, n_test, many_name, n_new, quick)
    )


def _spread(low: float, high: float, n_test: int) -> str:
    """Single test grids' gaps to "all free", in points; where they lie on both sides of it, what that says of the
    ``n_test`` grids' means (readers r33b, r34b: a point or two on 10 grids read as a measured deficit)."""
    said = f"single test grids lie from {low:+.1f} to {high:+.1f} points of it for CAE-long (section 5)"
    if low < 0 < high:
        too_few = f'The {n_test} test grids alone are too few to tell a point or two below "all free" from level'
        return f"{too_few}: {said}."
    return f'On the {n_test} test grids alone, against "all free", {said}.'


def _cell(acc: float, free: float) -> str:
    return f"{acc:.1%} (all free {free:.1%})"


def beside_all_free(acc: float, free: float) -> str:
    """``"86.5% (all free 87.8%: -1.3 points, below it)"``: as :func:`against_all_free`, from the two shares."""
    return against_all_free({"x_acc": acc, "x_all_free": free}, "x")[2:]


def _in_numbers(
    paper: Scores,
    long: Scores,
    preset: Scores,
    many: Scores,
    new: Scores,
    n_seen: int,
    n_test: int,
    many_name: str,
    n_new: int,
    quick: bool,
) -> str:
    """The answer's paragraph under the table, in three sentences on the new grids (CAE-long's verdict, CAE-preset,
    the many-grids CAE) and the test grids' caveat."""
    seen_said = (
        f"memorizes them: {long['seen_acc']:.1%} of their cells right"
        if long["seen_acc"] >= MEMORIZED
        else f"has trained too briefly in this quick run to memorize them ({long['seen_acc']:.1%})"
    )
    free = many["unseen_all_free"]
    gap = gap_points(new["long_acc"], free)
    preset_said = (
        "in this quick run, CAE-preset has trained a few steps only"
        if quick
        else "CAE-preset, stopped before it memorizes, reproduces neither column"
    )
    many_unseen = many["unseen_acc"]
    many_said = (
        f'{many_unseen:.1%} on the same {n_new} new grids: better than "all free", and still '
        f"{100 * (paper['unseen_acc'] - many_unseen):.0f} points short of {paper['unseen_acc']:.0%}"
        if many_unseen > free
        else f"{many_unseen:.1%} on the same {n_new} new grids: in this quick run, not better yet"
    )
    return (
        f"**In numbers.** Trained on {n_seen} grids, CAE-long {seen_said}. On {n_new} new grids it gets "
        f'{new["long_acc"]:.1%}, where answering "all free" gets {free:.1%} ({abs(gap):.1f} points '
        f"{'below' if gap < 0 else 'above'}; {int(new['long_above'])} of the {n_new} grids above it): it rebuilds a "
        f'new workspace **no better than answering "all free"**, and the paper\'s unseen column does not reproduce. '
        f"{preset_said[0].upper()}{preset_said[1:]}: {against_all_free(preset, 'seen')}; on the same {n_new} new "
        f"grids {beside_all_free(new['preset_acc'], free)}. Trained on {many_name}, the same layers get {many_said}. "
        f"{_spread(new['low'], new['high'], n_test)}"
    )


def _row(label: str, scores: Scores) -> str:
    return (
        f"| {label} | {scores['seen_acc']:.1%} | {scores['unseen_acc']:.1%} "
        f"| {scores['seen_all_free']:.1%} / {scores['unseen_all_free']:.1%} |"
    )


def closing_table(paper: Scores, rows: Mapping[str, Scores], unseen: str = "unseen") -> str:
    """The closing section's table, as Markdown: Table 1's 2DS row (``paper``'s ``seen_acc`` and ``unseen_acc``),
    then one row per ``rows`` label with its scores beside "all free", and the optimizer every CAE here shares.
    ``unseen`` heads the unseen column: every row of ours scores one set of grids (reader r34b), it names it; the
    paper's cell says its 100 % is on the paper's own 10 unseen grids (reader r35b)."""
    table = [
        f'| 2DS reconstruction accuracy | seen | {unseen} | "all free" (seen / unseen) |',
        "| --- | --- | --- | --- |",
        f"| paper, Table 1 | {paper['seen_acc']:.0%} | {paper['unseen_acc']:.0%} on its own 10 unseen grids (§IV-A) "
        "| not reported |",
    ] + [_row(label, scores) for label, scores in rows.items()]
    return "\n".join(table) + (
        "\n\nEvery CAE in this table trains with Adam (AdamW with its weight decay at 0) where the paper uses "
        "Adagrad at 0.1 (§IV-B3; with our CAE it diverges, "
        "the aside after section 8), for a number of steps the paper does not give."
    )
