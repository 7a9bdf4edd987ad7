"""Checkpoint folders: the predictor's ``state_dict`` plus JSON metadata.

A folder written by :func:`save_checkpoint` holds

- ``weights.pt``: ``CollisionPredictor.state_dict()`` (CAE, input encoding, MLP,
  threshold), read back with ``torch.load(..., weights_only=True)``;
- ``meta.json``: scenario, preset, seed, the networks' sizes, the library versions,
  the loss per epoch and (from ``toolkit train``) the evaluation scores.

:func:`save_checkpoint` writes the folder whole or not at all, and replaces an
existing checkpoint only when asked to (``overwrite=True``, ``toolkit train --force``);
:func:`check_destination` says before training whether a folder may receive one.

:func:`load_models` rebuilds the networks from the metadata and refuses, with a
``ValueError`` naming the problem, a folder for another scenario, missing or
corrupted files (saying how to write them again), and weights that do not fit the
recorded sizes.
"""

from __future__ import annotations

import json
import platform
import shutil
from dataclasses import asdict
from pathlib import Path

import numpy as np
import torch

from toolkit import __version__, scenarios
from toolkit.learning import presets
from toolkit.learning.models import CollisionPredictor, build_predictor
from toolkit.learning.presets import Preset
from toolkit.learning.training import TrainedModels
from toolkit.util import outputs

WEIGHTS, META = "weights.pt", "meta.json"
FORMAT = 1


def sizes(predictor: CollisionPredictor) -> dict:
    """The shapes that define the networks: CAE widths, MLP input and hidden widths, input encoding."""
    return {"cae": list(predictor.cae.sizes), "mlp_in": predictor.mlp.in_features, "mlp_hidden": list(predictor.mlp.hidden),
            "encoding": predictor.encoding.kind, "patch_radius": predictor.encoding.radius}


def check_destination(folder: str | Path, overwrite: bool = False) -> Path:
    """Refuse, before any training, a ``folder`` that cannot receive a checkpoint: a file, a place that cannot
    be written, a folder holding other things, or (unless ``overwrite``) a checkpoint already."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"checkpoint folder {folder} is a file; choose a folder")
    if folder.is_dir() and any(folder.iterdir()):
        if not ((folder / META).exists() or (folder / WEIGHTS).exists()):
            raise ValueError(f"checkpoint folder {folder} is not empty and holds no checkpoint; choose a new or "
                             "empty folder")
        if not overwrite:
            raise ValueError(f"checkpoint folder {folder} holds a checkpoint already ({_describe(folder)}); replace "
                             "it with `toolkit train --force` (overwrite=True), or choose another folder")
    # the checkpoint is written beside the folder, then renamed into place: its parent must be writable
    outputs.writable_folder(folder.parent, f"checkpoint folder {folder}")
    return folder


def save_checkpoint(models: TrainedModels, folder: str | Path, evaluation: dict | None = None, *,
                    overwrite: bool = False) -> Path:
    """Write ``weights.pt`` and ``meta.json`` (with ``evaluation``, if given) into ``folder``; returns the folder.

    The files go to a folder beside it first, which then takes its place: an interrupted
    save leaves the old folder as it was. An existing checkpoint is replaced only with ``overwrite``.
    """
    folder = check_destination(folder, overwrite)
    meta = {
        "format": FORMAT,
        "scenario": models.scenario.name,
        "preset": asdict(models.preset),
        "seed": models.seed,
        "threshold": models.threshold,
        "sizes": sizes(models.predictor),
        "history": models.history,
        "evaluation": evaluation,
        "versions": {"toolkit": __version__, "torch": torch.__version__, "numpy": np.__version__,
                     "python": platform.python_version()},
    }
    state = {k: v.detach().cpu() for k, v in models.predictor.state_dict().items()}
    new, old = (folder.with_name(f"{folder.name}.{suffix}.tmp") for suffix in ("new", "old"))
    for leftover in (new, old):  # of a save interrupted earlier
        shutil.rmtree(leftover, ignore_errors=True)
    new.mkdir()
    torch.save(state, new / WEIGHTS)
    (new / META).write_text(json.dumps(meta, indent=2))
    if folder.exists():
        folder.rename(old)
    new.rename(folder)
    shutil.rmtree(old, ignore_errors=True)
    return folder


def load_models(folder: str | Path, scenario: str | None = None, *, remedy: str | None = None) -> TrainedModels:
    """Read a checkpoint folder; with ``scenario``, refuse one trained for another scenario.

    A damaged folder is a ``ValueError`` naming the file and ending in ``remedy``
    (default: how to write it again with ``toolkit train``).
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise FileNotFoundError(f"checkpoint folder {folder} does not exist")
    remedy = remedy or f"write it again with `toolkit train ... --force --out {folder}`, or use another checkpoint"
    try:
        meta = _read_meta(folder)
    except ValueError as err:
        raise ValueError(f"{err}; {remedy}") from None
    if scenario is not None and meta["scenario"] != scenario:
        raise ValueError(f"checkpoint {folder} was trained for scenario {meta['scenario']!r}, not {scenario!r}")
    try:
        return _build(folder, meta)
    except ValueError as err:
        raise ValueError(f"{err}; {remedy}") from None


