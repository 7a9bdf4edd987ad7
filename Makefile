# Two commands for a fresh machine (see README): `make demo` and `make test`.
VENV ?= .venv
PY := $(VENV)/bin/python
OUT ?= results/2ds-paper

.PHONY: setup browser sandbox demo lint test lab assignments handout clean site

setup: $(VENV)/.installed

$(VENV)/.installed: pyproject.toml constraints.txt
	python3 -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet -c constraints.txt -e ".[dev]"
	touch $@

# Debian's Chromium for the browser test (root on these machines; skipped where present).
browser:
	@command -v chromium >/dev/null 2>&1 || { apt-get update -qq && apt-get install -y -qq chromium >/dev/null; }

# Debian's bubblewrap, the sandbox `toolkit grade` runs each student's notebook in (toolkit/teaching/sandbox.py).
sandbox:
	@command -v bwrap >/dev/null 2>&1 || { apt-get update -qq && apt-get install -y -qq bubblewrap >/dev/null; }

# The main job: the paper's 2DS tables at full size, printed next to the published numbers.
demo: setup
	$(VENV)/bin/toolkit reproduce --scenario 2ds --preset paper --out $(OUT)
	cat $(OUT)/tables.md

# The code's checks: ruff's lint (the notebooks' code cells too) and format (the library's and the tools' files; the
# notebooks' cells are laid out by hand), mypy's types (all configured in pyproject.toml).
lint: setup
	$(VENV)/bin/ruff check toolkit tools tests docs/scripts notebooks tutorials
	$(VENV)/bin/ruff format --check toolkit tools tests docs/scripts
	$(VENV)/bin/mypy

# The quick tests first, spread over every core, each test file in one worker (its fixtures made once there); then
# the slow ones in one process, since they spread their own work (notebooks, the site, grading) over the cores.
test: setup browser sandbox lint
	$(PY) -m pytest -q -m "not slow" -n auto --dist loadfile
	$(PY) -m pytest -q -m slow --durations=40

# JupyterLab on the notebooks, for a student: open the URL it prints, start with 01.
lab: setup
	$(VENV)/bin/jupyter lab --notebook-dir=notebooks --ip=127.0.0.1

# Course assignments: otter assign on every master, writing dist/student/ (hand these out) and
# dist/autograder/ beside it; grade with `toolkit grade NOTEBOOK` (tutorials/assignments/README.md).
assignments: setup
	$(PY) -c "from toolkit.teaching import grading; print(grading.build_all())"

# The tree a course gives its students, written into handout/: the library, notebooks, tutorials, docs and the
# assignments' student versions, with no master, hidden test or solution (checked as it is written;
# tools/handout.py; tools/ and tests/ stay out). Publish this tree, keep the masters private (tutorials/instructors.md).
handout: setup
	$(PY) -c "from tools import handout; print(handout.build_handout('handout'))"

# The course website, built into site/ (open site/index.html, or serve it from any static host:
# tutorials/instructors.md): the notebooks and tutorials executed at full size (TOOLKIT_QUICK=1: quick; a notebook
# whose inputs have not changed since the last build is reused from build/site/executed, tools/executed_notebooks.py),
# each with a download without outputs, the assignments' student versions, docs/ and the API reference (tools/site.py).
site: setup
	$(PY) -m tools.site --out site

clean:
	rm -rf $(VENV) results .pytest_cache
