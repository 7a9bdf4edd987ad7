"""Training: metrics against hand counts, determinism, evaluation keys, checkpoints and bad checkpoints."""

import json
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest
import torch

from toolkit import cli, scenarios
from toolkit.experiments import pipeline
from toolkit.experiments.config import QUICK, RunConfig
from toolkit.learning import checkpoints, data, metrics, presets, training

SCENARIO_2DS = scenarios.get("2ds")

TINY = replace(QUICK.shrink(presets.get("strong")), cae_epochs=1, mlp_epochs=2)  # enough to tell seeds apart


@pytest.fixture(scope="module")
def quick_2ds():
    config = RunConfig.create("2ds", "strong", quick=True, progress=False, device="cpu")
    splits = pipeline.make_splits(config)
    return splits, pipeline.train(config, splits, cae=True)


def test_classification_metrics_by_hand():
    truth = np.array([True, True, True, False, False])
    pred = np.array([True, False, True, False, True])
    assert metrics.classification(pred, truth) == pytest.approx({"acc": 3 / 5, "tpr": 2 / 3, "tnr": 1 / 2})


def test_classification_metrics_reject_bad_shapes():
    with pytest.raises(ValueError, match="predictions"):
        metrics.classification(np.ones(3, bool), np.ones(4, bool))


def test_threshold_sweep_scores_each_threshold_like_classification():
    probability = np.array([0.1, 0.4, 0.6, 0.9, 0.3])
    truth = np.array([True, True, True, False, False])
    rates = metrics.threshold_sweep(probability, truth, np.array([0.0, 0.5, 1.0]))
    assert rates["acc"] == pytest.approx([3 / 5, 2 / 5, 2 / 5])  # all valid; only 0.6 and 0.9; none valid
    assert rates["tpr"] == pytest.approx([1, 1 / 3, 0]) and rates["tnr"] == pytest.approx([0, 1 / 2, 1])
    at_half = metrics.classification(probability >= 0.5, truth)
    assert [rates[k][1] for k in ("acc", "tpr", "tnr")] == pytest.approx([at_half[k] for k in ("acc", "tpr", "tnr")])
    assert len(metrics.threshold_sweep(probability, truth)["acc"]) == len(metrics.SWEEP) == 101
    with pytest.raises(ValueError, match="must be equal"):
        metrics.threshold_sweep(probability, truth[:3])


def test_reconstruction_accuracy_by_hand():
    grids = np.array([[[1.0, -1.0], [-1.0, -1.0]], [[1.0, 1.0], [-1.0, 1.0]]])
    recon = np.array([[[0.3, -0.2], [0.1, -5.0]], [[-0.1, 2.0], [-1.0, 1.0]]])
    assert metrics.reconstruction_accuracy(recon, grids) == pytest.approx([0.75, 0.75])


def test_unknown_preset():
    with pytest.raises(ValueError, match="unknown preset"):
        presets.get("huge")


@pytest.mark.parametrize("setting", sorted(presets.CHOICES))
def test_a_preset_naming_an_unknown_choice_is_refused_as_it_is_made(setting):
    """Issue 48: a misspelt optimizer, encoding, initialization or loss is a one-line error when the preset is made
    (replace() makes one too), naming the setting and what it may be, not a failure minutes into training."""
    allowed = {
        "encoding": "raw, local",
        "optimizer": "adagrad, adamw",
        "cae_optimizer": "adagrad, adamw",
        "mlp_init": "torch, he",
        "cae_loss": "sum, mean",
    }[setting]
    with pytest.raises(ValueError, match=rf"^preset 'paper': {setting} must be one of {allowed}; got 'Adam'$"):
        replace(presets.get("paper"), **{setting: "Adam"})
    for value in allowed.split(", "):  # every choice offered is one the code that reads it accepts
        assert getattr(replace(presets.get("paper"), **{setting: value}), setting) == value
    assert {presets.OPTIMIZERS[n] for n in ("adagrad", "adamw")} == {torch.optim.Adagrad, torch.optim.AdamW}


def test_every_choice_a_preset_offers_is_one_training_reads():
    """The choices come from the code that reads them: each encoding builds, each initialization and loss runs."""
    scenario = scenarios.get("2ds")
    for encoding in presets.CHOICES["encoding"]:
        assert replace(TINY, encoding=encoding).build_predictor(scenario).encoding.kind == encoding
    for init in presets.CHOICES["mlp_init"]:  # CollisionMLP refuses an initialization it does not know
        replace(TINY, mlp_init=init).build_predictor(scenario)
    predictor = TINY.build_predictor(scenario)
    grids = torch.zeros((2, *scenario.grid_shape))
    with torch.no_grad():
        summed, mean = (float(predictor.cae.loss(grids, 0.0, loss)) for loss in presets.CHOICES["cae_loss"])
    assert summed == pytest.approx(mean * np.prod(scenario.grid_shape), rel=1e-5)


