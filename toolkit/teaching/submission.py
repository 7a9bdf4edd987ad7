"""The submission's side of grading: its notebook runs here, inside the sandbox, and nothing is judged here.

``python -m toolkit.teaching.submission NOTEBOOK ASSIGNMENT`` runs the notebook's graded cells
(as ``otter run`` would: ``otter_ignore`` cells and otter's own cells skipped, IPython's ``%`` and
``!`` lines dropped, a cell that raises does not stop the others), after making the toolkit's
answers unavailable (:mod:`~toolkit.teaching.unavailable`, so that no code object copied by a
cell is the original). Then it answers the grader (:mod:`~toolkit.teaching.grading`), which runs
the hidden tests in a process of its own: each request names one of the notebook's functions and
its arguments; the function runs here on them, and only plain values go back
(:mod:`~toolkit.teaching.wire`): what it returned, the gradient of a returned scalar tensor with
respect to the arguments' parameters, and what became of each argument (an array changed in
place, a roadmap whose edges were removed, a generator that drew numbers), so that the hidden
tests can see those effects too. A checker among the arguments is a stand-in here: each question
it is asked goes to the grader's checker, which counts it. The global random generators
(``numpy.random``, ``random``, torch's) are seeded afresh before each call: an answer that draws
from them is not reproducible, as the specifications require. The protocol uses the process's
original stdin and stdout; what the notebook prints goes to stderr, which the grader never reads.
"""

from __future__ import annotations

import io
import json
import os
import random
import sys
import types
from pathlib import Path

import dill
import numpy as np

from toolkit.geometry.checker import CollisionChecker
from toolkit.teaching import unavailable, wire


class Channel:
    """The two ends of the pipe to the grader."""

    def __init__(self, inbox: int, outbox: int):
        self.inbox, self.outbox = inbox, outbox
        self.checkers: dict[int, RemoteChecker] = {}

    def send(self, message: dict) -> None:
        wire.send(self.outbox, wire.dumps(message))

    def receive(self) -> dict:
        return _Unpickler(self, wire.receive(self.inbox)).load()


class _Unpickler(dill.Unpickler):
    """The grader's pickles, with a :class:`RemoteChecker` wherever the grader's message holds a checker."""

    def __init__(self, channel: Channel, payload: bytes):
        super().__init__(io.BytesIO(payload))
        self.channel = channel

    def persistent_load(self, pid):
        _, key, robot, few_calls, certificates_pay = pid
        if key not in self.channel.checkers:
            self.channel.checkers[key] = RemoteChecker(self.channel, key, robot, few_calls, certificates_pay)
        return self.channel.checkers[key]


class RemoteChecker(CollisionChecker):
    """A checker whose answers come from the grader's checker (which counts every question it is asked)."""

    def __init__(self, channel: Channel, key: int, robot, few_calls: bool, certificates_pay: bool):
        super().__init__(robot)
        self._channel, self._key = channel, key
        self.few_calls, self.certificates_pay = few_calls, certificates_pay

    def validity(self, Q) -> np.ndarray:
        return self._ask("validity", Q, None)

    def clearance_bounds(self, Q, cap: float) -> np.ndarray:
        return self._ask("clearance_bounds", Q, cap)

    def _ask(self, method: str, Q, cap: float | None) -> np.ndarray:
        self._channel.send({"ask": self._key, "method": method, "Q": np.asarray(Q, dtype=float), "cap": cap})
        reply = self._channel.receive()
        if "error" in reply:
            raise ValueError(reply["error"])
        return reply["answer"]


def graded_cells(notebook: dict) -> list[str]:
    """The source of each code cell grading runs: not ``otter_ignore``, not otter's own (not editable), without
    IPython's ``%`` and ``!`` lines."""
    cells = []
    for cell in notebook["cells"]:
        meta = cell.get("metadata", {})
        if cell["cell_type"] != "code" or "otter_ignore" in meta.get("tags", []) or not meta.get("editable", True):
            continue
        source = cell["source"] if isinstance(cell["source"], str) else "".join(cell["source"])
        cells.append("\n".join("" if line.lstrip()[:1] in ("%", "!") else line for line in source.splitlines()))
    return cells


