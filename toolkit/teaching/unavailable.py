"""The toolkit functions that compute an assignment's answer, made unavailable while grading.

The library implements the paper, so it holds code equivalent to the assignments' solutions
(the bridge test sampler, the path verification of Algorithm 1, the paper's CAE loss) and
functions that compute the graded numbers (TPR / TNR). Every hidden test calls :func:`apply`
first: each such entry point then raises :class:`NotAvailableWhileGrading` when called, however
the submission reached it (``from ... import``, an alias, a subclass), because the function's
code itself is replaced. A notebook may still read the library's source; only calling it is
refused. :func:`restore` puts the originals back (the test suite grades in its own process).
"""

from __future__ import annotations

import importlib
from types import FunctionType

ENTRY_POINTS = {  # assignment -> {"module:qualified name": what it computes}
    "bridge_test": {"toolkit.planning.sampling:BridgeTestSampler.draw": "the bridge test sampler"},
    "verify_and_repair": {
        f"toolkit.planning.query_roadmap:QueryRoadmap.{name}": "Algorithm 1's path verification"
        for name in ("extract_path", "verified_path", "failed_edges", "repair")
    },
    "evaluating_a_checker": {
        "toolkit.learning.metrics:classification": "accuracy, TPR and TNR",
        "toolkit.plots.classifier:confusion_counts": "a confusion matrix",
        "toolkit.plots.classifier:roc_points": "TPR and FPR at thresholds",
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
