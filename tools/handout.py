"""The tree a course gives its students, and the check that no solution is in it (``make handout``).

An assignment's master (``tutorials/assignments/<name>/<name>.ipynb``) holds its solutions and
hidden tests; students get the student version ``otter assign`` writes (:func:`grading.build`).
:func:`build_handout` writes the library, the notebooks, the tutorials, the docs and the files
that install them, with every master replaced by its student version and no autograder, hidden
test or solution in it; the course's own tools (``tools/``: this module, the site builder, the
notebook runner) and the test suite stay out, since a student needs the library, not what builds
the course around it, and so do the instructors' guides (``tutorials/instructors*.md``; the course website
has them): a Markdown link to a file left out keeps its text and loses its target (:func:`dead_links` finds
any that remain). :func:`secret_lines` names the lines a master must not leak (its solutions
and hidden tests) and :func:`find_secrets` finds them in any tree of files: the
handout, or a website built from the notebooks.
"""

from __future__ import annotations

import contextlib
import functools
import html
import json
import re
import shutil
import subprocess
import zipfile
from pathlib import Path

from toolkit.teaching import grading

ROOT = Path(__file__).resolve().parents[1]  # the repository
SHIPPED = (  # path prefixes a handout copies; not tools/ (the course's build tools) nor tests/
    "toolkit/",
    "notebooks/",
    "tutorials/",
    "docs/",
    "README.md",
    "LICENSE",
    "pyproject.toml",
    "constraints.txt",
    "Makefile",
    "binder/",  # Binder's (repo2docker's) configuration: the published handout can be tried there
    ".gitignore",  # what installing (`pip install ".[hub]"`: build/, *.egg-info) and running leave is not committed
)
INSTRUCTORS_ONLY = ("tutorials/instructors",)  # the instructors' guides (instructors.md, instructors_jupyterhub.md)
MARKERS = ("# BEGIN SOLUTION", "# END SOLUTION", "# BEGIN TESTS", "# END TESTS")  # otter's raw cells that open blocks
LINK = re.compile(r"\[([^\]]*)\]\(([^)\s]+)\)")  # a Markdown link [text](target) (no title in ours)
MIN_CHARS = 20  # a secret line is at least this long: shorter ones (`return None`, `continue`) prove nothing


def _cells(name: str) -> list[tuple[str, str]]:
    """``(kind, source)`` of every cell of ``name``'s master, ``kind`` being ``"secret"`` (a hidden test, a
    prose solution, or a solution cell) or ``"public"``. A solution cell's lines outside its ``# BEGIN
    SOLUTION`` / ``# END SOLUTION`` block are public (the student version keeps them)."""
    cells, in_solution, in_tests = [], False, False
    for cell in json.loads(grading.master(name).read_text())["cells"]:
        source = "".join(cell["source"])
        first = source.strip().splitlines()[0].strip().upper() if source.strip() else ""
        if cell["cell_type"] == "raw" and first in MARKERS:
            in_solution = first == "# BEGIN SOLUTION" or (in_solution and first != "# END SOLUTION")
            in_tests = first == "# BEGIN TESTS" or (in_tests and first != "# END TESTS")
        elif (in_tests and first == "# HIDDEN") or (in_solution and cell["cell_type"] == "markdown"):
            cells.append(("secret", source))
        elif in_solution:
            cells += _split_solution(source)
        else:
            cells.append(("public", source))
    return cells


def _split_solution(source: str) -> list[tuple[str, str]]:
    """A solution code cell as ``(kind, line)``: lines inside ``# BEGIN/END SOLUTION`` or ending in ``# SOLUTION``
    are secret, the rest public."""
    parts, inside = [], False
    for line in source.splitlines():
        marker = line.strip().upper()
        if marker in ("# BEGIN SOLUTION", "# END SOLUTION"):
            inside = marker == "# BEGIN SOLUTION"
            continue
        parts.append(("secret" if inside or marker.endswith("# SOLUTION") else "public", line))
    return parts


def _meaningful(line: str) -> bool:
    """A line long enough to reveal something and not one of otter's markers."""
    return len(line) >= MIN_CHARS and not re.match(r"#\s*(BEGIN|END|HIDDEN)\b", line, re.IGNORECASE)


@functools.cache
def _public_text() -> str:
    """What every student may read, one stripped line after another with whitespace collapsed: the files a
    handout ships besides the assignments (the library, notebooks, docs) and the public cells of every master
    (its student version's)."""
    shipped = (line for path in _shipped_files() for line in _text(ROOT / path).splitlines())
    masters = (
        line
        for name in grading.assignment_names()
        for kind, source in _cells(name)
        if kind == "public"
        for line in source.splitlines()
    )
    return "\n".join(" ".join(line.split()) for line in (*shipped, *masters))


