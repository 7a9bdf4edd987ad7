"""toolkit.teaching.notebook.trained_models: trains once, then loads; a changed preset trains anew."""

import dataclasses

from toolkit.learning import presets
from toolkit.teaching import notebook


def test_models_are_trained_once_and_retrained_when_the_preset_changes(tmp_path, monkeypatch):
    monkeypatch.setenv(notebook.CACHE_ENV, str(tmp_path))
    monkeypatch.setenv(notebook.QUICK_ENV, "1")
    trained = []
    monkeypatch.setattr(notebook.training, "preset_splits", lambda *a, **k: "splits")
    monkeypatch.setattr(notebook.training, "train_models", lambda *a, **k: trained.append(a[1]) or "models")
    monkeypatch.setattr(notebook.training, "evaluate", lambda models, splits: {})
    monkeypatch.setattr(notebook.checkpoints, "save_checkpoint",
                        lambda models, folder, evaluation: folder.mkdir(parents=True))
    monkeypatch.setattr(notebook.checkpoints, "load_models", lambda folder, scenario: ("loaded", folder.name))

    assert notebook.trained_models("2ds", "strong", progress=False) == "models"
    loaded = notebook.trained_models("2ds", "strong", progress=False)
    assert loaded[0] == "loaded" and loaded[1].startswith("2ds-strong-seed0-") and loaded[1].endswith("-quick")
    assert trained == ["strong"]

    changed = dataclasses.replace(presets.get("strong"), mlp_epochs=presets.get("strong").mlp_epochs + 1)
    monkeypatch.setattr(notebook.presets, "get", lambda name: changed)
    assert notebook.trained_models("2ds", "strong", progress=False) == "models"  # not the old model
    assert trained == ["strong", "strong"]
    assert len(list(tmp_path.iterdir())) == 2