def test_splits_follow_the_preset():
    splits = pipeline.make_splits(RunConfig.create("2ds", "paper", quick=True, progress=False))
    assert splits["train"].configs.shape == (8, 100, 2)  # paper: 100 samples per 2DS workspace
    assert len(pipeline.make_splits(RunConfig.create("2ds", "strong", quick=True, progress=False))["train"]) == 8 * 400


def test_quick_strong_2ds_learns(quick_2ds):
    splits, models = quick_2ds
    scores = training.evaluate(models, splits)
    assert set(scores) == {"cae", "mlp"} and set(scores["cae"]) == {
        "seen_acc",
        "unseen_acc",
        "seen_all_free",
        "unseen_all_free",
    }
    assert set(scores["mlp"]) == {"seen", "unseen", "unseen_uniform"}
    assert all(set(m) == {"acc", "tpr", "tnr", "always_valid"} for m in scores["mlp"].values())
    assert scores["mlp"]["unseen"]["acc"] > 0.85  # balanced test set: chance is 0.5
    assert scores["mlp"]["unseen"]["always_valid"] == 0.5
    # the paper's unseen test: validity-blind samples, mostly valid, scored against their share of valid ones
    blind = data.validity_blind_split(models.scenario, splits["unseen_test"])
    assert scores["mlp"]["unseen_uniform"]["always_valid"] == pytest.approx(blind.valid.mean())
    assert scores["mlp"]["unseen_uniform"]["always_valid"] > 0.7
    assert training.evaluate(models, dict(splits, unseen_uniform=blind)) == scores  # the same samples when given
    assert models.history["mlp"][-1] < models.history["mlp"][0]
    assert 0.05 <= models.threshold <= 0.95


def test_same_seed_same_models(quick_2ds):
    splits = quick_2ds[0]
    first, again, other = (
        training.train_models(SCENARIO_2DS, TINY, splits, seed, progress=False, device="cpu") for seed in (0, 0, 1)
    )
    state, same, different = (m.predictor.state_dict() for m in (first, again, other))
    assert all(torch.equal(state[k], same[k]) for k in state)
    assert not torch.equal(state["mlp.net.0.weight"], different["mlp.net.0.weight"])


def test_paper_preset_trains():
    splits = pipeline.make_splits(RunConfig.create("3dc7", "paper", quick=True, progress=False))
    tiny = replace(presets.get("paper"), cae_epochs=1, mlp_epochs=2)
    models = training.train_models(scenarios.get("3dc7"), tiny, splits, progress=False, device="cpu")
    assert models.threshold == 0.5 and np.all(np.isfinite(models.history["cae"] + models.history["mlp"]))
    assert isinstance(models.predictor.mlp.net[0], torch.nn.Linear) and models.predictor.mlp.in_features == 57


def test_strong_mlp_does_not_wait_for_a_cae_it_never_asks(quick_2ds):
    """strong's MLP does not see z: its CAE stays as initialized unless asked for (``cae=True``, ``--cae``)."""
    splits = quick_2ds[0]
    fast = training.train_models(SCENARIO_2DS, TINY, splits, 0, progress=False, device="cpu")
    asked = training.train_models(SCENARIO_2DS, TINY, splits, 0, progress=False, device="cpu", cae=True)
    torch.manual_seed(0)
    initial = TINY.build_predictor(scenarios.get("2ds"))
    for name, weight in initial.cae.state_dict().items():
        assert torch.equal(fast.predictor.cae.state_dict()[name], weight)
    assert not torch.equal(asked.predictor.cae.encoder[0].weight, initial.cae.encoder[0].weight)
    assert "cae" not in fast.history and len(asked.history["cae"]) >= 1
    assert training.evaluate(fast, splits)["cae"] == {"trained": False}
    assert set(training.evaluate(asked, splits)["cae"]) == {
        "seen_acc",
        "unseen_acc",
        "seen_all_free",
        "unseen_all_free",
    }
    paper = replace(QUICK.shrink(presets.get("paper")), cae_epochs=1, mlp_epochs=2)
    trained = training.train_models(SCENARIO_2DS, paper, splits, 0, progress=False, device="cpu")
    assert "cae" in trained.history  # z is used


def test_training_split_of_another_scenario(quick_2ds):
    with pytest.raises(ValueError, match="'2ds' data, not '3dc7'"):
        training.train_models(scenarios.get("3dc7"), QUICK.shrink(presets.get("paper")), quick_2ds[0], progress=False)


def test_calibrated_threshold_is_best_on_its_data(quick_2ds):
    splits, models = quick_2ds
    data = splits["seen_test"]
    t = training.calibrate_threshold(models.predictor, data)
    p = training.probabilities(models.predictor, data)
    acc = lambda threshold: np.mean((p >= threshold) == data.valid)
    assert all(acc(t) >= acc(other) for other in training.CALIBRATION_THRESHOLDS)


