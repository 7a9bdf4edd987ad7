"""toolkit.teaching.notebook.trained_models: trains once, then loads; a changed preset trains anew."""

import dataclasses

from toolkit.experiments.config import QUICK
from toolkit.learning import presets
from toolkit.teaching import notebook


def test_models_are_trained_once_and_retrained_when_the_preset_changes(tmp_path, monkeypatch):
    monkeypatch.setenv(notebook.CACHE_ENV, str(tmp_path))
    monkeypatch.setenv(notebook.QUICK_ENV, "1")
    trained = []

    def train_and_save(config, folder):
        trained.append(config.preset)
        folder.mkdir(parents=True)
        return "models", {}, folder

    monkeypatch.setattr(notebook.pipeline, "train_and_save", train_and_save)
    monkeypatch.setattr(notebook.checkpoints, "load_models", lambda folder, scenario: ("loaded", folder.name))

    assert notebook.trained_models("2ds", "strong", progress=False) == "models"
    loaded = notebook.trained_models("2ds", "strong", progress=False)
    assert loaded[0] == "loaded" and loaded[1].startswith("2ds-strong-seed0-") and loaded[1].endswith("-quick")
    assert [p.name for p in trained] == ["strong"] and trained[0].quick  # quick mode: the quick-sized recipe

    changed = dataclasses.replace(presets.get("strong"), mlp_epochs=presets.get("strong").mlp_epochs + 1)
    monkeypatch.setitem(presets.PRESETS, "strong", changed)
    assert notebook.trained_models("2ds", "strong", progress=False) == "models"  # not the old model
    assert len(trained) == 2 and trained[1] == QUICK.shrink(changed)
    assert len(list(tmp_path.iterdir())) == 2