def run_notebook(path: str) -> dict:
    """The namespace the notebook's graded cells leave behind (a cell that raises is skipped, as otter does)."""
    namespace: dict = {"__name__": "__main__"}
    for number, source in enumerate(graded_cells(json.loads(Path(path).read_text())), start=1):
        try:
            exec(compile(source, f"<code cell {number}>", "exec"), namespace)
        except BaseException:  # a student's cell may raise anything, SystemExit included
            continue
    return namespace


def _reseed() -> None:
    """Fresh seeds for the global random generators: an answer that draws from them differs from call to call."""
    np.random.seed(int.from_bytes(os.urandom(4), "little"))
    random.seed(os.urandom(16))
    if "torch" in sys.modules:
        sys.modules["torch"].manual_seed(int.from_bytes(os.urandom(4), "little"))


def _state(value: object) -> object:
    """What became of an argument, as plain values (None where nothing of it can come back)."""
    if isinstance(value, np.random.Generator):
        return ["rng", value.bit_generator.state]
    if isinstance(value, np.ndarray | list | dict | tuple):
        return ["value", value]
    torch = wire.loaded_torch()
    if torch is not None and isinstance(value, torch.Tensor):
        return ["value", value.detach()]
    if torch is not None and isinstance(value, torch.nn.Module):
        return ["module", {name: p.detach() for name, p in value.state_dict().items()}]
    if isinstance(value, CollisionChecker) or not hasattr(value, "__dict__"):
        return None
    return ["attrs", {k: v for k, v in vars(value).items() if isinstance(v, np.ndarray | int | float | bool)}]


def _gradients(result: object, args: tuple, kwargs: dict) -> list:
    """``[[argument, parameter name or "", gradient], ...]``: the gradient of a scalar tensor ``result`` with respect
    to every parameter of the arguments that are modules and every argument tensor that requires it."""
    torch = wire.loaded_torch()
    if torch is None or not isinstance(result, torch.Tensor) or result.ndim != 0 or not result.requires_grad:
        return []
    leaves = []
    for where, value in [*enumerate(args), *kwargs.items()]:
        if isinstance(value, torch.nn.Module):
            leaves += [(where, name, p) for name, p in value.named_parameters() if p.requires_grad]
        elif isinstance(value, torch.Tensor) and value.requires_grad:
            leaves.append((where, "", value))
    if not leaves:
        return []
    grads = torch.autograd.grad(result, [leaf for *_, leaf in leaves], allow_unused=True, retain_graph=True)
    return [[where, name, g.detach()] for (where, name, _), g in zip(leaves, grads) if g is not None]


def answer(namespace: dict, request: dict) -> dict:
    """Run one request of the grader: call a function of the notebook, or set one of its names."""
    if "set" in request:
        namespace[request["set"]] = request["value"]
        return {"done": True}
    args, kwargs = tuple(request["args"]), dict(request["kwargs"])
    function = namespace.get(request["call"])
    if not callable(function):
        return {"raised": f"NameError: the notebook defines no function {request['call']!r}"}
    _reseed()
    try:
        result = function(*args, **kwargs)
        reply: dict = {"result": result, "gradients": _gradients(result, args, kwargs)}
    except BaseException as error:  # what the student's function raised goes back as text
        reply = {"raised": f"{type(error).__name__}: {error}"}
    reply["after"] = [_plain(_state(a)) for a in args]
    reply["after_kw"] = {k: _plain(_state(v)) for k, v in kwargs.items()}
    return reply


def _plain(value: object) -> object:
    """``value`` where it can cross as plain values, else None."""
    try:
        wire.encode(value)
    except wire.NotPlain:
        return None
    return value


def main(argv: list[str]) -> None:
    notebook, assignment = argv
    channel = Channel(os.dup(0), os.dup(1))  # the grader's pipe; the notebook gets /dev/null and stderr instead
    os.dup2(os.open(os.devnull, os.O_RDONLY), 0)
    os.dup2(2, 1)
    unavailable.apply(assignment)  # before the notebook runs: a copied code object is the refusal
    namespace = run_notebook(notebook)
    functions = [k for k, v in namespace.items() if callable(v) and not isinstance(v, types.ModuleType)]
    channel.send({"ready": sorted(k for k in functions if not k.startswith("__"))})
    while True:
        try:
            request = channel.receive()
        except EOFError:
            return
        try:
            channel.send(answer(namespace, request))
        except wire.NotPlain as error:
            channel.send({"raised": f"TypeError: it returned {error}; return arrays, numbers, bools, or lists of them"})


if __name__ == "__main__":
    main(sys.argv[1:])
