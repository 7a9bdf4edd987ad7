"""Chapter 02's verdicts in words, built here so that the page shows one call, not its formatting (reader r30b: a
20-line helper cell and the answer-filling cell were plumbing on a student page).

- :func:`gap_points`: a score minus its "all free" baseline, in points, as a reader subtracts the printed values;
- :func:`memorized`: section 5's sentence on a CAE's scores: memorized, not yet, or above "all free" on new grids;
- :func:`against_all_free`: one split of a CAE's recorded scores beside "all free";
- :func:`correlation_in_words`: the size of a correlation in a word (section 7);
- :func:`answer`: the table and the answer at the top of the page, in this run's numbers.

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
    *,
    n_seen: int,
    steps: int,
    many_name: str,
    many_seen: int,
    quick: bool,
) -> str:
    """The table and the answer at the top of the page, as Markdown: Table 1's 2DS row (``paper``'s ``seen_acc`` and
    ``unseen_acc``), then CAE-long (this page's, ``steps`` steps on ``n_seen`` grids), CAE-preset (the `paper`
    preset's, recorded) and the CAE on ``many_name``, each beside "all free" (reader r30b: one sentence each, and the
    preset's row in the table the answer points to). The last row's "seen" is ``many_seen`` of its own training grids,
    not the 30 above it, and its label says so (reader r32b)."""
    table = [
        '| CAE (2DS) | seen | unseen | "all free": seen / unseen |',
        "| --- | --- | --- | --- |",
        f"| paper, Table 1 | {paper['seen_acc']:.0%} | {paper['unseen_acc']:.0%} | not reported |",
        _row(f"CAE-long: the paper's layer sizes and loss, {n_seen} grids, {steps:,} steps (this page)", long),
        _row("CAE-preset: the same, stopped early by the `paper` preset (chapters 03–04 load it)", preset),
        _row(
            f"the same layer sizes on {many_name} (not the paper's recipe, section 8); seen and unseen: "
            f"{many_seen} grids each, not the {n_seen} grids and the unseen test grids above",
            many,
        ),
    ]
    seen_said = (
        f"memorizes them: {long['seen_acc']:.1%} of their cells right"
        if long["seen_acc"] >= MEMORIZED
        else f"has trained too briefly in this quick run to memorize them ({long['seen_acc']:.1%})"
    )
    below = gap_points(long["unseen_acc"], long["unseen_all_free"])
    preset_said = (
        "in this quick run, CAE-preset has trained a few steps only"
        if quick
        else "CAE-preset, stopped before it memorizes, reproduces neither column"
    )
    many_unseen, many_free = many["unseen_acc"], many["unseen_all_free"]
    many_said = (
        f'{many_unseen:.1%} on {many_seen} unseen grids, where "all free" gets {many_free:.1%}: better, and still '
        f"{100 * (paper['unseen_acc'] - many_unseen):.0f} points short of {paper['unseen_acc']:.0%}"
        if many_unseen > many_free
        else f'{many_unseen:.1%} on {many_seen} unseen grids ("all free" {many_free:.1%}): in this quick run, '
        "not better yet"
    )
    return "\n".join(table) + (
        f"\n\n**In numbers.** Trained on {n_seen} grids, CAE-long {seen_said}. On unseen grids it gets "
        f'{long["unseen_acc"]:.1%}, where answering "all free" gets {long["unseen_all_free"]:.1%} ({abs(below):.1f} '
        f"points {'below' if below < 0 else 'above'}): it rebuilds a new workspace **no better than answering "
        f'"all free"**, and the paper\'s unseen column does not reproduce. {preset_said[0].upper()}{preset_said[1:]}: '
        f"{against_all_free(preset, 'seen')}, {against_all_free(preset, 'unseen')}. Trained on {many_name}, the same "
        f"layers get {many_said}."
    )


def _row(label: str, scores: Scores) -> str:
    return (
        f"| {label} | {scores['seen_acc']:.1%} | {scores['unseen_acc']:.1%} "
        f"| {scores['seen_all_free']:.1%} / {scores['unseen_all_free']:.1%} |"
    )


def closing_table(paper: Scores, rows: Mapping[str, Scores]) -> str:
    """The closing section's table, as Markdown: Table 1's 2DS row (``paper``'s ``seen_acc`` and ``unseen_acc``),
    then one row per ``rows`` label with its scores beside "all free", and the optimizer every CAE here shares."""
    table = [
        '| 2DS reconstruction accuracy | seen | unseen | "all free" (seen / unseen) |',
        "| --- | --- | --- | --- |",
        f"| paper, Table 1 | {paper['seen_acc']:.0%} | {paper['unseen_acc']:.0%} | not reported |",
    ] + [_row(label, scores) for label, scores in rows.items()]
    return "\n".join(table) + (
        "\n\nEvery CAE in this table trains with Adam (AdamW with its weight decay at 0) where the paper uses "
        "Adagrad at 0.1 (§IV-B3; with our CAE it diverges, "
        "section 4), for a number of steps the paper does not give."
    )
