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
corrupted files (saying how to write them again), a checkpoint of another
``FORMAT`` (naming the one it has and the one this toolkit reads: there is no
conversion), a preset whose settings are not this toolkit's, and weights that do
not fit the recorded sizes.
"""

from __future__ import annotations

import json
import platform
from dataclasses import asdict, fields
from pathlib import Path

import numpy as np
import torch

from toolkit import __version__, scenarios
from toolkit.learning.models import CollisionPredictor
from toolkit.learning.presets import Preset
from toolkit.learning.training import TrainedModels
from toolkit.scenarios import Scenario
from toolkit.util import outputs

WEIGHTS, META = "weights.pt", "meta.json"
FORMAT = 2  # of meta.json and weights.pt: a checkpoint of another format is refused, not converted
# (format 2: presets no longer record planner settings; which planner plans with a model is the experiments' choice)


def sizes(predictor: CollisionPredictor) -> dict:
    """The shapes that define the networks: CAE widths, MLP input and hidden widths, input encoding."""
    return {
        "cae": list(predictor.cae.sizes),
        "mlp_in": predictor.mlp.in_features,
        "mlp_hidden": list(predictor.mlp.hidden),
        "encoding": predictor.encoding.kind,
        "patch_radius": predictor.encoding.radius,
    }


def check_destination(folder: str | Path, overwrite: bool = False) -> Path:
    """Refuse, before any training, a ``folder`` that cannot receive a checkpoint: a file, a place that cannot
    be written, a folder holding other things, or (unless ``overwrite``) a checkpoint already."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise ValueError(f"checkpoint folder {folder} is a file; choose a folder")
    if folder.is_dir() and any(folder.iterdir()):
        if not ((folder / META).exists() or (folder / WEIGHTS).exists()):
            raise ValueError(
                f"checkpoint folder {folder} is not empty and holds no checkpoint; choose a new or empty folder"
            )
        if not overwrite:
            raise ValueError(
                f"checkpoint folder {folder} holds a checkpoint already ({_describe(folder)}); replace "
                "it with `toolkit train --force` (overwrite=True), or choose another folder"
            )
    # the checkpoint is written beside the folder, then renamed into place: its parent must be writable
    outputs.writable_folder(folder.parent, f"checkpoint folder {folder}")
    return folder


