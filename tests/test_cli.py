"""The ``toolkit`` command before and around the work: help, argument checks, output checks, threads.

Every bad input must end in one line that names the problem, before any work is
done and without hanging (issue 16). Interrupts are in ``test_interrupts.py``.
"""

import dataclasses
import json
import os
import shutil
import subprocess
import sys

import pytest
import torch
from threadpoolctl import threadpool_info

from toolkit import cli, scenarios, viewer
from toolkit.experiments import pipeline
from toolkit.experiments import reproduce as experiments
from toolkit.experiments.config import RunConfig
from toolkit.experiments.stages import Stages
from toolkit.geometry.robots import BoxRobot, Link
from toolkit.learning import checkpoints, training
from toolkit.learning.data import SPLITS
from toolkit.util import threads

COMMANDS = ("reproduce", "train", "plan", "bench", "view")


def subparsers() -> dict:
    parser = cli.build_parser()
    choices = next(a for a in parser._actions if a.dest == "command").choices
    assert isinstance(choices, dict)
    return choices


# -- help ---------------------------------------------------------------------------------------------


def test_help_names_the_scenarios_samplers_and_commands_in_words(capsys):
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    text = capsys.readouterr().out
    for words in (
        "3D office, youBot-like 8-DoF",
        "3D clutter, 9-DoF box chain",
        "bridge test",
        "obstacle-based",
        "Gaussian",
        "uniform random configurations",
        "TOOLKIT_THREADS",
        "examples:",
    ):
        assert words in text
    for name in COMMANDS:
        assert f"\n  {name} " in text  # listed with its summary


@pytest.mark.parametrize("name", COMMANDS)
def test_every_option_is_explained_in_plain_text(name, capsys):
    sub = subparsers()[name]
    for action in sub._actions:
        assert action.help, f"toolkit {name} {action.option_strings}: no help"
    with pytest.raises(SystemExit):
        cli.main([name, "--help"])
    text = capsys.readouterr().out
    assert "``" not in text and ":func:" not in text and ":mod:" not in text  # no reStructuredText
    assert "\nexamples:\n  toolkit " + name in text


# -- arguments ------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "argv, message",
    [
        (["view", "--port", "70000"], "argument --port: must be 0..65535, got 70000"),
        (["view", "--port", "-1"], "argument --port: must be 0..65535, got -1"),
        (["view", "--port", "http"], "argument --port: must be a whole number, 0..65535; got 'http'"),
        (["view", "--samples", "1000000"], "argument --samples: must be 0..100000, got 1000000"),
        (["plan", "--scenario", "2ds", "--seed", "-3"], "argument --seed: must be 0..4294967295, got -3"),
        (
            ["reproduce", "--scenario", "2ds", "--out", "x", "--workers", "0"],
            "argument --workers: must be 1 or more, got 0",
        ),
        (["bench", "--scenario", "2ds", "--pairs", "11"], "argument --pairs: must be 1..10, got 11"),
        (["bench", "--scenario", "2ds", "--workspaces", "0"], "argument --workspaces: must be 1..100, got 0"),
        (
            ["train", "--scenario", "2ds", "--out", "x", "--mlp-epochs", "0"],
            "argument --mlp-epochs: must be 1 or more, got 0",
        ),
    ],
)
def test_numbers_are_checked_by_the_parser_with_the_flag_named(argv, message, capsys):
    with pytest.raises(SystemExit) as exit_info:
        cli.main(argv)
    assert exit_info.value.code == 2
    assert capsys.readouterr().err.strip().endswith(message)


def test_plan_refuses_a_checkpoint_of_another_scenario_by_name(checkpoint_2ds, capsys):
    args = ["plan", "--scenario", "3dc7", "--sampler", "BS", "--predict", "--checkpoint", str(checkpoint_2ds)]
    assert cli.main([*args, "--seed", "0"]) == 2
    err = capsys.readouterr().err
    assert f"checkpoint {checkpoint_2ds} was trained for scenario '2ds', not '3dc7'" in err


WALLED_IN = dataclasses.replace(  # a square as wide as the 2DS region: every configuration meets a block
    scenarios.get("2ds"),
    name="walled-in",
    robot=BoxRobot("wide", "point2d", [Link((15.0, 15.0, 0.0))], [], position_bounds=([15.0] * 2, [16.0] * 2)),
)


