"""A signal stops a command cleanly: nothing left running, nothing finished lost, no output half-written.

- `toolkit reproduce` stopped while it plans: every process ends, the finished samplers are
  kept and a rerun goes on. The reproduction runs in a subprocess from a small script
  that makes the bridge test's planning never finish (the script is re-imported by the
  spawned planning processes, so the stall is theirs): the three other samplers plan two
  queries each, finish and are cached, the bridge test's worker is still busy, and then the signal comes.
  The processes are found in /proc (Linux).
- `toolkit train` stopped while it trains, saves the weights or renames the new
  checkpoint into place (a script signals it at that point): the output folder as it
  was, nothing beside it.
- A signal at every line an atomic write runs (:func:`toolkit.util.outputs.write_atomically`,
  :func:`toolkit.learning.checkpoints.save_checkpoint`), traced in-process: the old output
  until the rename that puts the new one in place, the new one after it, whole, and
  nothing else in the folder.
"""

import dataclasses
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path
from unittest.mock import ANY

import pytest

from toolkit import cli
from toolkit.experiments import pipeline, stages
from toolkit.experiments import reproduce as experiments
from toolkit.experiments.config import RunConfig
from toolkit.experiments.stages import Stages
from toolkit.learning import checkpoints
from toolkit.util import outputs

pytestmark = pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="finds processes in /proc (Linux)")

STALLED_RUN = '''
"""`toolkit ...` whose bridge-test planning never finishes, while the other samplers plan two queries each (what
is tested is the stop, not the planning)."""
import sys
import time

from toolkit.experiments import queries

planned = queries.run_interleaved


def stalled(scenario, query_set, sampler, *args, **kwargs):
    while sampler == "BT":
        time.sleep(1)
    return planned(scenario, query_set[:2], sampler, *args, **kwargs)


queries.run_interleaved = stalled
if __name__ == "__main__":
    from toolkit import cli

    raise SystemExit(cli.main(sys.argv[1:]))
'''
ARGS = ["reproduce", "--scenario", "2ds", "--preset", "strong", "--quick", "--workers", "2"]
FINISHED = ["planning_BS", "planning_OB", "planning_G"]


