"""The sentences the chapters print from their measurements (:mod:`toolkit.teaching.findings`), on crafted values:
prediction saving, costing and tying, an outlier that moves a mean, and the lesson carrying the crossover's words."""

import numpy as np
import pytest

from toolkit.teaching import findings


def summary(totals: list[float]) -> dict:
    """What queries.summarize writes about the totals that the sentences read."""
    q1, median, q3 = np.percentile(totals, (25, 50, 75))
    return {
        "n_queries": len(totals),
        "total_s": float(np.mean(totals)),
        "total_s_median": float(median),
        "total_s_q1": float(q1),
        "total_s_q3": float(q3),
        "sampling_s_median": float(median) / 10,
        "total_s_per_query": totals,
    }


@pytest.mark.parametrize(
    ("ratio", "expected"), [(0.5, "saves"), (0.96, "ties"), (1.0, "ties"), (1.04, "ties"), (1.2, "costs")]
)
def test_verdict_reads_a_ratio_with_a_five_percent_tie(ratio, expected):
    assert findings.verdict(ratio) == expected


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf")])
def test_verdict_refuses_what_is_not_a_time_ratio(bad):
    with pytest.raises(ValueError, match="a time ratio must be a positive number"):
        findings.verdict(bad)


def test_describe_ratios_groups_the_samplers_in_every_direction():
    sentence = findings.describe_ratios("3DC-7", {"BS": 0.5, "OB": 1.57, "G": 1.02, "BT": 1.89}, "the lazy planner")
    assert sentence == (
        "3DC-7, total time with / without prediction against the lazy planner: prediction saves time with BS (0.50); "
        "costs time with OB (1.57) and BT (1.89); ties (within 5 %) with G (1.02)."
    )


def test_describe_ratios_says_every_sampler_when_all_agree():
    sentence = findings.describe_ratios("2DS", {"BS": 1.3, "OB": 1.5}, "X", kind="sampling")
    assert sentence.endswith("prediction costs time with every sampler: BS (1.30) and OB (1.50).")
    assert "sampling time" in sentence


def test_describe_medians_uses_the_medians_not_the_means():
    table = {"BS": {"without": summary([0.1, 0.1, 9.0]), "with": summary([0.2, 0.2, 0.2])}}  # means 3.07 vs 0.2
    assert findings.median_ratios(table) == pytest.approx({"BS": 2.0})
    sentence = findings.describe_medians("3DC-7", table, "the lazy planner")
    assert sentence.startswith("3DC-7 (medians over 3 queries), total time") and "costs time with every" not in sentence
    assert "costs time with BS (2.00)" in sentence


def test_outliers_names_the_slow_query_and_the_mean_it_moves():
    table = {
        "BS": {"without": summary([0.1, 2.1, 0.1]), "with": summary([0.2, 0.2, 0.2])},
        "OB": {"without": summary([0.1, 0.3, 0.2]), "with": summary([0.2, 0.2, 0.2])},  # 3x: not an outlier
        "G": {"without": summary([0.01] * 20 + [0.05]), "with": summary([0.2] * 3)},  # 5x, but the mean hardly moves
    }
    (line,) = findings.outliers("3DC-7", table)
    assert line == (
        "3DC-7, BS without prediction: query 1 took 2.1 s, 21x the other queries' median (0.1 s); "
        "it pulls the mean up to 0.767 s (the median: 0.1 s)."
    )


def test_outliers_of_two_queries_say_the_median_moves_too():
    (line,) = findings.outliers("3DC-7", {"BS": {"without": summary([2.0, 0.02]), "with": summary([0.02, 0.02])}})
    assert "query 0 took 2 s, 100x" in line and "with only two queries the median too (1.01 s)" in line


def test_describe_lesson_carries_every_verdict_and_the_crossover_conclusion_verbatim():
    conclusion = ["obstacles: learning never wins over 10-500.", "triangles: learning is cheaper at 20, 320."]
    text = findings.describe_lesson({"2DS": "2DS: prediction costs time.", "3DC-7": "3DC-7: it saves."}, conclusion)
    assert "- 2DS: prediction costs time.\n- 3DC-7: it saves." in text
    assert text.endswith("- " + conclusion[0] + "\n- " + conclusion[1])


def test_describe_throughput_says_who_leads_in_both_directions():
    measured = {"ratio": 0.5, "learned_cfg_per_s": 4e6, "fcl_cfg_per_s": 1e6}
    assert findings.describe_throughput("3DC-7", measured, 10_000) == (
        "3DC-7, calls of 10,000 configurations on one thread: the learned checker answered 0.50x as many "
        "configurations a second as the default exact checker (it trails) and 4.00x as many as python-fcl (it leads)."
    )
    tie = findings.describe_throughput("2DS", {"ratio": 1.02, "learned_cfg_per_s": 1.0, "fcl_cfg_per_s": 1.0}, 500)
    assert tie.count("(a tie, within 5 %)") == 2


def test_compare_scores_says_higher_lower_and_equal_at_the_printed_precision():
    ours, paper = {"acc": 0.77, "tpr": 0.849, "tnr": 0.6}, {"acc": 0.71, "tpr": 0.85, "tnr": 0.61}
    assert findings.compare_scores(ours, paper) == (
        "accuracy 77% against 71% (higher), TPR 85% against 85% (equal), TNR 60% against 61% (lower)"
    )


def test_describe_accuracy_against_always_valid_and_a_coin_flip():
    assert findings.describe_accuracy("paper", 0.38, 0.86) == (
        'paper: accuracy 38%, below "always valid" (86%) and below a coin flip (50%) (worse than chance)'
    )
    assert findings.describe_accuracy("strong", 0.97, 0.86).endswith(
        'above "always valid" (86%) and above a coin flip (50%)'
    )
    assert "level with a coin flip" in findings.describe_accuracy("x", 0.5, 0.5)


def test_describe_threshold_sweep_finds_the_switch_and_the_best_threshold():
    probability = np.array([0.45, 0.46, 0.47, 0.48, 0.9, 0.91, 0.92, 0.93, 0.94, 0.95])
    valid = np.array([False, False, False, False, True, True, True, True, True, True])
    sentence = findings.describe_threshold_sweep(probability, valid)
    assert sentence.startswith('up to a threshold of 0.45 the model calls every sample valid (TPR 1, TNR 0: "always')
    assert "60% accuracy" in sentence and "best accuracy over all thresholds is 100%, at 0.90" in sentence
    flat = findings.describe_threshold_sweep(np.full(4, 0.5), np.array([True, True, True, False]))
    assert "lie between 0.50 and 0.50" in flat and "is 75%, at 0.50" in flat
    with pytest.raises(ValueError, match="must be equal, non-empty"):
        findings.describe_threshold_sweep(np.zeros(3), np.zeros(4, dtype=bool))
