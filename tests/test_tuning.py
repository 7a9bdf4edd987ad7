"""`toolkit tune`: the paper's unstated settings chosen on held-out training workspaces, never on the unseen ones."""

import json

import numpy as np
import pytest
import torch

from toolkit import cli, scenarios
from toolkit.experiments import tuning
from toolkit.experiments.config import QUICK, RunConfig
from toolkit.learning import models, training


def test_the_one_standard_error_rule_takes_the_first_setting_within_noise_of_the_best():
    rows = [{"validation_acc": a} for a in (0.50, 0.55, 0.59, 0.60)]
    # 600 samples: the best (0.60) has a standard error of 0.02, so 0.59 is within it and 0.55 is not
    assert tuning.one_standard_error_choice(rows, 600) is rows[2]
    assert tuning.one_standard_error_choice(rows, 60) is rows[1]  # SE 0.063: 0.55 is within it
    assert tuning.one_standard_error_choice(rows[:1], 600) is rows[0]


def test_he_initialization_of_the_mlp_has_he_spread_and_unknown_names_fail():
    torch.manual_seed(0)
    he = models.CollisionMLP(400, (300, 4), dropout=0.5, init="he").net[0].weight.detach()
    default = models.CollisionMLP(400, (300, 4), dropout=0.5).net[0].weight.detach()
    # He for PReLU: std = sqrt(2 / ((1 + a^2) fan_in)); PyTorch's default: uniform with std 1 / sqrt(3 fan_in)
    assert float(he.std()) == pytest.approx(np.sqrt(2 / ((1 + models.PRELU_SLOPE**2) * 400)), rel=0.05)
    assert float(default.std()) == pytest.approx(1 / np.sqrt(3 * 400), rel=0.05)
    with pytest.raises(ValueError, match="unknown MLP initialization 'xavier'"):
        models.CollisionMLP(4, (3,), dropout=0.0, init="xavier")


@pytest.mark.slow
def test_quick_tuning_never_sees_the_unseen_workspaces_chooses_the_best_and_resumes(tmp_path, monkeypatch):
    generate = scenarios.Scenario.workspaces

    def seen_only(scenario, stream, count, seed):
        assert stream != "unseen", "tuning generated the unseen test workspaces"
        return generate(scenario, stream, count, seed)

    monkeypatch.setattr(scenarios.Scenario, "workspaces", seen_only)
    out = tmp_path / "tune"
    assert cli.main(["tune", "--scenario", "2ds", "--quick", "--out", str(out)]) == 0
    result = json.loads((out / "tuning.json").read_text())
    n = QUICK.workspaces[0]
    assert (result["fit_workspaces"], result["validation_workspaces"]) == (n - 2, 2)
    assert [r["cae_epochs"] for r in result["cae"]] == list(tuning.CAE_EPOCHS)
    assert len(result["mlp"]) == np.prod([len(v) for v in tuning.MLP_GRID.values()])
    best = max(r["validation_acc"] for r in result["mlp"])
    se = np.sqrt(best * (1 - best) / result["validation_samples"])
    chosen = next(r for r in result["mlp"] if r["validation_acc"] >= best - se)  # the first within one SE
    assert result["chosen"] == {
        "cae_epochs": max(result["cae"], key=lambda r: r["validation_acc"])["cae_epochs"],
        **{k: chosen[k] for k in tuning.MLP_GRID},
    }
    for row in result["mlp"]:
        assert 0.0 <= row["validation_acc"] <= 1.0 and row["train_seconds"] >= 0
    table = (out / "tuning.md").read_text()
    assert table.count("**chosen**") == 2 and "never used" in table
    # a finished tuning is not redone
    monkeypatch.setattr(training, "train_models", lambda *a, **k: pytest.fail("a cached row was trained again"))
    monkeypatch.setattr(training, "train_cae", lambda *a, **k: pytest.fail("a cached CAE was trained again"))
    assert tuning.tune(RunConfig.create("2ds", quick=True, progress=False), out) == result
