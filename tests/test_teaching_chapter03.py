"""Chapter 03's tables (toolkit.teaching.chapter03): each row names the run it is (reader r27c: two rows for the same
model gave two sets of numbers, and the paper's 88 % accuracy sat in a column of balanced accuracy)."""

from __future__ import annotations

import numpy as np

from toolkit.experiments import paper_numbers
from toolkit.teaching import chapter03, recorded


def test_the_opening_table_gives_the_papers_accuracy_as_reported_and_its_balanced_accuracy_apart():
    published = paper_numbers.MLP["2ds"]["unseen"]
    lines = chapter03.opening_table().splitlines()
    paper = next(line for line in lines if line.startswith("| the paper's MLP"))
    assert f"as reported: {published['acc']:.0%})" in paper
    assert f"| {(published['tpr'] + published['tnr']) / 2:.1%} |" in paper  # 87.5 %, not the reported 88 %
    strong7 = recorded.table("strong", "MLP accuracy")["3dc7"]
    label = "our `strong` preset, 3DC-7, recorded run"  # r29c, r30c
    assert any(line.startswith(f"| {label} | {recorded.ours(strong7['Balanced unseen Acc']):.0%} |") for line in lines)
    paper7 = "| the paper's MLP, its Table 2, 3DC-7 (a 7-DoF chain of two boxes in 3D, section 5; its accuracy, as "
    assert lines[5].startswith(paper7 + "reported: 71%) | 73.0% | 85% | 61% |")  # r32c: 3DC-7 defined, beside ours
    assert lines[6].startswith(f"| {label} |") and "| TPR (valid kept) |" in lines[0]  # r32c: "free kept" elsewhere
    assert "preset (the toolkit's training recipe" in lines[3]


def test_the_closing_table_holds_the_paper_and_each_recorded_run_above_this_pages_draw_and_a_box_the_other_runs():
    """Reader r29c: thirteen rows, the others folded; reader r30c: the recorded run (55 %) in the fold and this page's
    draw (53 %) visible, named alike: each recorded run now stands directly above this page's draw of it."""
    scores = {"paper\nbalanced": {"acc": 0.5, "tpr": 0.3, "tnr": 0.7}, "always valid\nbalanced": {"acc": 0.5}}
    scores["always valid\nbalanced"] |= {"tpr": 1.0, "tnr": 0.0}
    evaluation = {"mlp": {"unseen": {"acc": 0.9, "tpr": 0.8, "tnr": 1.0}}}
    table = chapter03.closing_table(scores, lambda scenario, preset: evaluation)
    rows = [line.split(" | ")[0].lstrip("| ") for line in table.splitlines()[2:]]
    assert rows == [
        "the paper's Table 2, 2DS unseen",
        "`paper` preset, 2DS unseen, recorded run (docs/results.md)",
        "`paper` preset, 2DS unseen, this page's draw (section 4)",
        "always valid",
        "the paper's Table 2, 3DC-7 unseen",  # reader r32c
        "`strong` preset, 3DC-7 unseen, recorded run (docs/results.md)",
        "`strong` preset, 3DC-7 unseen, this page's model (`trained_scores`)",
    ]
    paper_row = "| validity-blind by §IV-A; its rates imply 60% valid | 88% | 90% / 85% | 87.5% |"  # r31c
    assert paper_row in table  # the paper's, as the opening table prints it
    assert "| validity-blind by §IV-A; its rates imply 42% valid | 71% | 85% / 61% | 73.0% |" in table  # r32c
    paper2, strong7 = (recorded.table(p, "MLP accuracy")[s] for p, s in (("paper", "2ds"), ("strong", "3dc7")))
    opening = chapter03.opening_table()
    for row in (paper2, strong7):  # the recorded rows carry the opening table's numbers, rounded alike
        said = [f"{recorded.ours(row[c]):.0%}" for c in ("Balanced unseen Acc", "TPR", "TNR")]
        assert f"| {said[0]} | {said[1]} / {said[2]} |" in table and f"| {' | '.join(said)} |" in opening
    kept, valid = np.array([True, False, True, True]), np.array([True, False, False, True])
    box = chapter03.other_runs((kept, valid), lambda scenario, preset: evaluation)
    assert box.startswith("<details><summary>") and box.endswith("</details>")
    rows = [line.split(" | ")[0].lstrip("| ") for line in box.splitlines() if line.startswith("| `")]
    assert rows[0] == "`strong` preset, 3DC-7 slice of section 5"
    assert sum("this page's model (`trained_scores`)" in row for row in rows) == 2
    assert not any("recorded run" in row for row in rows)  # r30c: visible in the closing table, not folded
    assert "| its 4 cells | 75% | 100% / 50% | 75% |" in box