def save_checkpoint(
    models: TrainedModels, folder: str | Path, evaluation: dict | None = None, *, overwrite: bool = False
) -> Path:
    """Write ``weights.pt`` and ``meta.json`` (with ``evaluation``, if given) into ``folder``; returns the folder.

    The files go to a folder beside it first, which then takes its place
    (:func:`toolkit.util.outputs.write_atomically`): a save stopped by an error or a signal
    leaves the old folder as it was and nothing beside it. An existing checkpoint is
    replaced only with ``overwrite``.
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
        "versions": {
            "toolkit": __version__,
            "torch": torch.__version__,
            "numpy": np.__version__,
            "python": platform.python_version(),
        },
    }
    state = {k: v.detach().cpu() for k, v in models.predictor.state_dict().items()}

    def write(new: Path) -> None:
        new.mkdir()
        torch.save(state, new / WEIGHTS)
        (new / META).write_text(json.dumps(meta, indent=2))

    outputs.write_atomically(folder, write)
    return folder


def load_models(
    folder: str | Path, scenario: str | Scenario | None = None, *, remedy: str | None = None
) -> TrainedModels:
    """Read a checkpoint folder; with ``scenario``, refuse one trained for another scenario, and with a
    :class:`~toolkit.scenarios.Scenario` use that one (else the one its recorded name resolves to).

    A damaged folder is a ``ValueError`` naming the file and ending in ``remedy``
    (default: how to write it again with ``toolkit train``).
    """
    folder = Path(folder)
    if not folder.is_dir():
        what = "is a file, not a folder" if folder.exists() else "does not exist"
        raise FileNotFoundError(f"checkpoint folder {folder} {what}")
    remedy = remedy or f"write it again with `toolkit train ... --force --out {folder}`, or use another checkpoint"
    try:
        meta = _read_meta(folder)
    except ValueError as err:
        raise ValueError(f"{err}; {remedy}") from None
    name = scenario.name if isinstance(scenario, Scenario) else scenario
    if name is not None and meta["scenario"] != name:
        raise ValueError(f"checkpoint {folder} was trained for scenario {meta['scenario']!r}, not {name!r}")
    try:
        return _build(folder, meta, scenario if isinstance(scenario, Scenario) else scenarios.get(meta["scenario"]))
    except ValueError as err:
        raise ValueError(f"{err}; {remedy}") from None


def _build(folder: Path, meta: dict, scenario: Scenario) -> TrainedModels:
    """The networks ``meta`` describes for ``scenario``, with the weights of ``folder``."""
    preset = _read_preset(folder, meta["preset"])
    predictor = preset.build_predictor(scenario)
    if sizes(predictor) != meta["sizes"]:
        raise ValueError(
            f"checkpoint {folder}: recorded sizes {meta['sizes']} differ from the {meta['scenario']!r} "
            f"networks of preset {preset.name!r}, {sizes(predictor)}"
        )
    try:
        predictor.load_state_dict(torch.load(folder / WEIGHTS, map_location="cpu", weights_only=True))
    except FileNotFoundError:
        raise ValueError(f"checkpoint {folder} has no {WEIGHTS}") from None
    except Exception as err:  # unpickling, zip, shape or key errors: the weights cannot be trusted
        raise ValueError(f"checkpoint {folder}: {WEIGHTS} is corrupted or does not match the networks: {err}") from err
    return TrainedModels(scenario, preset, predictor.eval(), int(meta["seed"]), meta["history"])


def _read_preset(folder: Path, recorded) -> Preset:
    """The :class:`Preset` a checkpoint records: every setting of it, none missing or unknown."""
    expected = {f.name for f in fields(Preset)}
    have = set(recorded) if isinstance(recorded, dict) else set()
    if have != expected:
        raise ValueError(
            f"checkpoint {folder}: {META}'s preset does not match this toolkit's Preset (missing "
            f"{sorted(expected - have)}, unknown {sorted(have - expected)})"
        )
    mlp_hidden = recorded["mlp_hidden"]  # a list in JSON
    return Preset(**{**recorded, "mlp_hidden": None if mlp_hidden is None else tuple(mlp_hidden)})


def _describe(folder: Path) -> str:
    """A checkpoint's scenario and preset, for messages."""
    try:
        meta = json.loads((folder / META).read_text())
        return f"scenario {meta['scenario']}, preset {meta['preset']['name']}"
    except (OSError, ValueError, KeyError, TypeError):  # damaged or partial: still a checkpoint folder
        return "its metadata unreadable"


def _read_meta(folder: Path) -> dict:
    """``folder``'s metadata, checked: a JSON object of this toolkit's format, with every key the loader reads."""
    try:
        meta = json.loads((folder / META).read_text())
    except FileNotFoundError:
        raise ValueError(f"checkpoint {folder} has no {META} (metadata missing)") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as err:
        raise ValueError(f"checkpoint {folder}: {META} is corrupted: {err}") from err
    if not isinstance(meta, dict):
        raise ValueError(f"checkpoint {folder}: {META} is corrupted: not a JSON object")
    if meta.get("format") != FORMAT:
        raise ValueError(
            f"checkpoint {folder} has format {meta.get('format', 'none recorded')}, this toolkit reads format {FORMAT}"
        )
    missing = {"scenario", "preset", "sizes", "seed", "history"} - set(meta)
    if missing:
        raise ValueError(f"checkpoint {folder}: {META} lacks {sorted(missing)}")
    return meta
