"""Where commands write, checked before they start; files they write whole or not at all, and read back.

A command that runs for minutes must not fail at the end because its output is a
file, read-only, or already holds something else: :func:`writable_folder` and
:func:`writable_file` check (and create the folder) first. :func:`read_json` names a
file that does not parse and says how to recover.

:func:`write_atomically` writes a file or a folder through a temporary beside it
that then takes its place (a rename, which the file system does at once), so an
interrupted write leaves the old output or none, never half of one, and no
temporary. Python runs a signal's handler between any two steps of the main
thread, so Ctrl-C (SIGINT) or SIGTERM could otherwise stop a write after its
temporary exists but before the code that removes it has begun: while a write
runs, :func:`signals_held` makes them wait, and a signal that came throws the new
output away before the old one is touched and then acts as it would have.
"""

from __future__ import annotations

import json
import secrets
import shutil
import signal
import tempfile
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from types import FrameType

HELD = (signal.SIGINT, signal.SIGTERM)  # the signals a write makes wait


def writable_folder(folder: str | Path, what: str) -> Path:
    """Create ``folder`` (and its parents) and make sure files can be written in it; errors begin with ``what``."""
    folder = Path(folder)
    existing = next(p for p in (folder, *folder.parents) if p.exists())  # the folder or where it would go
    if not existing.is_dir():
        raise ValueError(f"{what}: {existing} is a file, not a folder; choose a folder")
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):  # nameless on Linux: nothing to leave behind
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


@contextmanager
def signals_held() -> Iterator[list[int]]:
    """SIGINT and SIGTERM wait until the block ends, then the first that came acts as it would have; yields the
    list of those that came. Handlers run only in the main thread: elsewhere nothing waits, nothing needs to."""
    came: list[int] = []
    if threading.current_thread() is not threading.main_thread():
        yield came
        return
    handlers = {sig: h for sig in HELD if (h := signal.getsignal(sig)) is not None}  # None: set outside Python
    holding = True

    def note(signum: int, frame: FrameType | None) -> None:
        if holding:
            came.append(signum)
        else:  # a signal cut the restoring below short and left this handler in place: act as the old one
            signal.signal(signum, handlers[signal.Signals(signum)])
            signal.raise_signal(signum)

    try:
        for sig in handlers:
            signal.signal(sig, note)
        yield came
    finally:
        holding = False
        for sig, handler in handlers.items():
            signal.signal(sig, handler)
        if came:
            signal.raise_signal(came[0])  # the old handler acts now: raises, ends the process, or ignores it


def write_atomically(path: str | Path, write: Callable[[Path], object]) -> Path:
    """Write the file or folder ``path`` whole or not at all; returns it.

    ``write(tmp)`` makes a file or folder at ``tmp``, a name beside ``path`` that keeps its
    suffix (``np.savez`` and ``savefig`` read it); then one rename puts ``tmp`` in the place of
    ``path``. SIGINT and SIGTERM wait meanwhile: one that came before that rename, or an
    error, removes ``tmp`` and leaves ``path`` as it was.
    """
    path = Path(path)
    token = secrets.token_hex(4)  # two processes may write the same path at once (two notebooks, one cache)
    tmp, old = (path.with_name(f"{path.stem}.{token}.{tag}.tmp{path.suffix}") for tag in ("new", "old"))
    with signals_held() as came:
        try:
            write(tmp)
            _put_in_place(tmp, path, old, came)
        finally:
            _remove(tmp)
            _remove(old)
    return path


def _put_in_place(tmp: Path, path: Path, old: Path, came: list[int]) -> None:
    """Rename ``tmp`` to ``path`` unless a signal ``came``: that one rename replaces the old output with the new.
    A folder at ``path`` moves to ``old`` first (a rename cannot replace a folder that holds files), and back
    unless the new one took its place."""
    moved = tmp.is_dir() and path.is_dir()
    if moved:
        path.rename(old)
    try:
        if not came:
            tmp.replace(path)
            moved = False
    finally:
        if moved:
            old.rename(path)


def _remove(path: Path) -> None:
    """Remove the file or folder ``path`` if it is there."""
    if path.is_dir():
        shutil.rmtree(path)
    else:
        path.unlink(missing_ok=True)


def write_json(path: str | Path, value) -> Path:
    """Write ``value`` as JSON, whole or not at all (:func:`write_atomically`)."""
    text = json.dumps(value, indent=2)
    return write_atomically(path, lambda tmp: tmp.write_text(text))
