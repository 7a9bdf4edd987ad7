"""Where commands write, checked before they start; files they read back, with errors that say what to do.

A command that runs for minutes must not fail at the end because its output is a
file, read-only, or already holds something else: :func:`writable_folder` and
:func:`writable_file` check (and create the folder) first. :func:`read_json` names a
file that does not parse and says how to recover. :func:`write_json` writes
atomically (a temporary file, then a rename), so an interrupted write leaves the
old file or none, never half of one.
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path


def writable_folder(folder: str | Path, what: str) -> Path:
    """Create ``folder`` (and its parents) and make sure files can be written in it; errors begin with ``what``."""
    folder = Path(folder)
    existing = next(p for p in (folder, *folder.parents) if p.exists())  # the folder or where it would go
    if not existing.is_dir():
        raise ValueError(f"{what}: {existing} is a file, not a folder; choose a folder")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as err:
        raise ValueError(f"{what}: cannot write in {folder} ({err.strerror or err})") from None
    return folder


def writable_file(path: str | Path, what: str) -> Path:
    """Make sure the file ``path`` can be written (its folder is created); errors begin with ``what``."""
    path = Path(path)
    if path.is_dir():
        raise ValueError(f"{what}: {path} is a folder; give a file name")
    writable_folder(path.parent, f"{what} {path}")
    return path


def read_json(path: str | Path, advice: str):
    """The JSON in ``path``; a ``ValueError`` naming the file and giving ``advice`` when it does not parse."""
    path = Path(path)
    try:
        return json.loads(path.read_text())
    except (json.JSONDecodeError, UnicodeDecodeError) as err:
        raise ValueError(f"{path} is damaged ({err}); {advice}") from None


def write_json(path: Path, value) -> None:
    """Write ``value`` as JSON atomically: a temporary file, then a rename."""
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(value, indent=2))
    tmp.replace(path)
