"""`toolkit ablate`: one cumulative change per row from the paper's recipe, every row scored alike, resumable."""

import json
from dataclasses import replace

import pytest

from toolkit import cli
from toolkit.experiments import ablation
from toolkit.experiments.config import RunConfig
from toolkit.learning import presets, training


def test_rows_add_one_change_each_to_the_paper_preset():
    rows = ablation.step_presets()
    assert [k for k, _, _ in rows] == [k for k, _, _ in ablation.STEPS]
    assert rows[0][2] == replace(presets.get("paper"), name="ablation:paper")
    last = rows[-1][2]
    assert (last.encoding, last.latent_input, last.optimizer, last.dropout, last.cae_workspaces) == (
        "local",
        False,
        "adamw",
        0.0,
        2000,
    )
    for (_, _, before), (key, _, after), (_, _, changes) in zip(rows, rows[1:], ablation.STEPS[1:]):
        differ = {f for f in before.__dataclass_fields__ if f != "name" and getattr(before, f) != getattr(after, f)}
        assert differ == {f for f, v in changes.items() if getattr(before, f) != v}, key


@pytest.mark.slow
def test_quick_ablation_scores_every_row_and_resumes(tmp_path, monkeypatch, capsys):
    out = tmp_path / "ab"
    assert cli.main(["ablate", "--scenario", "2ds", "--quick", "--out", str(out)]) == 0
    result = json.loads((out / "ablation.json").read_text())
    assert [r["key"] for r in result["rows"]] == [k for k, _, _ in ablation.STEPS]
    for row in result["rows"]:
        for split in ("seen", "unseen", "unseen_uniform"):
            assert set(row["mlp"][split]) == {"acc", "tpr", "tnr", "always_valid"}
        assert row["mlp"]["unseen"]["always_valid"] == 0.5 and row["mlp"]["unseen_uniform"]["always_valid"] > 0.6
    # every row tested on the same samples: "always valid" is one number down the column
    assert len({r["mlp"]["unseen_uniform"]["always_valid"] for r in result["rows"]}) == 1
    trained = [r["key"] for r in result["rows"] if r["cae_trained"]]
    assert trained == ["paper", "cae_mean", "cae_many"]  # later rows change no CAE setting: they reuse row 2's
    table = (out / "ablation.md").read_text()
    assert table.count("\n| ") == len(ablation.STEPS) + 2 and "(CAE reused)" in table
    # a finished ablation is not redone
    monkeypatch.setattr(training, "train_models", lambda *a, **k: pytest.fail("a cached row was trained again"))
    assert ablation.ablate(RunConfig.create("2ds", quick=True, progress=False), out) == result["rows"]