# -- checkpoints -------------------------------------------------------------------


def test_checkpoint_round_trip(quick_2ds, tmp_path):
    splits, models = quick_2ds
    checkpoints.save_checkpoint(models, tmp_path, evaluation={"x": 1})
    loaded = checkpoints.load_models(tmp_path, scenario="2ds")
    data = splits["unseen_test"]
    assert np.array_equal(
        training.probabilities(loaded.predictor, data), training.probabilities(models.predictor, data)
    )
    assert loaded.threshold == models.threshold and loaded.preset == models.preset
    meta = json.loads((tmp_path / "meta.json").read_text())
    assert (
        meta["scenario"] == "2ds" and meta["versions"]["torch"] == torch.__version__ and meta["evaluation"] == {"x": 1}
    )


def test_checkpoint_of_another_scenario(quick_2ds, tmp_path):
    checkpoints.save_checkpoint(quick_2ds[1], tmp_path)
    with pytest.raises(ValueError, match="trained for scenario '2ds', not '3do'"):
        checkpoints.load_models(tmp_path, scenario="3do")


@pytest.mark.parametrize("damage", ["truncate", "garbage", "no_weights", "no_meta", "bad_meta", "wrong_sizes"])
def test_damaged_checkpoint(quick_2ds, tmp_path, damage):
    checkpoints.save_checkpoint(quick_2ds[1], tmp_path)
    weights, meta = tmp_path / "weights.pt", tmp_path / "meta.json"
    if damage == "truncate":
        weights.write_bytes(weights.read_bytes()[:1000])
    elif damage == "garbage":
        weights.write_bytes(b"not a torch file")
    elif damage == "no_weights":
        weights.unlink()
    elif damage == "no_meta":
        meta.unlink()
    elif damage == "bad_meta":
        meta.write_text(meta.read_text()[:50])
    else:
        data = json.loads(meta.read_text())
        data["sizes"]["mlp_hidden"] = [6, 4]
        meta.write_text(json.dumps(data))
    message = {
        "no_meta": "metadata missing",
        "bad_meta": "corrupted",
        "no_weights": "no weights.pt",
        "wrong_sizes": "recorded sizes",
    }.get(damage, "corrupted")
    with pytest.raises(ValueError, match=message):
        checkpoints.load_models(tmp_path)


def test_missing_checkpoint_folder(tmp_path):
    with pytest.raises(FileNotFoundError):
        checkpoints.load_models(tmp_path / "nowhere")


def test_cli_train_writes_a_checkpoint(tmp_path, capsys):
    out = tmp_path / "ckpt"
    assert cli.main(["train", "--scenario", "2ds", "--preset", "paper", "--quick", "--out", str(out)]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert set(printed["mlp"]) == {"seen", "unseen", "unseen_uniform"}
    loaded = checkpoints.load_models(out, "2ds")
    assert loaded.preset.name == "paper" and loaded.quick


@pytest.mark.parametrize("flags, asked", [([], None), (["--cae"], True)])
def test_cli_train_trains_the_cae_when_asked(flags, asked, tmp_path, monkeypatch):
    seen = {}

    class Stop(Exception):
        pass

    def fake_train(*args, **kwargs):
        seen.update(kwargs)
        raise Stop

    monkeypatch.setattr(pipeline, "make_splits", lambda *args, **kwargs: {})
    monkeypatch.setattr(training, "train_models", fake_train)
    with pytest.raises(Stop):
        cli.main(["train", "--scenario", "2ds", "--preset", "strong", "--out", str(tmp_path / "c")] + flags)
    assert seen["cae"] is asked  # None: train_models' rule, a CAE only for an MLP that sees z


@pytest.mark.parametrize("name, lr, batch", [("2ds", 1e-3, 100), ("3dc7", 1e-4, 100), ("3do", 1e-4, 10)])
def test_strong_cae_follows_the_scenarios_caps(name, lr, batch, monkeypatch):
    """strong's CAE: AdamW 1e-3 on batches of 100 generated grids where the scenario allows (at 1e-3 the 3DC and
    3DO CAEs diverge; 3DO's steps are slow)."""
    seen = {}
    monkeypatch.setattr(
        training,
        "fit",
        lambda params, epochs, loss_of, **settings: seen.update(
            lr=settings["lr"], batch=max(len(b) for e in epochs for b in e)
        ),
    )
    s, stand_in = scenarios.get(name), SimpleNamespace(cae=torch.nn.Linear(1, 1))  # the 3DO CAE: 147M parameters
    training.train_cae(
        stand_in,
        torch.zeros(2000, 1),
        presets.get("strong"),
        torch.Generator(),
        progress=False,
        max_steps=s.cae_max_steps,
        max_batch=s.cae_max_batch,
        max_lr=s.cae_max_lr,
    )
    assert seen == {"lr": lr, "batch": batch}
