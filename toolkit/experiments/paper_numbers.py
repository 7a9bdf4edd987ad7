"""The published figures of Tran, Denny, Ekenna, as printed in the paper (§V).

Fractions in [0, 1] and seconds, keyed like ``results.json``. Table 3 gives the
time improvement ratio ``(without - with) / without``; the text around it gives
the mean and standard deviation of the times behind it, ``(mean, std)``; :func:`table3_against_text` says where
the two disagree.
"""

from decimal import Decimal

# Table 1: CAE reconstruction accuracy (3DC is one row for both box chains).
CAE = {
    "2ds": {"seen_acc": 1.00, "unseen_acc": 1.00},
    "3do": {"seen_acc": 0.96, "unseen_acc": 0.94},
    "3dc7": {"seen_acc": 0.98, "unseen_acc": 0.95},
    "3dc9": {"seen_acc": 0.98, "unseen_acc": 0.95},
}

# Table 2: MLP accuracy, true positive rate (valid predicted valid), true negative rate.
MLP = {
    "2ds": {"seen": {"acc": 0.92, "tpr": 0.96, "tnr": 0.88}, "unseen": {"acc": 0.88, "tpr": 0.90, "tnr": 0.85}},
    "3do": {"seen": {"acc": 0.76, "tpr": 0.88, "tnr": 0.64}, "unseen": {"acc": 0.73, "tpr": 0.85, "tnr": 0.60}},
    "3dc7": {"seen": {"acc": 0.75, "tpr": 0.87, "tnr": 0.64}, "unseen": {"acc": 0.71, "tpr": 0.85, "tnr": 0.61}},
    "3dc9": {"seen": {"acc": 0.73, "tpr": 0.82, "tnr": 0.66}, "unseen": {"acc": 0.72, "tpr": 0.82, "tnr": 0.62}},
}

# Table 3: time improvement ratio with the framework, per sampler.
IMPROVEMENT = {
    "2ds": {
        "sampling": {"BS": 0.53, "OB": 0.57, "G": 0.63, "BT": 0.74},
        "total": {"BS": 0.17, "OB": 0.18, "G": 0.11, "BT": 0.08},
    },
    "3do": {
        "sampling": {"BS": 0.45, "OB": 0.58, "G": 0.41, "BT": 0.56},
        "total": {"BS": 0.01, "OB": 0.09, "G": 0.10, "BT": -0.08},
    },
    "3dc7": {
        "sampling": {"BS": 0.49, "OB": 0.58, "G": 0.51, "BT": 0.61},
        "total": {"BS": -0.02, "OB": 0.14, "G": -0.09, "BT": 0.54},
    },
    "3dc9": {
        "sampling": {"BS": 0.39, "OB": 0.59, "G": 0.48, "BT": 0.62},
        "total": {"BS": 0.18, "OB": 0.20, "G": 0.13, "BT": 0.37},
    },
}

# §V text: (mean, std) seconds per query, without and with the framework.
TIMES = {
    "2ds": {
        "sampling_s": {
            "BS": ((0.0004, 0.0002), (0.0002, 0.0002)),
            "OB": ((0.05, 0.01), (0.03, 0.01)),
            "G": ((0.04, 0.01), (0.02, 0.01)),
            "BT": ((0.26, 0.23), (0.11, 0.03)),
        },
        "total_s": {
            "BS": ((0.12, 0.01), (0.10, 0.01)),
            "OB": ((0.38, 0.05), (0.31, 0.03)),
            "G": ((0.09, 0.01), (0.09, 0.01)),
            "BT": ((0.13, 0.01), (0.13, 0.01)),
        },
    },
    "3do": {
        "sampling_s": {
            "BS": ((0.11, 0.01), (0.06, 0.02)),
            "OB": ((1.13, 0.08), (0.56, 0.25)),
            "G": ((0.21, 0.04), (0.12, 0.02)),
            "BT": ((0.76, 0.13), (0.32, 0.02)),
        },
        "total_s": {
            "BS": ((40.86, 36.47), (40.51, 25.91)),
            "OB": ((43.74, 22.01), (39.88, 18.72)),
            "G": ((42.32, 41.99), (38.22, 30.01)),
            "BT": ((40.40, 33.92), (43.13, 28.87)),
        },
    },
    "3dc7": {
        "sampling_s": {
            "BS": ((0.007, 0.003), (0.003, 0.001)),
            "OB": ((0.20, 0.03), (0.09, 0.01)),
            "G": ((0.09, 0.01), (0.04, 0.02)),
            "BT": ((0.42, 0.04), (0.17, 0.02)),
        },
        "total_s": {
            "BS": ((0.53, 0.03), (0.54, 0.03)),
            "OB": ((0.65, 0.35), (0.56, 0.13)),
            "G": ((0.45, 0.40), (0.49, 0.12)),
            "BT": ((0.95, 0.64), (0.44, 0.05)),
        },
    },
    "3dc9": {
        "sampling_s": {
            "BS": ((0.015, 0.005), (0.008, 0.003)),
            "OB": ((0.08, 0.01), (0.04, 0.01)),
            "G": ((0.04, 0.01), (0.02, 0.01)),
            "BT": ((0.10, 0.02), (0.04, 0.02)),
        },
        "total_s": {
            "BS": ((0.73, 0.48), (0.60, 0.19)),
            "OB": ((3.27, 3.62), (2.60, 0.19)),
            "G": ((3.90, 4.73), (3.40, 0.41)),
            "BT": ((7.10, 0.77), (4.50, 0.50)),
        },
    },
}


def table3_against_text() -> dict[str, tuple[float, float]]:
    """Table 3's cells that the mean times of the paper's text (§V, printed to two decimals or more) do not give
    within rounding (of either): ``{"3DO total BT": (-0.068, -0.08)}``, the improvement they give and Table 3's."""
    names, differ = {"2ds": "2DS", "3do": "3DO", "3dc7": "3DC-7", "3dc9": "3DC-9"}, {}
    for scenario, kind, (sampler, printed) in (
        (s, k, c) for s in IMPROVEMENT for k in IMPROVEMENT[s] for c in IMPROVEMENT[s][k].items()
    ):
        (without, _), (with_, _) = TIMES[scenario][f"{kind}_s"][sampler]
        a, b = (0.5 * 10.0 ** -max(2, -int(Decimal(repr(t)).as_tuple().exponent)) for t in (without, with_))
        low, high = 1 - (with_ + b) / (without - a), 1 - (with_ - b) / (without + a)  # a, b: half the last digit
        if high < printed - 0.005 or low > printed + 0.005:  # Table 3 prints whole percent
            differ[f"{names[scenario]} {kind} {sampler}"] = (1 - with_ / without, printed)
    return differ


def saved_beyond_sampling() -> dict[tuple[str, str], tuple[float, float, float]]:
    """The paper's cells whose whole query, by its §V mean times, saved more seconds than all of its sampling took
    without the framework: more than skipping the samples' checks can save, so not prediction's alone.
    ``{(scenario, sampler): (seconds saved, seconds of sampling without, standard deviation of the total without)}``."""
    over = {}
    for scenario, kinds in TIMES.items():
        for sampler, ((without, spread), (with_, _)) in kinds["total_s"].items():
            sampling = kinds["sampling_s"][sampler][0][0]
            if without - with_ > sampling:
                over[scenario, sampler] = (without - with_, sampling, spread)
    return over
