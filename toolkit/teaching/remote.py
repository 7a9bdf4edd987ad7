"""A submission seen from the grader: its notebook's functions, called as if they were local.

:class:`Submission` starts ``python -m toolkit.teaching.submission`` on the student's notebook,
inside a :mod:`~toolkit.teaching.sandbox` (or, unisolated, as a plain subprocess), and
:class:`RemoteFunction` stands for each function the notebook defines: calling it sends the
arguments (the grader's own objects, pickled; a checker goes as a stand-in whose questions come
back here to the real checker, which counts them), waits for plain values
(:mod:`~toolkit.teaching.wire`), applies what became of each argument to the grader's objects and
returns the result, a scalar tensor with the gradients the submission computed. What the
submission raised comes back as :class:`SubmissionRaised`; a process that ended (``os._exit``,
a crash, its limits) as :class:`SubmissionEnded`, after which the next call starts it afresh, up
to :data:`STARTS` times. Past the deadline every call raises :class:`TimeoutError`.
"""

from __future__ import annotations

import contextlib
import io
import os
import signal
import subprocess
import sys
from pathlib import Path

import dill
import numpy as np

import toolkit
from toolkit.geometry.checker import CollisionChecker
from toolkit.teaching import sandbox, wire
from toolkit.teaching.unavailable import stripped_modules

STARTS = 3  # times a submission's process is started before every further call fails
INSIDE = "/grading/in"  # where the notebook appears in the sandbox
IMPORTED_FROM = Path(toolkit.__file__).resolve().parent.parent  # the folder that holds this toolkit package


class SubmissionRaised(Exception):
    """What a submission's function raised, as its text (``TypeName: message``)."""


class SubmissionEnded(Exception):
    """The submission's process ended (or broke the protocol) during a call."""


class _Pickler(dill.Pickler):
    """Pickles the grader's arguments; a checker goes as a key, and its questions come back to it."""

    def __init__(self, file, checkers: dict[int, CollisionChecker]):
        super().__init__(file, recurse=True)
        self.checkers = checkers

    def persistent_id(self, obj):
        if not isinstance(obj, CollisionChecker):
            return None
        key = next((k for k, c in self.checkers.items() if c is obj), len(self.checkers))
        self.checkers[key] = obj
        return ("checker", key, obj.robot, bool(obj.few_calls), bool(obj.certificates_pay))