@pytest.mark.parametrize(
    "argv, message",
    [
        (["plan", "--scenario", "2ds", "--option", "k=abc"], "LazyParams.k must be a positive integer, got 'abc'"),
        (
            ["plan", "--scenario", "2ds", "--planner", "rrt-connect", "--option", "range=far"],
            "RRTConnectParams.range must be positive and finite, got 'far'",
        ),
        (
            ["plan", "--scenario", "walled-in"],
            "found no 1 valid start/goal pairs far enough apart in this walled-in workspace",
        ),
        (
            ["plan", "--scenario", "2ds", "--predict", "--checkpoint", "{file}"],
            "checkpoint folder {file} is a file, not a folder",
        ),
        (
            ["train", "--scenario", "2ds", "--quick", "--device", "tpu", "--out", "{tmp}/c"],
            "--device 'tpu' is not a torch device; use cpu or cuda",
        ),
    ],
)
def test_foreseeable_errors_end_in_one_line(argv, message, tmp_path, monkeypatch, no_training, capsys):
    """Issue 48: a bad option value, an unsolvable query set, a checkpoint that is a file, a device the machine has
    not: one line naming the problem, exit code 2, no traceback (each was a traceback or a wrong message before)."""
    monkeypatch.setitem(scenarios.SCENARIOS, WALLED_IN.name, WALLED_IN)
    (tmp_path / "notes.txt").write_text("not a checkpoint")
    fill = {"file": tmp_path / "notes.txt", "tmp": tmp_path}
    assert cli.main([arg.format(**fill) for arg in argv]) == 2
    assert capsys.readouterr().err.splitlines() == [f"toolkit {argv[0]}: error: {message.format(**fill)}"]


def test_view_refuses_a_bad_checkpoint_in_the_terminal_before_serving(tmp_path, checkpoint_2ds, capsys, monkeypatch):
    def no_server(*args, **kwargs):
        raise AssertionError("a server was started")

    monkeypatch.setattr(viewer.server.viser, "ViserServer", no_server)
    assert cli.main(["view", "--checkpoint", str(tmp_path / "missing")]) == 2
    assert capsys.readouterr().err == f"toolkit view: error: checkpoint folder {tmp_path / 'missing'} does not exist\n"
    assert cli.main(["view", "--scenario", "3do", "--checkpoint", str(checkpoint_2ds)]) == 2
    assert "trained for scenario '2ds', not '3do'" in capsys.readouterr().err
    damaged = shutil.copytree(checkpoint_2ds, tmp_path / "damaged")
    (damaged / checkpoints.META).write_text('{"format": 1, "scen')
    assert cli.main(["view", "--checkpoint", str(damaged)]) == 2
    err = capsys.readouterr().err
    assert f"checkpoint {damaged}: meta.json is corrupted" in err
    assert err.rstrip().endswith(
        f"write it again with `toolkit train ... --force --out {damaged}`, or use another checkpoint"
    )