def _stat(pid: int) -> list[str] | None:
    """The fields after the command name in /proc/PID/stat (state, parent, ...), or None when gone."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except OSError:
        return None


def descendants(pid: int) -> set[int]:
    """Every process below ``pid``."""
    children: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and (fields := _stat(int(entry.name))):
            children.setdefault(int(fields[1]), []).append(int(entry.name))
    found, todo = set(), [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.add(child)
            todo.append(child)
    return found


def alive(pid: int) -> bool:
    fields = _stat(pid)
    return fields is not None and fields[0] != "Z"  # a zombie has ended; only its parent has yet to notice


@pytest.fixture
def out(tmp_path, checkpoint_2ds):
    """A run folder holding the data and models stages already (they are not what is tested here)."""
    out = tmp_path / "run"
    config = RunConfig.create("2ds", "strong", quick=True, progress=False)
    cache = Stages(out, config.settings(), progress=False).cache
    for name, dataset in pipeline.make_splits(config).items():
        dataset.save(cache / f"data_{name}.npz")
    shutil.copytree(checkpoint_2ds, cache / "checkpoint")
    return out


@pytest.mark.slow
@pytest.mark.parametrize(
    "sig, whom",
    [(signal.SIGINT, "group"), (signal.SIGINT, "parent"), (signal.SIGTERM, "parent"), (signal.SIGKILL, "parent")],
    ids=["ctrl-c", "sigint-parent", "sigterm", "sigkill"],
)
def test_a_signal_during_planning_stops_every_process_and_keeps_the_finished_samplers(
    sig: signal.Signals, whom: str, out: Path, tmp_path: Path
) -> None:
    script = tmp_path / "stalled_run.py"
    script.write_text(STALLED_RUN)
    run = subprocess.Popen(
        [sys.executable, str(script), *ARGS, "--out", str(out)],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own process group
    )
    workers: set[int] = set()
    try:
        deadline = time.monotonic() + 600  # generous: imports and spawns crawl on a busy machine
        while not all((out / "cache" / f"{name}.json").exists() for name in FINISHED):
            assert run.poll() is None, f"the run ended early:\n{run.communicate()[1][-3000:]}"
            assert time.monotonic() < deadline, "the three samplers did not finish in 10 minutes"
            time.sleep(0.2)
        workers = descendants(run.pid)
        assert len(workers) >= 2  # the planning processes, one of them stuck in the bridge test
        (os.killpg if whom == "group" else os.kill)(run.pid, sig)
        stopped = time.monotonic()
        code = run.wait(timeout=60)
        took = time.monotonic() - stopped
        deadline = time.monotonic() + 30  # after SIGKILL the workers notice their parent is gone within a second
        while any(map(alive, workers)) and time.monotonic() < deadline:
            time.sleep(0.2)
        left = [pid for pid in workers if alive(pid)]
    finally:
        for pid in [run.pid, *workers]:  # whatever happened above, leave nothing running (they hold its pipes)
            if alive(pid):
                os.kill(pid, signal.SIGKILL)
        stderr = run.communicate(timeout=60)[1]
    assert not left, f"processes left behind: {left}"
    assert code == (128 + sig if sig != signal.SIGKILL else -sig), stderr[-3000:]
    assert took < 30, f"{took:.1f} s to stop"
    assert experiments.finished_stages(out) == ["data", "models", "learning"] + FINISHED
    if sig != signal.SIGKILL:
        name = signal.Signals(sig).name
        assert stderr.splitlines()[-1] == (
            f"toolkit reproduce: stopped by {name}; kept the finished stages in {out} (2ds: data, models, learning, "
            "planning_BS, planning_OB, planning_G); run the same command again to go on from there"
        )
        assert "Traceback" not in stderr

    assert cli.main([*ARGS, "--out", str(out)]) == 0  # the same command, without the stall
    results = json.loads((out / "results.json").read_text())
    assert results["recomputed"] == ["planning_BT", "throughput"]
    assert set(results["planning"]) == {"BS", "OB", "G", "BT"}


SIGNALLED_TRAIN = '''
"""`toolkit train ...` that meets a signal at POINT (argv[1]): stalled in the MLP's training until one comes,
or sending itself SIGNAL (argv[2]) as it saves the weights or renames a folder of the new checkpoint."""
import signal
import sys
import time
from pathlib import Path

import torch

from toolkit import cli
from toolkit.learning import training

POINT, SIGNAL = sys.argv[1], signal.Signals[sys.argv[2]]


def stalled(*args, **kwargs):
    print("training the MLP", file=sys.stderr, flush=True)
    while True:
        time.sleep(0.1)


def signalling(real):
    def call(*args, **kwargs):
        signal.raise_signal(SIGNAL)  # to this thread, at once (os.kill may reach another thread, and later)
        return real(*args, **kwargs)

    return call


if POINT == "training":
    training.train_mlp = stalled
elif POINT == "saving":
    torch.save = signalling(torch.save)
elif POINT == "renaming":
    Path.rename, Path.replace = signalling(Path.rename), signalling(Path.replace)
raise SystemExit(cli.main(sys.argv[3:]))
'''


def _contents(folder: Path) -> dict[str, bytes | None]:
    """Everything under ``folder`` by relative path: a file's bytes, None for a folder (an empty one counts)."""
    return {str(p.relative_to(folder)): p.read_bytes() if p.is_file() else None for p in sorted(folder.rglob("*"))}