class Submission:
    """The student's notebook run in a process of its own; :meth:`function` gives its functions."""

    def __init__(self, notebook: Path, assignment: str, deadline: float, isolate: bool, cpu_s: float):
        self.notebook, self.assignment, self.deadline = Path(notebook), assignment, deadline
        self.isolate, self.cpu_s = isolate, cpu_s
        self.process: subprocess.Popen | None = None
        self.starts, self.names = 0, list[str]()
        self.checkers: dict[int, CollisionChecker] = {}

    def start(self) -> list[str]:
        """Run the notebook; the names of the functions it defines (empty when its process ended first)."""
        self.close()
        self.starts += 1
        python = [sys.executable, "-m", "toolkit.teaching.submission"]
        if self.isolate:
            inner = [*python, f"{INSIDE}/{self.notebook.name}", self.assignment]
            shown = {str(self.notebook.parent): INSIDE}  # the notebook; the library's answers stripped
            shown |= {
                copy: f"{sandbox.LIBRARY}/toolkit/{inside}"
                for copy, inside in stripped_modules(self.assignment).items()
            }
            command = sandbox.command(inner, shown, {}, cpu_s=self.cpu_s)
            env = None
        else:
            command = [*python, str(self.notebook), self.assignment]
            env = {**os.environ, "PYTHONPATH": str(IMPORTED_FROM)}  # this toolkit, wherever it is installed
        self.process = subprocess.Popen(
            command,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,  # what the notebook printed: never read, never quoted
            env=env,
            start_new_session=True,  # its own group: closing it stops everything it started
        )
        try:
            ready = self._receive()
        except SubmissionEnded:
            self.close()
            return []
        self.names = [n for n in ready.get("ready", []) if isinstance(n, str)]
        return self.names

    def close(self) -> None:
        """Stop the submission's process and everything it started."""
        if self.process is not None:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()
            for pipe in (self.process.stdin, self.process.stdout):
                pipe.close()  # type: ignore[union-attr]
            self.process = None

    def function(self, name: str) -> RemoteFunction:
        return RemoteFunction(self, name)

    def request(self, message: dict) -> dict:
        """Send ``message``; answer the checker's questions until the reply comes; return it."""
        if self.process is None and (self.starts >= STARTS or not self.start()):
            raise SubmissionEnded("the notebook's process ended and is not started again")
        payload = io.BytesIO()
        _Pickler(payload, self.checkers).dump(message)
        try:
            wire.send(self.process.stdin.fileno(), payload.getvalue())  # type: ignore[union-attr]
        except OSError:
            self.close()
            raise SubmissionEnded("the notebook's process ended") from None
        while True:
            reply = self._receive()
            if "ask" not in reply:
                return reply
            self._answer(reply)

    def _receive(self) -> dict:
        try:
            reply = wire.loads(wire.receive(self.process.stdout.fileno(), self.deadline))  # type: ignore[union-attr]
        except TimeoutError:
            self.close()
            raise
        except (EOFError, OSError, ValueError, TypeError, KeyError):  # gone, or not plain values
            self.close()
            raise SubmissionEnded("the notebook's process ended during this call") from None
        if not isinstance(reply, dict):
            self.close()
            raise SubmissionEnded("the notebook's process sent something other than an answer")
        return reply

    def _answer(self, question: dict) -> None:
        """A question the submission asked a checker: the grader's checker answers it (and counts it)."""
        checker = self.checkers.get(question.get("ask"))  # type: ignore[arg-type]
        Q, method, cap = question.get("Q"), question.get("method"), question.get("cap")
        reply: dict[str, object]
        try:
            if checker is None or not isinstance(Q, np.ndarray) or Q.ndim != 2 or Q.shape[1] != checker.robot.dof:
                raise ValueError("a checker is asked about an array (N, dof) of its robot's configurations")
            if method == "validity":
                reply = {"answer": checker.are_valid(Q.astype(float))}
            elif method == "clearance_bounds" and isinstance(cap, float):
                reply = {"answer": checker.clearances(Q.astype(float), cap)}
            else:
                raise ValueError(f"a checker has no method {method!r}")
        except ValueError as error:
            reply = {"error": str(error)}
        payload = io.BytesIO()
        _Pickler(payload, self.checkers).dump(reply)
        wire.send(self.process.stdin.fileno(), payload.getvalue())  # type: ignore[union-attr]


class RemoteFunction:
    """One function of the submission's notebook, called from the grader's hidden tests."""

    def __init__(self, submission: Submission, name: str):
        self.submission, self.__name__ = submission, name
        self.__globals__ = _Globals(submission)  # a hidden test may set a name of the notebook (Q1's stand-in)

    def __call__(self, *args, **kwargs):
        reply = self.submission.request({"call": self.__name__, "args": args, "kwargs": kwargs})
        for value, after in [*zip(args, reply.get("after", [])), *_pairs(kwargs, reply.get("after_kw", {}))]:
            _apply(value, after)
        if "raised" in reply:
            raise SubmissionRaised(str(reply["raised"]))
        if "result" not in reply:
            raise SubmissionEnded("the notebook's process sent an answer without a result")
        return _with_gradients(reply["result"], reply.get("gradients", []), args, kwargs)


class _Globals:
    """``function.__globals__`` of a :class:`RemoteFunction`: setting a name sets it in the submission's notebook."""

    def __init__(self, submission: Submission):
        self.submission = submission

    def __setitem__(self, name: str, value: object) -> None:
        self.submission.request({"set": name, "value": value})


