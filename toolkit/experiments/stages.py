"""A run's stage cache: each stage's product written once, atomically, then reused — so a run resumes.

``toolkit reproduce``, ``ablate`` and ``tune`` run for minutes to hours. Each keeps what
it finished in ``out/cache``: a stage that is done is read back instead of computed
again, and a file is written whole (a temporary file, then a rename) or not at all,
so an interruption (Ctrl-C, SIGTERM) never leaves half a result that a later run
trusts. The folder records the settings of its run; a run with other settings is
refused before any work (:func:`check_out`), since its stages would not apply.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from functools import partial
from pathlib import Path

from toolkit.learning import checkpoints
from toolkit.util import outputs


class Stages:
    """The cache folder of one run: each stage's file is written once, atomically, then reused.

    ``seconds`` holds how long each stage took when it was computed (kept in the cache,
    so a resumed run still reports them); ``recomputed`` the stages this run computed.
    """

    def __init__(self, out: Path, settings: dict, progress: bool):
        check_out(out, settings)
        self.cache = out / "cache"
        if not self.cache.is_dir():  # it appears holding its settings: without them, check_out would refuse `out`
            outputs.write_atomically(self.cache, partial(_new_cache, settings=settings))
        self.progress = progress
        outputs.write_json(self.cache / "settings.json", settings)
        self._seconds_file = self.cache / "stage_seconds.json"
        self.seconds: dict[str, float] = (
            outputs.read_json(self._seconds_file, "delete it (the cached stages' times will read n/a)")
            if self._seconds_file.exists()
            else {}
        )
        self.recomputed: list[str] = []

    def took(self, name: str, seconds: float) -> None:
        """Record that stage ``name`` was computed in ``seconds``."""
        self.seconds[name] = seconds
        self.recomputed.append(name)
        outputs.write_json(self._seconds_file, self.seconds)

    def has(self, name: str) -> bool:
        return (self.cache / f"{name}.json").exists()

    def load(self, name: str) -> dict:
        return outputs.read_json(self.cache / f"{name}.json", "delete it to compute that stage again")

    def save(self, name: str, value: dict, seconds: float) -> None:
        """Store stage ``name``'s JSON ``value`` atomically, computed in ``seconds`` (recorded first: a run
        stopped between the two computes the stage again and records its time again)."""
        self.took(name, seconds)
        outputs.write_json(self.cache / f"{name}.json", value)

    def json(self, name: str, compute: Callable[[], dict]) -> dict:
        """The cached JSON ``name``, or ``compute()`` written atomically."""
        if self.has(name):
            return self.load(name)
        began = time.perf_counter()
        value = compute()
        self.save(name, value, time.perf_counter() - began)
        return value


def _new_cache(folder: Path, settings: dict) -> None:
    """A cache folder holding the run's settings."""
    folder.mkdir()
    outputs.write_json(folder / "settings.json", settings)


def check_out(out: Path, settings: dict) -> None:
    """Refuse, before any work, an output folder that cannot take this run: a file, a place that cannot be
    written, a folder holding something else (a checkpoint, other files), or a run with other settings. A
    folder holding a run with the same settings is what resuming needs."""
    recorded = out / "cache" / "settings.json"
    if out.is_dir() and not recorded.exists() and any(out.iterdir()):
        held = "a checkpoint of `toolkit train`" if (out / checkpoints.META).exists() else "other files"
        raise ValueError(f"--out {out} holds {held}, not a reproduction; choose a new or empty folder")
    outputs.writable_folder(out, "--out")
    if recorded.exists():
        previous = outputs.read_json(recorded, f"delete {out} to start again")
        if previous != settings:
            raise ValueError(
                f"{out} holds a run with other settings {previous}; "
                f"choose another --out, or delete {out} to start again"
            )