@pytest.mark.parametrize(
    "host, message",
    [
        ("192.0.2.1", "cannot serve on 192.0.2.1:8080: Cannot assign requested address"),  # not this computer's
        ("no-such-host.invalid", "cannot serve on host 'no-such-host.invalid'"),
    ],
)
def test_view_on_a_host_it_cannot_serve_on_says_so_instead_of_hanging(host, message):
    done = subprocess.run(
        [sys.executable, "-m", "toolkit", "view", "--scenario", "2ds", "--host", host],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 2
    assert done.stderr.startswith(f"toolkit view: error: {message}")


def test_free_port_moves_past_busy_ports_and_stops_at_the_last_one():
    import socket

    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen()
        port = busy.getsockname()[1]
        assert viewer.free_port("127.0.0.1", port) > port
        with pytest.raises(ValueError, match=f"ports {port}..{port} on 127.0.0.1 are all busy"):
            viewer.free_port("127.0.0.1", port, tries=1)


# -- outputs: train -------------------------------------------------------------------------------------


@pytest.fixture
def no_training(monkeypatch):
    """Fail the test if training starts: the checks must come first."""

    def trained(*args, **kwargs):
        raise AssertionError("training started before the output was checked")

    monkeypatch.setattr(training, "train_models", trained)


def test_train_refuses_a_file_or_a_place_under_a_file_before_training(tmp_path, no_training, capsys):
    (tmp_path / "notes.txt").write_text("mine")
    assert cli.main(["train", "--scenario", "2ds", "--quick", "--out", str(tmp_path / "notes.txt")]) == 2
    assert f"checkpoint folder {tmp_path / 'notes.txt'} is a file" in capsys.readouterr().err
    assert cli.main(["train", "--scenario", "2ds", "--quick", "--out", str(tmp_path / "notes.txt" / "ckpt")]) == 2
    assert f"{tmp_path / 'notes.txt'} is a file, not a folder" in capsys.readouterr().err
    assert (tmp_path / "notes.txt").read_text() == "mine"


@pytest.mark.skipif(hasattr(os, "geteuid") and os.geteuid() == 0, reason="root writes in read-only folders")
def test_train_refuses_a_read_only_folder_before_training(tmp_path, no_training, capsys):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        assert cli.main(["train", "--scenario", "2ds", "--quick", "--out", str(locked / "ckpt")]) == 2
        assert f"cannot write in {locked}" in capsys.readouterr().err
    finally:
        locked.chmod(0o700)


def test_train_never_replaces_a_checkpoint_without_force(tmp_path, checkpoint_2ds, no_training, capsys):
    existing = shutil.copytree(checkpoint_2ds, tmp_path / "ckpt")
    before = (existing / checkpoints.META).read_text()
    assert cli.main(["train", "--scenario", "3dc7", "--quick", "--out", str(existing)]) == 2
    err = capsys.readouterr().err
    assert "holds a checkpoint already (scenario 2ds, preset strong)" in err and "toolkit train --force" in err
    assert (existing / checkpoints.META).read_text() == before
    other = tmp_path / "other"
    other.mkdir()
    (other / "notes.txt").write_text("mine")
    assert cli.main(["train", "--scenario", "2ds", "--quick", "--force", "--out", str(other)]) == 2
    assert "is not empty and holds no checkpoint" in capsys.readouterr().err


def test_train_force_replaces_a_checkpoint_whole(tmp_path, checkpoint_2ds, monkeypatch, capsys):
    existing = shutil.copytree(checkpoint_2ds, tmp_path / "ckpt")
    trained = checkpoints.load_models(checkpoint_2ds)
    monkeypatch.setattr(
        training,
        "train_models",
        lambda scenario, preset, splits, seed, **options: dataclasses.replace(trained, seed=seed),
    )
    assert (
        cli.main(
            [
                "train",
                "--scenario",
                "2ds",
                "--preset",
                "strong",
                "--quick",
                "--seed",
                "7",
                "--force",
                "--out",
                str(existing),
            ]
        )
        == 0
    )
    assert json.loads(capsys.readouterr().out)["checkpoint"] == str(existing)
    assert checkpoints.load_models(existing).seed == 7
    assert sorted(p.name for p in tmp_path.iterdir()) == ["ckpt"]  # no temporary folder left beside it


# -- outputs: reproduce ---------------------------------------------------------------------------------


@pytest.fixture
def no_data(monkeypatch):
    """Fail the test if a reproduction starts its first stage: the checks must come first."""

    def made(*args, **kwargs):
        raise AssertionError("the data stage started before the output was checked")

    monkeypatch.setattr(pipeline, "make_splits", made)


def reproduce(out, scenario="2ds") -> int:
    return cli.main(["reproduce", "--scenario", scenario, "--quick", "--out", str(out)])


def test_reproduce_refuses_what_it_cannot_write_before_any_work(tmp_path, checkpoint_2ds, no_data, capsys):
    (tmp_path / "notes.txt").write_text("mine")
    assert reproduce(tmp_path / "notes.txt") == 2
    assert (
        capsys.readouterr().err == f"toolkit reproduce: error: --out: {tmp_path / 'notes.txt'} is a file, not a "
        "folder; choose a folder\n"
    )
    assert reproduce(tmp_path / "notes.txt" / "run") == 2
    assert f"--out: {tmp_path / 'notes.txt'} is a file, not a folder" in capsys.readouterr().err
    assert reproduce(checkpoint_2ds) == 2
    assert "holds a checkpoint of `toolkit train`, not a reproduction" in capsys.readouterr().err
    assert reproduce(tmp_path) == 2  # holds notes.txt
    assert "holds other files, not a reproduction" in capsys.readouterr().err
    assert (tmp_path / "notes.txt").read_text() == "mine"


def test_reproduce_all_checks_every_scenario_folder_before_the_first_starts(tmp_path, no_data, capsys):
    Stages(tmp_path / "3do", RunConfig.create("3do", "paper", quick=True, seed=1).settings(), progress=False)
    assert reproduce(tmp_path, "all") == 2  # 2ds would run first; 3do's folder holds another seed
    assert f"{tmp_path / '3do'} holds a run with other settings" in capsys.readouterr().err
    assert not any((tmp_path / "2ds").iterdir())  # checked (made, written to), nothing computed
    single = tmp_path / "single"
    Stages(single, RunConfig.create("2ds", "paper", quick=True, seed=0).settings(), progress=False)
    assert reproduce(single, "all") == 2
    assert "holds ['cache'], not the scenario folders of a reproduction" in capsys.readouterr().err


@pytest.mark.parametrize("name", ["settings", "stage_seconds", "planning_BS", "learning"])
def test_a_damaged_cache_file_is_named_with_what_to_do(name, tmp_path):
    settings = RunConfig.create("2ds", "paper", quick=True, seed=0).settings()
    stages = Stages(tmp_path, settings, progress=False)
    damaged = stages.cache / f"{name}.json"
    damaged.write_text('{"scenario": "2ds", "pre')  # cut off mid-write, as by a full disk
    advice = {"settings": f"delete {tmp_path} to start again", "stage_seconds": "delete it"}
    with pytest.raises(ValueError) as error:
        Stages(tmp_path, settings, progress=False).load(name)
    assert str(error.value).startswith(f"{damaged} is damaged (Unterminated string")
    assert advice.get(name, "delete it to compute that stage again") in str(error.value)


def test_damaged_data_and_checkpoint_in_the_cache_are_named_with_what_to_do(tmp_path, checkpoint_2ds):
    config = RunConfig.create("2ds", "strong", quick=True, progress=False)
    cache = Stages(tmp_path, config.settings(), progress=False).cache
    for split in SPLITS:
        (cache / f"data_{split}.npz").write_bytes(b"PK\x03\x04 cut off")
    with pytest.raises(
        ValueError,
        match=r"data_train.npz is not a valid dataset file .*; delete it to compute the "
        r"data stage again",
    ):
        experiments.reproduce(config, tmp_path)
    for name, dataset in pipeline.make_splits(config).items():
        dataset.save(cache / f"data_{name}.npz")
    checkpoint = shutil.copytree(checkpoint_2ds, cache / "checkpoint")
    (checkpoint / checkpoints.META).write_text("{")
    with pytest.raises(ValueError, match=f"meta.json is corrupted.*; delete {checkpoint} to train again"):
        experiments.reproduce(config, tmp_path)


# -- threads ------------------------------------------------------------------------------------------


def blas_threads() -> list[int]:
    return [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]


@pytest.mark.parametrize("setting, expected", [(None, 1), ("3", 3)])
def test_commands_run_on_one_thread_unless_toolkit_threads_says(setting, expected, monkeypatch, capsys):
    from toolkit.experiments import bench

    seen = []
    monkeypatch.setattr(
        bench,
        "throughput",
        lambda *a, **k: (
            seen.append((torch.get_num_threads(), blas_threads()))
            or {"exact_cfg_per_s": 1.0, "learned_cfg_per_s": 2.0, "ratio": 2.0}
        ),
    )
    monkeypatch.setattr(bench, "edge_checks", lambda *a, **k: {})
    if setting is None:
        monkeypatch.delenv(threads.ENV, raising=False)
    else:
        monkeypatch.setenv(threads.ENV, setting)
    before = torch.get_num_threads(), blas_threads()
    assert cli.main(["bench", "--scenario", "2ds", "--json"]) == 0
    assert seen == [(expected, [expected] * len(before[1]))]
    assert (torch.get_num_threads(), blas_threads()) == before  # the caller's settings come back


def test_a_bad_thread_count_is_named(monkeypatch, capsys):
    monkeypatch.setenv(threads.ENV, "two")
    assert cli.main(["bench", "--scenario", "2ds", "--json"]) == 2
    assert capsys.readouterr().err.startswith("toolkit bench: error: TOOLKIT_THREADS='two': expected a whole number")