def _pairs(kwargs: dict, after: object) -> list:
    return [(kwargs[k], v) for k, v in after.items() if k in kwargs] if isinstance(after, dict) else []


def _apply(value: object, after: object) -> None:
    """Give the grader's argument ``value`` what became of it in the submission (``after``: ``[kind, data]``), where
    the two agree in kind and shape."""
    if not (isinstance(after, list) and len(after) == 2):
        return
    kind, data = after
    torch = wire.loaded_torch()
    if kind == "rng" and isinstance(value, np.random.Generator) and isinstance(data, dict):
        with contextlib.suppress(ValueError, TypeError, KeyError):  # not a state of this generator: left as it is
            value.bit_generator.state = data
    elif kind == "value":
        _update(value, data)
    elif kind == "module" and torch is not None and isinstance(value, torch.nn.Module) and isinstance(data, dict):
        mine = value.state_dict()
        with torch.no_grad():
            for name, tensor in data.items():
                same = isinstance(tensor, torch.Tensor) and name in mine and tensor.shape == mine[name].shape
                if same and not torch.equal(tensor.to(mine[name].dtype), mine[name]):
                    mine[name].copy_(tensor)
    elif kind == "attrs" and isinstance(data, dict) and hasattr(value, "__dict__"):
        for name, new in data.items():
            old = vars(value).get(name)
            if (isinstance(old, np.ndarray) and isinstance(new, np.ndarray)) or type(old) is type(new):
                setattr(value, name, new)


def _update(value: object, data: object) -> object:
    """``value`` made equal to ``data`` in place where it can be (arrays, tensors, lists, dicts, and their items;
    only what changed: a copy would stale a graph that saved a tensor); returns what to hold in its place."""
    torch = wire.loaded_torch()
    if isinstance(value, np.ndarray) and isinstance(data, np.ndarray) and data.shape == value.shape:
        floats = data.dtype.kind in "fc" and value.dtype.kind in "fc"
        if not np.array_equal(data, value, equal_nan=floats):
            value[...] = data
        return value
    if torch is not None and isinstance(value, torch.Tensor) and isinstance(data, torch.Tensor):
        if data.shape == value.shape and not torch.equal(data.to(value.dtype), value.detach()):
            with torch.no_grad():
                value.copy_(data)
        return value
    if isinstance(value, tuple) and isinstance(data, tuple) and len(value) == len(data):
        for item, new in zip(value, data):
            _update(item, new)
        return value
    if type(value) is list and type(data) is list:
        same = len(value) == len(data)
        value[:] = [_update(item, new) for item, new in zip(value, data)] if same else data
        return value
    if type(value) is dict and type(data) is dict:
        kept = {key: _update(value[key], new) if key in value else new for key, new in data.items()}
        value.clear()
        value.update(kept)
        return value
    return data


def _with_gradients(result: object, gradients: object, args: tuple, kwargs: dict) -> object:
    """``result``; a scalar tensor given, for each gradient the submission sent, a term with that gradient with
    respect to the grader's own parameter or tensor (``(p - p.detach()) * g``: zero in value)."""
    torch = wire.loaded_torch()
    if torch is None or not isinstance(result, torch.Tensor) or result.ndim != 0 or not isinstance(gradients, list):
        return result
    for item in gradients:
        where, name, grad = item if isinstance(item, list) and len(item) == 3 else (None, None, None)
        value = args[where] if isinstance(where, int) and 0 <= where < len(args) else kwargs.get(where)
        if isinstance(value, torch.nn.Module):
            value = dict(value.named_parameters()).get(name)
        if isinstance(value, torch.Tensor) and isinstance(grad, torch.Tensor) and grad.shape == value.shape:
            result = result + ((value - value.detach()) * grad.to(value.dtype)).sum()
    return result
