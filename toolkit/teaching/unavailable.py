"""The toolkit functions that compute an assignment's answer, made unavailable while grading.

The library implements the paper, so it holds code equivalent to the assignments' solutions
(the bridge test sampler, the path verification of Algorithm 1, the paper's CAE loss) and
functions that compute the graded numbers (TPR / TNR). Every hidden test calls :func:`apply`
first: each such entry point then raises :class:`NotAvailableWhileGrading` when called, however
the submission reached it (``from ... import``, an alias, a subclass), because the function's
code itself is replaced. :func:`restore` puts the originals back (the test suite grades in its own process).

In the grading sandbox the library's answers are not even there: :func:`stripped_modules` writes
copies of the modules that hold them, each entry point's body replaced by the same refusal, and
the sandbox shows those copies in the originals' place. A notebook there that reloads a module,
or reads its source and runs it, finds the refusal too.
"""

from __future__ import annotations

import ast
import atexit
import functools
import importlib
import shutil
import tempfile
from pathlib import Path
from types import FunctionType

ENTRY_POINTS = {  # assignment -> {"module:qualified name": what it computes}
    "bridge_test": {"toolkit.planning.sampling:BridgeTestSampler.draw": "the bridge test sampler"},
    "verify_and_repair": {
        f"toolkit.planning.query_roadmap:QueryRoadmap.{name}": "Algorithm 1's path verification"
        for name in ("extract_path", "verified_path", "failed_edges", "repair")
    },
    "evaluating_a_checker": {
        "toolkit.learning.metrics:classification": "accuracy, TPR and TNR",
        "toolkit.plots.answers:confusion_counts": "a confusion matrix",
        "toolkit.plots.answers:roc_points": "TPR and FPR at thresholds",
    },
    "cae_loss": {
        "toolkit.learning.models:CAE.loss": "the CAE's loss",
        "toolkit.learning.models:CAE.encoder_weight_penalty": "the paper's weight penalty",
    },
}
_originals: dict[str, object] = {}  # entry point -> its code object, while unavailable


class NotAvailableWhileGrading(RuntimeError):
    """Raised by a toolkit function that computes an assignment's answer, called while grading."""


def _function(entry: str) -> FunctionType:
    module, name = entry.split(":")
    found = importlib.import_module(module)
    for part in name.split("."):
        found = getattr(found, part)
    return found  # type: ignore[return-value]


def _refusal(entry: str, what: str, free: tuple[str, ...]):
    """A code object that raises :class:`NotAvailableWhileGrading`, with the same free variables as the original's
    (a function's code may only be swapped for one with as many)."""
    message = f"{entry.replace(':', '.')} ({what}) is not available while grading: write it yourself"
    cells = "".join(f"    {v} = None\n" for v in free)
    uses = "".join(f"        {v}\n" for v in free)
    error = f"__import__({__name__!r}, fromlist=['_']).NotAvailableWhileGrading"  # found from any module's globals
    source = f"def outer():\n{cells}    def refused(*args, **kwargs):\n{uses}        raise {error}({message!r})\n"
    source += "    return refused\n"
    namespace: dict = {}
    exec(source, namespace)  # our own fixed source; the code runs with the original's globals
    return namespace["outer"]().__code__


def apply(assignment: str) -> None:
    """Make every entry point that answers ``assignment`` raise :class:`NotAvailableWhileGrading` (idempotent)."""
    if assignment not in ENTRY_POINTS:
        raise ValueError(f"unknown assignment {assignment!r}; choose one of {sorted(ENTRY_POINTS)}")
    for entry, what in ENTRY_POINTS[assignment].items():
        if entry not in _originals:
            function = _function(entry)
            _originals[entry] = function.__code__
            function.__code__ = _refusal(entry, what, function.__code__.co_freevars)


def restore() -> None:
    """Give every entry point its own code back."""
    for entry in list(_originals):
        _function(entry).__code__ = _originals.pop(entry)  # type: ignore[assignment]


@functools.cache
def stripped_modules(assignment: str) -> dict[str, str]:
    """``{copy: module path inside the package}``: the modules holding ``assignment``'s entry points, each entry
    point's body (its docstring aside) replaced by a line that raises :class:`NotAvailableWhileGrading`; written
    once per process into a folder removed at exit."""
    if assignment not in ENTRY_POINTS:
        raise ValueError(f"unknown assignment {assignment!r}; choose one of {sorted(ENTRY_POINTS)}")
    folder = Path(tempfile.mkdtemp(prefix="toolkit-stripped-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    by_module: dict[str, list[tuple[str, str]]] = {}
    for entry, what in ENTRY_POINTS[assignment].items():
        module, name = entry.split(":")
        by_module.setdefault(module, []).append(
            (name, f"{entry.replace(':', '.')} ({what}) is not available while grading: write it yourself")
        )
    copies = {}
    for module, names in by_module.items():
        source_file = Path(importlib.import_module(module).__file__)  # type: ignore[arg-type]
        source = source_file.read_text()
        for name, message in names:
            source = _strip(source, name, message)
        copy = folder / module.replace(".", "_") / source_file.name
        copy.parent.mkdir()
        copy.write_text(source)
        copies[str(copy)] = "/".join(module.split(".")[1:]) + ".py"
    return copies


def _strip(source: str, qualname: str, message: str) -> str:
    """``source`` with the body of the function ``qualname`` (``Class.method`` or ``function``) replaced by a line
    that raises :class:`NotAvailableWhileGrading` with ``message``."""
    body = ast.parse(source).body
    for part in qualname.split("."):
        node = next(n for n in body if isinstance(n, ast.ClassDef | ast.FunctionDef) and n.name == part)
        body = node.body
    documented = isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant) and len(body) > 1
    first = body[1] if documented else body[0]
    if first.lineno == node.lineno:
        raise ValueError(f"{qualname}: a body on the line of its def cannot be stripped")
    lines = source.splitlines(keepends=True)
    error = f"__import__({__name__!r}, fromlist=['_']).NotAvailableWhileGrading"
    refusal = " " * first.col_offset + f"raise {error}({message!r})\n"
    return "".join(lines[: first.lineno - 1] + [refusal] + lines[node.end_lineno :])