def _build(folder: Path, meta: dict) -> TrainedModels:
    """The networks ``meta`` describes, with the weights of ``folder``."""
    preset_fields = dict(meta["preset"])
    try:
        # settings added to Preset after the checkpoint was written: those of the preset it names
        preset_fields = {**asdict(presets.get(preset_fields.get("name"))), **preset_fields}
        preset_fields["mlp_hidden"] = tuple(preset_fields["mlp_hidden"]) if preset_fields.get("mlp_hidden") else None
        preset = Preset(**preset_fields)
    except TypeError as err:
        raise ValueError(f"checkpoint {folder}: {META} has an unreadable preset: {err}") from err
    scen = scenarios.get(meta["scenario"])
    predictor = build_predictor(scen, preset.encoding, preset.mlp_hidden, preset.dropout, preset.latent_input)
    if sizes(predictor) != meta["sizes"]:
        raise ValueError(f"checkpoint {folder}: recorded sizes {meta['sizes']} differ from the {meta['scenario']!r} "
                         f"networks of preset {preset.name!r}, {sizes(predictor)}")
    try:
        state = torch.load(folder / WEIGHTS, map_location="cpu", weights_only=True)
        # the input encoding's buffers derive from the scenario; earlier checkpoints stored them, now they are rebuilt
        predictor.load_state_dict({k: v for k, v in state.items() if not k.startswith("encoding.")})
    except FileNotFoundError:
        raise ValueError(f"checkpoint {folder} has no {WEIGHTS}") from None
    except Exception as err:  # unpickling, zip, shape or key errors: the weights cannot be trusted
        raise ValueError(f"checkpoint {folder}: {WEIGHTS} is corrupted or does not match the networks: {err}") from err
    return TrainedModels(scen, preset, predictor.eval(), int(meta.get("seed", 0)), meta.get("history", {}))


def _describe(folder: Path) -> str:
    """A checkpoint's scenario and preset, for messages."""
    try:
        meta = json.loads((folder / META).read_text())
        return f"scenario {meta['scenario']}, preset {meta['preset']['name']}"
    except (OSError, ValueError, KeyError, TypeError):  # damaged or partial: still a checkpoint folder
        return "its metadata unreadable"


def _read_meta(folder: Path) -> dict:
    try:
        meta = json.loads((folder / META).read_text())
    except FileNotFoundError:
        raise ValueError(f"checkpoint {folder} has no {META} (metadata missing)") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as err:
        raise ValueError(f"checkpoint {folder}: {META} is corrupted: {err}") from err
    missing = {"format", "scenario", "preset", "sizes"} - set(meta) if isinstance(meta, dict) else {"everything"}
    if missing:
        raise ValueError(f"checkpoint {folder}: {META} lacks {sorted(missing)}")
    if meta["format"] != FORMAT:
        raise ValueError(f"checkpoint {folder} has format {meta['format']}, this toolkit reads format {FORMAT}")
    return meta
