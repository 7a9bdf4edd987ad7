"""What a reader follows through one PRM query: the toolkit's functions and source lines it runs (issue #33).

    .venv/bin/python docs/scripts/query_reading.py [--list]

It measures the ``toolkit`` that Python imports (the first line printed says which); for
another checkout, run its copy of the script with ``PYTHONPATH=that/checkout``.

Builds 3DC-7's first query (``make_queries(scenario, seed=0, n_workspaces=1)``), its
default exact checker (``exact_checker``) and, for "with prediction", a learned checker
of a quick ``strong`` model (trained here in a few seconds, in a temporary folder). Each
way, it solves the query once to warm up, then once more as ``toolkit plan --predict`` does
(the BS sampler, the default planner: ``problems.build(scenario, query, checker=...)``, then
``task.solve``) under ``sys.setprofile``, and prints how many distinct functions ran, their
source lines and their files; ``--list`` adds the functions, file by file.

What counts (the variant closest to the issue's figures, among those tried: with or
without comprehensions, lambdas, dataclasses' generated methods, numba's kernels, the
checkers' set-up, decorators and docstrings in the lines):

- a function: a code object whose file lies in the ``toolkit/`` folder imported; not a
  comprehension, generator expression or lambda (read as part of its function), not a
  method dataclasses generate (its file is ``<string>``), not a numba-compiled kernel
  (numba reports its calls to the profiler, but it runs compiled; the issue leaves them
  out: counting them adds 2 functions, 49 lines and 1 file each way);
- its lines: ``inspect.getsourcelines``, decorators to last line, docstring, comments
  and blank lines inside included;
- the checkers are built and warmed before: encoding the workspace and the compiled
  checker's arrays are not part of the query; building the task (``problems.build``: the
  planner, its parameters and the problem) and solving it are. (Before issue 48 the script
  called ``default_options`` then ``solve_query``, what ``toolkit plan`` called then.)

Which functions run depends on the query (repairs, bridges): other seeds move the count by a
few. The figures, before and after the layouts of issues #33 and #48, are in ``docs/design.md``.
"""

import argparse
import inspect
import sys
import tempfile
from collections import defaultdict
from pathlib import Path

import numpy as np

import toolkit
from toolkit import scenarios
from toolkit.experiments import pipeline, problems, queries
from toolkit.experiments.config import RunConfig
from toolkit.geometry.collision import exact_checker
from toolkit.learning.learned import LearnedChecker

ROOT = Path(toolkit.__file__).resolve().parent


def one_query(scenario, query, checker, exact):
    """Solve ``query`` as ``toolkit plan`` does: BS sampler, the default planner, ``checker`` deciding samples."""
    task = problems.build(scenario, query, sampler="BS", checker=checker, exact=exact)
    return task.solve(np.random.default_rng(0))


def compiled_kernels() -> set:
    """The Python code of the toolkit's numba-compiled functions (numba reports their calls to a profiler too)."""
    modules = [module for name, module in list(sys.modules.items()) if name.startswith("toolkit.")]
    return {f.py_func.__code__ for module in modules for f in vars(module).values() if hasattr(f, "py_func")}


def functions_run(call, *args) -> set:
    """The code objects of the toolkit's functions that ``call(*args)`` runs (see the module's docstring)."""
    codes = set()
    sys.setprofile(lambda frame, event, arg: codes.add(frame.f_code) if event == "call" else None)
    try:
        call(*args)
    finally:
        sys.setprofile(None)
    return {
        code
        for code in codes - compiled_kernels()
        if Path(code.co_filename).resolve().is_relative_to(ROOT) and not code.co_name.startswith("<")
    }


def report(label: str, codes: set, listing: bool) -> None:
    by_file = defaultdict(list)
    for code in codes:
        by_file[Path(code.co_filename).resolve().relative_to(ROOT.parent)].append(code)
    lines = {code: len(inspect.getsourcelines(code)[0]) for code in codes}
    print(f"{label}: {len(codes)} functions, {sum(lines.values())} lines, {len(by_file)} files")
    for file, found in sorted(by_file.items()) if listing else ():
        print(f"  {file}: {len(found)} functions, {sum(lines[c] for c in found)} lines")
        for code in sorted(found, key=lambda c: c.co_firstlineno):
            print(f"    {code.co_firstlineno:4}  {getattr(code, 'co_qualname', code.co_name)} ({lines[code]})")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--list", action="store_true", help="list the functions, file by file")
    args = parser.parse_args()
    scenario = scenarios.get("3dc7")
    query = queries.make_queries(scenario, seed=0, n_workspaces=1)[0]
    with tempfile.TemporaryDirectory() as folder:
        config = RunConfig.create(scenario, "strong", quick=True, progress=False, device="cpu")
        models, _, _ = pipeline.train_and_save(config, folder)
    exact = exact_checker(query.workspace, scenario.robot)
    print(f"toolkit: {ROOT}")
    for label, checker in (("with prediction", LearnedChecker(query.workspace, models)), ("without", None)):
        one_query(scenario, query, checker, exact)  # warm-up: lazy set-up and first calls' costs
        report(label, functions_run(one_query, scenario, query, checker, exact), args.list)


if __name__ == "__main__":
    main()