def test_the_mistakes_table_prints_a_share_below_1_percent_with_a_decimal():
    assert [chapter03.share(f) for f in (0, 0.0004, 0.0039, 0.01, 0.64)] == ["0%", "under 0.1%", "0.4%", "1%", "64%"]


def test_a_slice_verdict_counts_its_mistakes_by_where_they_lie():
    truth = np.ones((20, 20), dtype=bool)
    truth[5:10, 5:10] = False  # one C-obstacle
    p = truth.astype(float)
    assert chapter03.slice_verdict(p, truth, 0.5, 1).endswith("it finds the obstacles, and errs only at their edges")
    p[15, 15] = 0.0  # a free cell far from the obstacle rejected
    said = chapter03.slice_verdict(p, truth, 0.5, 1)
    assert said.startswith("1 of 400 cells wrong, 0% of them near a boundary")
    assert said.endswith("away from any boundary it makes 1 conservative and 0 dangerous mistakes")


def test_score_unseen_scores_each_model_and_always_valid_on_the_same_balanced_and_blind_samples(checkpoint_2ds):
    """Section 4's measurement, moved off the page (reader r29c: a screen of loop code): per kind of sample, the truth,
    each model's P(valid) and its scores, "always valid" scoring the share of valid samples."""
    from toolkit import scenarios
    from toolkit.learning import checkpoints, metrics

    scenario = scenarios.get("2ds")
    models = {"strong": checkpoints.load_models(checkpoint_2ds, scenario)}
    t = {"strong": models["strong"].threshold}
    truth, predicted_p, scores = chapter03.score_unseen(scenario, models, t, 2, 20, 0)
    assert {kind: v.shape for kind, v in truth.items()} == {"balanced": (40,), "validity-blind": (40,)}
    assert truth["balanced"].mean() == 0.5 and set(predicted_p) == {
        ("strong", "balanced"),
        ("strong", "validity-blind"),
    }
    for kind, v in truth.items():
        assert scores[f"always valid\n{kind}"]["acc"] == v.mean()
        assert scores[f"strong\n{kind}"] == metrics.classification(predicted_p["strong", kind] >= t["strong"], v)


def test_the_threshold_explorer_starts_at_the_models_own_threshold_and_moves_to_anothers():
    """Section 6's slider, off the page (reader r29c): its picture is the decision map with its alt text as tooltip,
    and picking a model moves the threshold to that model's own."""
    from toolkit.geometry import robots
    from toolkit.plots import slices

    grid = slices.slice_grid(robots.point_robot(), n=8)
    valid = np.ones(grid.shape, dtype=bool)
    valid[2:4, 2:4] = False
    p = np.where(valid, 0.8, 0.3)
    box = chapter03.threshold_explorer({"a": (p, valid, grid, 0.6), "b": (p, valid, grid, 0.25)}, start="a")
    (model, threshold), picture = box.children[0].children, box.children[1]
    assert threshold.value == 0.6 and bytes(picture.value).startswith(b"\x89PNG")
    assert "threshold 0.60" in picture.tooltip
    model.value = "b"
    assert threshold.value == 0.25 and "threshold 0.25" in picture.tooltip
