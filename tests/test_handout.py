"""The students' tree holds no solution (tools.handout, `make handout`)."""

from __future__ import annotations

import json
import shutil

import pytest

from toolkit.teaching import grading
from tools import handout


def test_every_master_has_solution_and_hidden_test_lines_to_look_for():
    for name in grading.assignment_names():
        secrets = handout.secret_lines(name)
        cells = json.loads(grading.master(name).read_text())["cells"]
        master = {line.strip() for cell in cells for line in "".join(cell["source"]).splitlines()}
        assert len(secrets) >= 20, f"{name}: only {len(secrets)} secret lines"
        assert secrets <= master, name
        assert not any(line.startswith(("# BEGIN", "# END", "# HIDDEN")) for line in secrets)


def test_lines_a_student_sees_are_not_secret():
    """A prompt, a public test and the setup stay in the student version: none of their lines is a secret."""
    secrets = handout.secret_lines("bridge_test")
    assert "def bridge_test(checker, n_attempts, sigma, rng):" not in secrets  # the signature the student gets
    assert "return sampling.Sampler(checker).valid(Q)" not in secrets  # the setup's helper
    assert any(line.startswith("assert _sampling.Sampler(_gap).valid(_m).all()") for line in secrets)  # hidden


def test_a_leaked_solution_or_hidden_test_is_found_in_notebooks_html_and_zips(tmp_path):
    master = grading.master("verify_and_repair")
    shutil.copy(master, tmp_path / "copied.ipynb")
    hidden = next(line for line in handout.secret_lines("cae_loss") if line.startswith("assert _torch.allclose"))
    (tmp_path / "page.html").write_text(f"<pre><span>{hidden[:30]}</span>{hidden[30:].replace('&', '&amp;')}</pre>")
    (tmp_path / "clean.md").write_text("# Nothing to see\n\nThe public text of an assignment.\n")
    found = handout.find_secrets(tmp_path)
    assert {line.split(": ", 1)[0] for line in found} == {"copied.ipynb", "page.html"}, found
    assert f"page.html: {' '.join(hidden.split())}" in found


@pytest.mark.slow
def test_the_handout_holds_the_course_and_no_solution(tmp_path):
    out = handout.build_handout(tmp_path / "handout")
    files = {str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()}
    for needed in ("README.md", "LICENSE", "pyproject.toml", "constraints.txt", "Makefile", "toolkit/__init__.py"):
        assert needed in files, needed
    assert {"binder/requirements.txt", "binder/start"} <= files  # Binder for the published handout
    assert "build/" in (out / ".gitignore").read_text().split()  # what `pip install ".[hub]"` writes stays out of git
    assert (handout.ROOT / "tutorials" / "instructors_jupyterhub.md").is_file()
    assert not [f for f in files if f.startswith("tutorials/instructors")]  # the instructors' guides stay out
    assert any(f.startswith("notebooks/") and f.endswith(".ipynb") for f in files)
    assert "tutorials/getting_started.ipynb" in files and "tutorials/assignments/README.md" in files
    outside = ("tests/", "tools/")  # the test suite and the course's build tools are not the students'
    assert not any("/dist/" in f or f.endswith(".zip") or f.startswith(outside) for f in files), sorted(files)
    for name in grading.assignment_names():
        given = out / grading.master(name).relative_to(handout.ROOT)
        notebook = json.loads(given.read_text())
        sources = ["".join(cell["source"]) for cell in notebook["cells"]]
        assert notebook["metadata"]["otter"]["assignment_name"] == name  # the student version otter assign wrote
        assert not any("ASSIGNMENT CONFIG" in s or "BEGIN SOLUTION" in s or "# HIDDEN" in s for s in sources), name
        cases = [
            case for test in notebook["metadata"]["otter"]["tests"].values() for case in test["suites"][0]["cases"]
        ]
        assert cases and not any(case["hidden"] for case in cases), name
    assert handout.find_secrets(out) == []
    assert handout.dead_links(out) == []  # the README's links to the instructors' guides keep only their text
    readme = (out / "README.md").read_text()
    assert "tutorials/instructors.md" in readme and "](tutorials/instructors.md" not in readme
    assert "](notebooks/" in readme  # links into what the handout holds stay links


def test_dead_links_are_found(tmp_path):
    (tmp_path / "docs").mkdir()
    (tmp_path / "here.md").write_text("x")
    (tmp_path / "docs" / "page.md").write_text(
        "[ok](../here.md#part) [web](https://example.org) [anchor](#top) [gone](../missing.md) [dir](../docs)"
    )
    assert handout.dead_links(tmp_path) == ["docs/page.md -> ../missing.md"]