@pytest.mark.slow
@pytest.mark.parametrize(
    "point, sig, existing",
    [
        ("training", signal.SIGTERM, False),
        ("saving", signal.SIGTERM, False),
        ("saving", signal.SIGTERM, True),
        ("renaming", signal.SIGINT, True),
    ],
    ids=["training", "saving", "saving-force", "renaming-force-sigint"],
)
def test_a_signal_while_training_leaves_the_output_as_it_was(
    point: str, sig: signal.Signals, existing: bool, tmp_path: Path, checkpoint_2ds: Path
) -> None:
    script, out = tmp_path / "signalled_train.py", tmp_path / "outputs" / "ckpt"
    script.write_text(SIGNALLED_TRAIN)
    out.parent.mkdir()
    if existing:  # `--force` replaces it: until the new one is whole, it must stay as it was
        shutil.copytree(checkpoint_2ds, out)
    before = _contents(out.parent)
    train = ["train", "--scenario", "2ds", "--quick", "--seed", "1", "--out", str(out), *(["--force"] * existing)]
    run = subprocess.Popen(
        [sys.executable, str(script), point, sig.name, *train],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    printed: list[str] = []
    stderr = run.stderr
    assert stderr is not None
    reader = threading.Thread(target=lambda: printed.extend(iter(lambda: stderr.read(1), "")), daemon=True)
    reader.start()
    try:
        if point == "training":  # the signal comes from outside, while the MLP trains (for ever)
            deadline = time.monotonic() + 600  # generous: imports crawl on a busy machine
            while "training the MLP" not in "".join(printed):
                assert run.poll() is None and time.monotonic() < deadline, "".join(printed)[-3000:]
                time.sleep(0.2)
            run.send_signal(sig)
        code = run.wait(timeout=600)
    finally:
        run.kill()
        reader.join(timeout=60)
    assert code == 128 + sig, "".join(printed)[-3000:]
    assert "".join(printed).splitlines()[-1] == (
        f"toolkit train: stopped by {sig.name}; {out} is as it was (the checkpoint is written only when training "
        "ends); run the same command again to train from the start"
    )
    assert _contents(out.parent) == before  # the old checkpoint or none, byte for byte, and nothing beside it
    assert sorted(p.name for p in out.parent.iterdir()) == (["ckpt"] if existing else [])


def _signal_at_line(n: int | None, sig: signal.Signals, files: set[str], lines: list[str]) -> Callable:
    """A trace function (``sys.settrace``) that raises ``sig`` before the ``n``-th line run in ``files`` (never
    when ``n`` is None); every line run there is appended to ``lines`` as ``file:line``."""

    def local(frame, event, arg):
        if event == "line":
            if len(lines) == n:
                signal.raise_signal(sig)  # its handler runs here, as if the signal came before this line
            lines.append(f"{Path(frame.f_code.co_filename).name}:{frame.f_lineno}")
        return local

    return lambda frame, event, arg: local if frame.f_code.co_filename in files else None


def _signal_at_every_line(
    make_old: Callable[[Path], object], run: Callable[[Path], object], sig: signal.Signals, tmp_path: Path
) -> tuple[list[str], Path, list[Path]]:
    """Run ``run(folder)`` under the CLI's signal handling once per line it runs in the toolkit's writing modules
    (and this file), ``sig`` raised before that line, each time in a fresh ``folder`` made by ``make_old``; the
    lines, a folder where it ran without a signal, and the folders the signals left (each signal must act)."""
    files = {outputs.__file__, checkpoints.__file__, stages.__file__, __file__}

    def fresh(name: str) -> Path:
        folder = tmp_path / name
        folder.mkdir(parents=True)
        make_old(folder)
        return folder

    lines: list[str] = []
    whole = fresh("whole")
    sys.settrace(_signal_at_line(None, sig, files, lines))
    try:
        run(whole)
    finally:
        sys.settrace(None)
    left = []
    for n in range(len(lines)):
        folder = fresh(f"signal-at-{n}")
        with pytest.raises(cli.Interrupted) as stopped, cli.signals_interrupt():
            sys.settrace(_signal_at_line(n, sig, files, []))
            try:
                run(folder)
            finally:
                sys.settrace(None)
        assert stopped.value.signum == sig, lines[n]
        left.append(folder)
    return lines, whole, left


def _old_or_new(
    make_old: Callable[[Path], object], write_new: Callable[[Path], object], sig: signal.Signals, tmp_path: Path
) -> tuple[list[str], list[str]]:
    """:func:`_signal_at_every_line` for a write: the lines, and what the signal before each left, "old" (as
    ``make_old`` left the folder) or "new" (as the whole write does). Anything else (a temporary left, a
    mixture) fails here."""
    lines, whole, folders = _signal_at_every_line(make_old, write_new, sig, tmp_path)
    old = tmp_path / "old"
    old.mkdir()
    make_old(old)
    reference = {"old": _contents(old), "new": _contents(whole)}
    left = []
    for line, folder in zip(lines, folders):
        state = [name for name, there in reference.items() if _contents(folder) == there]
        assert state, f"a signal before {line} left {sorted(_contents(folder))}"
        left.append(state[0])
    return lines, left


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT], ids=["sigterm", "sigint"])
@pytest.mark.parametrize("kind", ["folder", "file", "new folder"])
def test_a_signal_at_any_line_of_a_write_leaves_the_old_output_or_the_new_whole(kind, sig, tmp_path):
    def make_old(folder: Path) -> None:
        if kind == "folder":
            (folder / "out").mkdir()
            (folder / "out" / "a.txt").write_text("old a")
        elif kind == "file":
            (folder / "out.json").write_text('"old"')

    def write_folder(tmp: Path) -> None:
        tmp.mkdir()
        (tmp / "a.txt").write_text("new a")
        (tmp / "b.txt").write_text("new b")

    if kind == "file":
        write_new = lambda folder: outputs.write_json(folder / "out.json", "new")
    else:
        write_new = lambda folder: outputs.write_atomically(folder / "out", write_folder)
    lines, left = _old_or_new(make_old, write_new, sig, tmp_path / "runs")
    kept = left.count("old")
    assert left == ["old"] * kept + ["new"] * (len(left) - kept), list(zip(lines, left))
    first_new = lines[kept]  # the first line before which a signal no longer keeps the old output: the rename
    source = Path(outputs.__file__).read_text().splitlines()[int(first_new.split(":")[1]) - 1]
    assert re.search(r"tmp\.replace\(path\)", source), (first_new, source)


