"""Chapter 03's tables and verdicts, built here so that the page shows them, not their formatting (reader r27c: a
17-line code cell stood between the verdict and its table).

- :func:`opening_table`: the verdict's table, the paper's Table 2 and the full-size runs recorded in
  ``docs/results.md``;
- :func:`mistakes_table`: section 3's mistakes on the P(valid) maps, how many lie near a boundary, where the
  dangerous ones are;
- :func:`score_unseen`: section 4's scores of each model and of "always valid" on unseen workspaces' samples;
- :func:`slice_verdict`: section 5's verdict on a slice, its counts and words;
- :func:`threshold_explorer`: section 6's slider over the decision maps;
- :func:`closing_table`, :func:`other_runs` and :func:`implied_shares`: the closing section's table (each recorded run
  above this page's draw of it), its folded box of other runs, and the lines under it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping

import numpy as np

from toolkit.experiments import paper_numbers
from toolkit.geometry.collision import exact_checker
from toolkit.learning import data, metrics
from toolkit.learning.learned import LearnedChecker
from toolkit.plots import answers
from toolkit.plots.slices import CSpaceSlice
from toolkit.teaching import recorded

NAMES = {"2ds": "2DS", "3dc7": "3DC-7"}


def opening_table() -> str:
    """The paper's unseen 2DS and 3DC-7 rows (its reported accuracy, and the balanced accuracy its TPR and TNR give)
    and the recorded runs' balanced accuracy, TPR and TNR on unseen workspaces' balanced samples, as a Markdown table;
    its row labels say what a preset and 3DC-7 are (reader r29c: defined in a trailing parenthesis, after their first
    use; reader r32c: the `strong` 3DC-7 row had no paper row to set it beside)."""
    rows = [
        "| model, unseen workspaces | balanced accuracy | TPR (valid kept) | TNR (collisions rejected) |",
        "| --- | ---: | ---: | ---: |",
    ]
    for who, scenario in OPENING:  # the paper's row above ours of the same robot (reader r32c: none for 3DC-7)
        if who == "Table 2":
            published = paper_numbers.MLP[scenario]["unseen"]
            label, said = OPENING[who, scenario], f"its accuracy, as reported: {published['acc']:.0%}"
            label = f"{label[:-1]}; {said})" if label.endswith(")") else f"{label} ({said})"
            rows.append(
                f"| {label} "
                f"| {(published['tpr'] + published['tnr']) / 2:.1%} | {published['tpr']:.0%} | {published['tnr']:.0%} |"
            )
            continue
        row = recorded.table(who, "MLP accuracy")[scenario]  # scored on balanced samples of unseen workspaces
        rows.append(
            f"| {OPENING[who, scenario]} | {recorded.ours(row['Balanced unseen Acc']):.0%} "
            f"| {recorded.ours(row['TPR']):.0%} | {recorded.ours(row['TNR']):.0%} |"
        )
    return "\n".join(rows)


OPENING = {  # the opening table's row labels: each says what it is, 3DC-7 where it first appears
    ("Table 2", "2ds"): "the paper's MLP, its Table 2, 2DS",
    ("paper", "2ds"): "our `paper` preset (the toolkit's training recipe of the paper's MLP), 2DS, recorded run",
    ("strong", "2ds"): "our `strong` preset (our own recipe), 2DS, recorded run",
    ("Table 2", "3dc7"): "the paper's MLP, its Table 2, 3DC-7 (a 7-DoF chain of two boxes in 3D, section 5)",
    ("strong", "3dc7"): "our `strong` preset, 3DC-7, recorded run",
}


def mistakes_table(
    probability: Mapping[str, np.ndarray], thresholds: Mapping[str, float], valid, grid: CSpaceSlice, near: int
) -> str:
    """Per model (``probability[name] (nx, ny)`` against ``valid (nx, ny)`` at ``thresholds[name]``): the cells wrong
    and the share within ``near`` cells of a boundary, the conservative and dangerous cells, and the box that holds the
    dangerous ones, as a Markdown table."""
    rows = [
        "| model | cells wrong (share of all cells); share of them near a boundary | conservative "
        "| dangerous; share of them near a boundary | the dangerous cells lie within |",
        "| --- | ---: | ---: | ---: | --- |",
    ]
    for preset, p in probability.items():
        kept = p >= thresholds[preset]  # (nx, ny) bool
        wrong, near_all = answers.mistakes_near_boundary(kept, valid, cells=near)
        dangerous, near_d = answers.mistakes_near_boundary(kept | valid, valid, cells=near)  # obstacle cells kept only
        i, j = np.nonzero(kept & ~valid)  # the dangerous cells' indices
        box = (
            f"x {grid.axes[0][i].min():.1f} to {grid.axes[0][i].max():.1f}, "
            f"y {grid.axes[1][j].min():.1f} to {grid.axes[1][j].max():.1f}"
            if len(i)
            else "none"
        )
        share_d = f"{dangerous:,}; {near_d:.0%} near a boundary" if dangerous else "0"
        rows.append(
            f"| `{preset}` | {wrong:,} of {valid.size:,} ({share(wrong / valid.size)}); {near_all:.0%} near a boundary "
            f"| {np.sum(~kept & valid):,} | {share_d} | {box} |"
        )
    return "\n".join(rows)


def share(fraction: float) -> str:
    """A share as a percentage, with a decimal below 1 % so that a nonzero share never reads 0 % (reader r28c: "39 of
    10,000 (0%)")."""
    if 0 < fraction < 0.001:
        return "under 0.1%"
    return f"{fraction:.1%}" if 0 < fraction < 0.01 else f"{fraction:.0%}"


def score_unseen(scenario, models: Mapping, thresholds: Mapping[str, float], n: int, per_workspace: int, seed: int):
    """Section 4's measurement: on ``n`` unseen workspaces of ``scenario``, ``per_workspace`` balanced samples (half
    valid, as training uses) and as many validity-blind ones (uniform: one reading of the paper's unseen test), each
    of ``models`` (``{preset: TrainedModels}``) answering at ``thresholds[preset]``. Returns ``truth[kind] (N,)``
    bool, ``predicted_p[preset, kind] (N,)`` P(valid), and ``scores["preset\\nkind"]`` (and ``"always valid\\nkind"``)
    as :func:`toolkit.learning.metrics.classification` gives them."""
    truth: dict[str, list] = {"balanced": [], "validity-blind": []}  # per workspace: (per_workspace,) bool
    predicted: dict[tuple[str, str], list] = {(preset, kind): [] for preset in models for kind in truth}
    for i, ws in enumerate(scenario.workspaces("unseen", n, seed)):
        exact = exact_checker(ws, scenario.robot)
        rng = np.random.default_rng([seed, i])
        q_balanced, valid_balanced = data.balanced_samples(exact, rng, per_workspace)  # 50 % valid
        q_blind = scenario.robot.sample(rng, per_workspace)  # uniform (validity-blind)
        truth["balanced"].append(valid_balanced)
        truth["validity-blind"].append(exact.are_valid(q_blind))
        for preset, m in models.items():
            checker = LearnedChecker(ws, m)
            for kind, q in (("balanced", q_balanced), ("validity-blind", q_blind)):
                predicted[preset, kind].append(checker.probability(q))
    valid = {kind: np.concatenate(v) for kind, v in truth.items()}
    predicted_p = {key: np.concatenate(v) for key, v in predicted.items()}
    scores = {}
    for kind, v in valid.items():
        for preset in models:
            scores[f"{preset}\n{kind}"] = metrics.classification(predicted_p[preset, kind] >= thresholds[preset], v)
        scores[f"always valid\n{kind}"] = metrics.classification(np.ones_like(v), v)
    return valid, predicted_p, scores


def slice_verdict(p, truth, threshold: float, near: int) -> str:
    """What a map of P(valid) ``p (nx, ny)`` says against ``truth (nx, ny)``: how much obstacle it misses, and where
    its mistakes lie (within ``near`` cells of a boundary or away from any)."""
    kept = p >= threshold
    wrong, near_all = answers.mistakes_near_boundary(kept, truth, cells=near)
    # each kind alone: counted as wrong only where that kind of mistake is made
    conservative, near_c = answers.mistakes_near_boundary(kept & truth, truth, cells=near)  # free cells rejected
    dangerous, near_d = answers.mistakes_near_boundary(kept | truth, truth, cells=near)  # obstacle cells kept
    far_c, far_d = round(conservative * (1 - near_c)), round(dangerous * (1 - near_d))
    missed, rejected = np.mean(kept[~truth]), np.mean(~kept[truth])  # obstacle cells called valid; free ones rejected
    counts = (
        f"{wrong} of {truth.size} cells wrong, {int(100 * near_all)}% of them near a boundary; {missed:.0%} of the "
        f"C-obstacle's cells called valid, {rejected:.0%} of the free ones rejected: "
    )
    if missed > 0.05:
        return counts + "it misses parts of the obstacles"
    if far_c + far_d == 0:
        return counts + "it finds the obstacles, and errs only at their edges"
    where = "mostly at their edges" if near_all >= 0.5 else "more often away from their edges than at them"
    return (
        counts + f"it finds the obstacles and errs {where}; away from any boundary it makes {far_c} "
        f"conservative and {far_d} dangerous mistakes"
    )


def threshold_explorer(maps: Mapping[str, tuple], start: str):
    """Section 6's slider (reader r29c: its code filled a screen of the page): a model, ``maps[name] = (P(valid),
    truth, grid, its own threshold)``, and a threshold; the decision map redrawn as a picture (it changes in place, no
    flicker), its alt text the picture's tooltip. Picking a model moves the threshold to that model's own."""
    import io

    import ipywidgets as widgets

    from toolkit.plots import classifier
    from toolkit.plots.alt import alt_text

    model = widgets.Dropdown(options=list(maps), value=start, description="model")
    own = round(maps[start][3], 2)
    threshold = widgets.FloatSlider(own, min=0.0, max=1.0, step=0.01, description="threshold", continuous_update=False)
    picture = widgets.Image(format="png")

    def redraw(change=None) -> None:
        p, truth, cells, _ = maps[model.value]
        png = io.BytesIO()
        fig = classifier.threshold_view(p, truth, cells, threshold=threshold.value, title=model.value)
        fig.savefig(png, format="png", dpi=96)  # one pixel a CSS pixel: the text at its size on the page
        picture.value, picture.tooltip = png.getvalue(), alt_text(fig)  # the picture, and what it shows in words

    def pick_model(change) -> None:
        own = round(maps[model.value][3], 2)  # a new model starts at its own threshold
        if threshold.value != own:
            threshold.value = own  # redraws
        else:
            redraw()

    model.observe(pick_model, "value")
    threshold.observe(redraw, "value")
    redraw()
    return widgets.VBox([widgets.HBox([model, threshold]), picture])


def rates(s: Mapping[str, float], balanced: str = ".0%") -> str:
    """Accuracy, TPR / TNR, balanced accuracy (formatted as ``balanced`` says): a closing table row's last three
    cells."""
    return f"{s['acc']:.0%} | {s['tpr']:.0%} / {s['tnr']:.0%} | {(s['tpr'] + s['tnr']) / 2:{balanced}}"


def closing_table(scores: Mapping[str, Mapping[str, float]], trained: Callable[[str, str], dict]) -> str:
    """The paper's unseen 2DS row, then each recorded run (``docs/results.md``, the opening table's) directly above
    this page's draw of the same measurement: section 4's ``scores`` (``"preset\\nkind"``: each preset and "always
    valid" on balanced, then validity-blind samples) and the 3DC-7 ``strong`` model as ``trained`` (``trained_scores``)
    scores it, as a Markdown table (reader r30c: the recorded 55 % stood at the top and this page's 53 % at the bottom,
    both named alike, with the recorded row folded away)."""
    rows = ["| | samples | accuracy | TPR / TNR | balanced accuracy |", "| --- | --- | --- | --- | --- |"]
    rows.append(paper_row("2ds"))
    for name, s in scores.items():
        label, kind = name.split("\n")
        if label != "always valid":
            record = recorded_scores(label, "2ds", kind)
            if record is not None:
                rows.append(f"| `{label}` preset, 2DS unseen, {RECORDED} | {kind} | {rates(record)} |")
            label = f"`{label}` preset, 2DS unseen, {DRAWN}"
        rows.append(f"| {label} | {kind} | {rates(s)} |")
    strong7 = recorded_scores("strong", "3dc7") or {}  # the opening table's row, under the paper's (reader r32c)
    rows.append(paper_row("3dc7"))
    rows.append(f"| `strong` preset, 3DC-7 unseen, {RECORDED} | balanced | {rates(strong7)} |")
    own7 = trained("3dc7", "strong")["mlp"]["unseen"]  # toolkit train's test: its own workspaces' balanced samples
    rows.append(f"| `strong` preset, 3DC-7 unseen, this page's model (`trained_scores`) | balanced | {rates(own7)} |")
    return "\n".join(rows)


def paper_row(scenario: str) -> str:
    """The closing table's row of the paper's Table 2, unseen ``scenario``: validity-blind samples by §IV-A, the
    share of valid ones its rates imply (reader r31c: not "unclear", the two that clash), its balanced accuracy to a
    tenth as in the opening table (r28c)."""
    published = paper_numbers.MLP[scenario]["unseen"]
    return (
        f"| the paper's Table 2, {NAMES[scenario]} unseen | validity-blind by §IV-A; its rates imply "
        f"{_implied_share(published):.0%} valid | {rates(published, '.1%')} |"
    )


RECORDED = "recorded run (docs/results.md)"  # the closing table's label of a run the opening table quotes
DRAWN = "this page's draw (section 4)"  # and of this page's own test of the same model


def recorded_scores(preset: str, scenario: str, kind: str = "balanced") -> dict[str, float] | None:
    """The recorded run's accuracy, TPR and TNR of ``preset`` on ``scenario``'s unseen workspaces, ``kind`` of
    samples, as the opening table (balanced) and chapter 04 (validity-blind) read them; None where the record has no
    such row (validity-blind "always valid" is no run)."""
    row = recorded.table(preset, "MLP accuracy")[scenario]
    if kind == "balanced":
        return {"acc": recorded.ours(row["Balanced unseen Acc"]), "tpr": recorded.ours(row["TPR"])} | {
            "tnr": recorded.ours(row["TNR"])
        }
    if kind == "validity-blind":
        return {k: recorded.ours(row[f"Unseen {c}"]) for k, c in (("acc", "Acc"), ("tpr", "TPR"), ("tnr", "TNR"))}
    return None


def other_runs(slice7: tuple[np.ndarray, np.ndarray], trained: Callable[[str, str], dict]) -> str:
    """Other runs of the same recipes, in a folded box: the 3DC-7 slice ``(kept, valid)``; the page's 2DS models as
    ``trained`` (``trained_scores``) scores them."""
    rows = ["| | samples | accuracy | TPR / TNR | balanced accuracy |", "| --- | --- | --- | --- | --- |"]
    kept7, valid7 = slice7
    s7 = metrics.classification(np.ravel(kept7), np.ravel(valid7))
    rows.append(f"| `strong` preset, 3DC-7 slice of section 5 | its {np.size(valid7)} cells | {rates(s7)} |")
    for preset in ("paper", "strong"):
        s = trained("2ds", preset)["mlp"]["unseen"]
        rows.append(f"| `{preset}` preset, 2DS unseen, this page's model (`trained_scores`) | balanced | {rates(s)} |")
    return (
        "<details><summary>Other runs of the same recipes</summary>\n\n"
        + "\n".join(rows)
        + "\n\n"
        + OTHER_RUNS
        + "\n\n</details>"
    )


OTHER_RUNS = (  # what the folded table's rows are (r30c: its paragraph on seeded random streams cut to one line)
    "The slice row counts section 5's map. The `trained_scores` rows are this page's models as `toolkit train` scores "
    "them on its own test workspaces' balanced samples, not section 4's: another draw of the same test, with the same "
    "verdicts."
)


def implied_shares(blind_share: float) -> str:
    """The share of valid samples the paper's unseen and seen accuracy, TPR and TNR imply, if each accuracy pools
    them (``acc = s TPR + (1 - s) TNR``), beside ``blind_share``, this page's validity-blind samples' share."""
    unseen, seen = _implied_share(paper_numbers.MLP["2ds"]["unseen"]), _implied_share(paper_numbers.MLP["2ds"]["seen"])
    return (
        "unseen column: share of valid samples the paper's accuracy, TPR and TNR imply, if its accuracy pools them: "
        f"{unseen:.0%}; here, validity-blind: {blind_share:.0%}\n"
        f'seen column, the same arithmetic: {seen:.0%} valid (§IV-A: "approximately distributed 50/50")'
    )


def _implied_share(r: Mapping[str, float]) -> float:
    """The share of valid samples ``s`` for which an accuracy pooling them, ``s TPR + (1 - s) TNR``, is ``r["acc"]``."""
    return (r["acc"] - r["tnr"]) / (r["tpr"] - r["tnr"])
