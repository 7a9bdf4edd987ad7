"""toolkit.teaching.notebook.trained_models: trains once, then loads; a changed preset trains anew."""

import dataclasses
import json

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


def test_trained_scores_are_the_checkpoints_evaluation(tmp_path, monkeypatch):
    monkeypatch.setenv(notebook.CACHE_ENV, str(tmp_path))
    monkeypatch.setenv(notebook.QUICK_ENV, "1")
    scores = {"cae": {"seen_acc": 0.9}, "mlp": {"unseen": {"acc": 0.55}}}

    def train_and_save(config, folder):
        folder.mkdir(parents=True)
        (folder / "meta.json").write_text(json.dumps({"evaluation": scores}))
        return "models", scores, folder

    monkeypatch.setattr(notebook.pipeline, "train_and_save", train_and_save)
    monkeypatch.setattr(notebook.checkpoints, "load_models", lambda folder, scenario: "loaded")
    assert notebook.trained_scores("2ds", "paper", progress=False) == scores  # trains, then reads
    assert notebook.trained_scores("2ds", "paper", progress=False) == scores  # reads the cached folder


@dataclasses.dataclass(frozen=True)
class SweepSizes:
    """Sizes a notebook names as one (as chapter 04's crossover sizes): the banner lists their fields."""

    blocks: tuple[int, ...]
    batch: int


def test_banner_says_what_quick_mode_shrinks(monkeypatch, capsys):
    monkeypatch.setattr(notebook, "NAMED_SIZES", {})
    monkeypatch.setenv(notebook.QUICK_ENV, "1")
    assert notebook.sized(full=20_000, quick=2_000, what="configurations per check") == 2_000
    assert notebook.sized(full=range(8), quick=range(5, 8), what="queries") == range(5, 8)
    sweep = notebook.sized(full=SweepSizes((10, 500), 10_000), quick=SweepSizes((10,), 500), what="sweep")
    notebook.banner(models=[("2ds", "paper"), ("3dc7", "strong")])
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("QUICK MODE (TOOLKIT_QUICK=1)")
    assert lines[1] == "  configurations per check: 2,000 (full size: 20,000)"
    assert lines[2] == "  queries: 3 (5..7) (full size: 8 (0..7))"
    assert sweep.batch == 500 and lines[3] == "  sweep: blocks 10; batch 500 (full size: blocks 10/500; batch 10,000)"
    del lines[3]
    paper, strong = presets.get("paper"), presets.get("strong")
    quick_paper = QUICK.shrink(paper)
    assert lines[3].startswith(
        f"  2ds/paper model: training workspaces {QUICK.workspaces[0]} (full size 30), "
        f"labelled configurations each 100, MLP epochs {quick_paper.mlp_epochs} (full size {paper.mlp_epochs}), "
        f"CAE epochs {quick_paper.cae_epochs} "
    )
    assert lines[4].endswith("its CAE is not trained (this MLP does not read z)")
    assert f"MLP epochs {QUICK.shrink(strong).mlp_epochs} (full size {strong.mlp_epochs})" in lines[4]
    monkeypatch.setenv(notebook.QUICK_ENV, "0")
    notebook.banner(models=[("2ds", "paper")])
    assert capsys.readouterr().out.startswith("Full size:")  # one line, no sizes