def test_a_signal_at_any_line_of_saving_a_checkpoint_leaves_the_old_one_or_the_new_one(checkpoint_2ds, tmp_path):
    models = checkpoints.load_models(checkpoint_2ds)
    retrained = dataclasses.replace(models, seed=models.seed + 1)  # another checkpoint: its meta.json differs
    lines, left = _old_or_new(
        lambda folder: shutil.copytree(checkpoint_2ds, folder / "ckpt"),
        lambda folder: checkpoints.save_checkpoint(retrained, folder / "ckpt", overwrite=True),
        signal.SIGTERM,
        tmp_path,
    )
    kept = left.count("old")
    assert left == ["old"] * kept + ["new"] * (len(left) - kept), list(zip(lines, left))
    assert kept > len(lines) // 2  # a signal anywhere in the writing keeps the old checkpoint


def test_a_signal_at_any_line_of_starting_a_run_leaves_a_folder_the_rerun_takes(tmp_path):
    settings = RunConfig.create("2ds", "strong", quick=True, progress=False).settings()
    start = lambda folder: Stages(folder / "run", settings, progress=False)
    lines, whole, left = _signal_at_every_line(lambda folder: None, start, signal.SIGTERM, tmp_path)
    assert _contents(whole) == {"run": None, "run/cache": None, "run/cache/settings.json": ANY}
    for line, folder in zip(lines, left):
        start(folder)  # the rerun: check_out takes what the signal left (a cache folder without settings it refuses)
        assert _contents(folder) == _contents(whole), line


@pytest.fixture
def python_sigint():
    """Python's own SIGINT handler (KeyboardInterrupt), as in a notebook, whatever this process started with (a
    shell's background job starts with SIGINT ignored); the handler before afterwards."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)


def test_signals_wait_until_a_write_is_done_and_then_act_as_they_would_have(tmp_path, python_sigint):
    ran_on = []
    with pytest.raises(KeyboardInterrupt), outputs.signals_held() as came:
        signal.raise_signal(signal.SIGINT)
        ran_on.append(list(came))  # still runs: the signal waits
    assert ran_on == [[signal.SIGINT]]
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    with outputs.signals_held() as came:  # an ignored signal waits too, and then is ignored
        signal.raise_signal(signal.SIGINT)
    assert came == [signal.SIGINT] and signal.getsignal(signal.SIGINT) == signal.SIG_IGN
    signal.signal(signal.SIGINT, signal.default_int_handler)

    def interrupted_write(tmp: Path) -> None:
        tmp.write_text("new")
        signal.raise_signal(signal.SIGINT)

    with pytest.raises(KeyboardInterrupt):
        outputs.write_atomically(tmp_path / "out.txt", interrupted_write)
    assert list(tmp_path.iterdir()) == []  # the write that met the signal was thrown away
    done = []
    worker = threading.Thread(target=lambda: done.append(outputs.write_json(tmp_path / "t.json", [1])))
    worker.start()
    worker.join()
    assert done == [tmp_path / "t.json"] and json.loads((tmp_path / "t.json").read_text()) == [1]