def secret_lines(name: str) -> set[str]:
    """The stripped lines of ``name``'s master that only its solutions and hidden tests hold: a copy of any one
    of them means a solution or a hidden test leaked. Lines every student may read anyway, whole or as part of
    a longer line (:func:`_public_text`), and short generic ones (:data:`MIN_CHARS`) are left out."""
    secret = {line.strip() for kind, source in _cells(name) if kind == "secret" for line in source.splitlines()}
    return {line for line in secret if _meaningful(line) and " ".join(line.split()) not in _public_text()}


def _text(path: Path) -> str:
    """The text a reader of ``path`` sees: notebooks and JSON as their strings, HTML without its tags, a zip as
    its members' text; '' for other binary files."""
    if path.suffix == ".zip":
        with zipfile.ZipFile(path) as archive:
            return "\n".join(archive.read(member).decode("utf-8", "replace") for member in archive.namelist())
    raw = path.read_bytes()
    if b"\0" in raw[:8192]:
        return ""
    text = raw.decode("utf-8", "replace")
    if path.suffix in (".ipynb", ".json"):
        with contextlib.suppress(ValueError):  # not JSON after all: read it as text
            text = "\n".join(_strings(json.loads(text)))
    if path.suffix in (".html", ".htm", ".xml", ".svg", ".ipynb", ".json"):
        text = html.unescape(re.sub(r"<[^>]*>", "", text))
    return text


def _strings(value) -> list[str]:
    """Every string inside a parsed JSON value, depth first."""
    if isinstance(value, str):
        return [value]
    items = value.values() if isinstance(value, dict) else value if isinstance(value, list) else []
    return [s for item in items for s in _strings(item)]


def find_secrets(root: Path, names: list[str] | None = None) -> list[str]:
    """``"path: line"`` (path relative to ``root``) for every file under ``root`` that holds a
    :func:`secret_lines` line of the assignments ``names`` (default: all), whitespace collapsed."""
    root = Path(root)
    names = names or grading.assignment_names()
    secrets = sorted({" ".join(line.split()) for name in names for line in secret_lines(name)})
    found = []
    for path in sorted(p for p in root.rglob("*") if p.is_file()):
        text = " ".join(_text(path).split())
        found += [f"{path.relative_to(root)}: {line}" for line in secrets if line in text]
    return found


def _shipped_files() -> list[str]:
    """The repository's files a handout copies: tracked or not ignored by git, under :data:`SHIPPED`, outside
    the assignments' folders (their masters and ``dist/``) and the instructors' guides."""
    listed = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.splitlines()
    assignment_folders = tuple(f"tutorials/assignments/{name}/" for name in grading.assignment_names())
    return [
        path
        for path in listed
        if path.startswith(SHIPPED)
        and not path.startswith(assignment_folders + INSTRUCTORS_ONLY)
        and (ROOT / path).is_file()
    ]


def build_handout(out: str | Path) -> Path:
    """Write the students' tree into ``out`` (replaced): the shipped files and each assignment's student version
    (:func:`grading.student_notebook`, built when stale) at its master's path. Raises when a line of a solution
    or a hidden test is found in the tree written; returns ``out``."""
    out = Path(out).resolve()
    if out == ROOT or ROOT.is_relative_to(out):
        raise ValueError(f"the handout folder {out} would replace the repository")
    shutil.rmtree(out, ignore_errors=True)
    for path in _shipped_files():
        (out / path).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / path, out / path)
    for name in grading.assignment_names():
        target = out / grading.master(name).relative_to(ROOT)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(grading.student_notebook(name), target)
    for page in out.rglob("*.md"):  # a link into what the handout leaves out would be dead there
        page.write_text(LINK.sub(functools.partial(_kept_or_text, page), page.read_text()))
    if leaks := find_secrets(out):
        raise RuntimeError(f"the handout in {out} holds solutions or hidden tests:\n" + "\n".join(leaks[:20]))
    return out


def _resolves(page: Path, target: str) -> bool:
    """Whether a link ``target`` on ``page`` reaches something: a web address or anchor, or a file or folder
    that exists relative to the page."""
    if re.match(r"[a-z][a-z0-9+.-]*:|#", target):
        return True
    return (page.parent / target.split("#")[0]).exists()


def _kept_or_text(page: Path, link: re.Match) -> str:
    """A Markdown link on ``page`` as it was if it resolves, else its text alone."""
    return link[0] if _resolves(page, link[2]) else link[1]


def dead_links(root: Path) -> list[str]:
    """``"page -> target"`` for every Markdown link under ``root`` whose target does not exist."""
    root = Path(root)
    return [
        f"{page.relative_to(root)} -> {link[2]}"
        for page in sorted(root.rglob("*.md"))
        for link in LINK.finditer(page.read_text())
        if not _resolves(page, link[2])
    ]
