"""Stopping `toolkit reproduce` while it plans: nothing left running, nothing finished lost, a rerun goes on;
stopping `toolkit train`: the output folder as it was.

The reproduction runs in a subprocess from a small script that makes the bridge
test's planning never finish (the script is re-imported by the spawned planning
processes, so the stall is theirs): the three other samplers finish and are cached,
the bridge test's worker is still busy, and then the signal comes. The processes
are found in /proc (Linux).
"""

import json
import os
import shutil
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from toolkit import cli
from toolkit.experiments import pipeline
from toolkit.experiments import reproduce as experiments
from toolkit.experiments.config import RunConfig
from toolkit.experiments.stages import Stages

pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="finds processes in /proc (Linux)"),
]

STALLED_RUN = '''
"""`toolkit ...` whose bridge-test planning never finishes."""
import sys
import time

from toolkit.planning import queries

planned = queries.run_interleaved


def stalled(scenario, query_set, sampler, *args, **kwargs):
    while sampler == "BT":
        time.sleep(1)
    return planned(scenario, query_set, sampler, *args, **kwargs)


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
        start_new_session=True,
    )  # its own process group
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


def test_sigterm_while_training_leaves_the_output_as_it_was(tmp_path):
    out = tmp_path / "ckpt"
    # Many MLP epochs (tens of seconds of training), so the signal lands in training however late a busy machine
    # lets us see it begin; a quick run would finish first, and the signal would meet the process on its way out.
    train = ["train", "--scenario", "2ds", "--quick", "--mlp-epochs", "3000", "--out", str(out)]
    run = subprocess.Popen(
        [sys.executable, "-m", "toolkit", *train],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
        text=True,
    )
    printed = []
    reader = threading.Thread(target=lambda: printed.extend(iter(lambda: run.stderr.read(1), "")), daemon=True)
    reader.start()
    try:
        deadline = time.monotonic() + 600
        while "MLP (paper)" not in "".join(printed):  # its progress bar: the MLP's training has begun
            assert run.poll() is None and time.monotonic() < deadline, "".join(printed)[-3000:]
            time.sleep(0.2)
        run.send_signal(signal.SIGTERM)
        code = run.wait(timeout=60)
    finally:
        run.kill()
        reader.join(timeout=60)
    assert code == 128 + signal.SIGTERM
    assert "".join(printed).splitlines()[-1] == (
        f"toolkit train: stopped by SIGTERM; {out} is as it was (the checkpoint is written only when training "
        "ends); run the same command again to train from the start"
    )
    assert list(tmp_path.iterdir()) == []  # no checkpoint, no half-written folder beside it
