"""What crosses between a submission's sandbox and the grader: messages of plain values.

The grader (:mod:`~toolkit.teaching.grading`) sends the submission's process
(:mod:`~toolkit.teaching.submission`) pickles: the grader's own objects, which the submission may
trust. Everything coming back is **plain values** only, encoded here as JSON: ``None``, bools,
numbers, strings, lists, tuples, dicts, numpy arrays and scalars of numbers or bools, and torch
tensors (their values, and the gradient of a scalar one with respect to the arguments'
parameters). :func:`decode` builds nothing else, so no object of the submission's making (a
``numpy.isclose`` that always says yes, a tensor subclass, a fake results file) can reach the
process that decides the score. Each message is a length (8 bytes) and its bytes.
"""

from __future__ import annotations

import base64
import json
import os
import select
import struct
import sys
import time

import numpy as np

KINDS = "biufc"  # numpy dtype kinds that may cross: bool, int, unsigned, float, complex
LARGEST = 2**28  # bytes in one message from a submission (256 MiB)


class NotPlain(TypeError):
    """A value a submission returned that is not a plain value."""


def encode(value) -> object:
    """``value`` as JSON-ready data (:func:`decode` inverts it); :class:`NotPlain` for anything else."""
    if value is None or type(value) in (bool, int, float, str):
        return value
    if isinstance(value, np.ndarray | np.generic):
        array = np.asarray(value)
        if array.dtype.kind not in KINDS:
            raise NotPlain(f"an array of {array.dtype} (only numbers and bools cross)")
        data = base64.b64encode(np.ascontiguousarray(array).tobytes()).decode()
        key = "$array" if isinstance(value, np.ndarray) else "$scalar"
        return {key: [array.dtype.str, list(array.shape), data]}
    if type(value) in (list, tuple):
        items = [encode(v) for v in value]
        return items if type(value) is list else {"$tuple": items}
    if type(value) is dict:
        return {"$dict": [[encode(k), encode(v)] for k, v in value.items()]}
    import torch  # only where tensors are used (cae_loss)

    if type(value) is torch.Tensor or isinstance(value, torch.nn.Parameter):
        return {"$tensor": encode(value.detach().cpu().numpy().copy())}
    raise NotPlain(f"a {type(value).__module__}.{type(value).__qualname__}")


def decode(data: object) -> object:
    """The plain value :func:`encode` wrote (checked: arrays of numbers or bools whose bytes match their shape)."""
    if data is None or type(data) in (bool, int, float, str):
        return data
    if type(data) is list:
        return [decode(v) for v in data]
    if type(data) is dict and len(data) == 1:
        ((key, body),) = data.items()
        if key in ("$array", "$scalar"):
            dtype, shape, raw = body
            dtype = np.dtype(str(dtype))
            if dtype.kind not in KINDS or not all(type(n) is int and n >= 0 for n in shape):
                raise NotPlain(f"an array of {dtype} with shape {shape}")
            array = np.frombuffer(base64.b64decode(raw, validate=True), dtype=dtype)
            if array.size != int(np.prod(shape)):
                raise NotPlain(f"{array.size} values for the shape {shape}")
            array = array.reshape(shape).copy()
            return array if key == "$array" else array[()]
        if key == "$tuple":
            return tuple(decode(v) for v in body)
        if key == "$dict":
            return {_key(decode(k)): decode(v) for k, v in body}
        if key == "$tensor":
            import torch

            return torch.as_tensor(decode(body))
    raise NotPlain(f"not a plain value: {str(data)[:80]}")


def _key(key: object) -> object:
    """A decoded dict key (arrays are not hashable, a tuple of plain values is)."""
    if isinstance(key, np.ndarray | list):
        raise NotPlain("a dict key that is an array or a list")
    return key


def loaded_torch():
    """torch where this process has imported it (an import under way in another thread is waited for), else None:
    only then can a value be a tensor."""
    if "torch" not in sys.modules:
        return None
    import torch

    return torch


def send(fd: int, payload: bytes) -> None:
    """Write one message to ``fd``."""
    view = memoryview(struct.pack("<Q", len(payload)) + payload)
    while view:
        view = view[os.write(fd, view) :]


def receive(fd: int, deadline: float | None = None) -> bytes:
    """Read one message from ``fd``; :class:`EOFError` when the other side has gone, :class:`TimeoutError` past
    ``deadline`` (a ``time.monotonic()`` value)."""
    (size,) = struct.unpack("<Q", _read(fd, 8, deadline))
    if size > LARGEST:
        raise NotPlain(f"a message of {size} bytes (at most {LARGEST})")
    return _read(fd, size, deadline)


def _read(fd: int, size: int, deadline: float | None) -> bytes:
    chunks, left = [], size
    while left:
        if deadline is not None:
            wait = deadline - time.monotonic()
            if wait <= 0 or not select.select([fd], [], [], wait)[0]:
                raise TimeoutError("no answer in time")
        chunk = os.read(fd, min(left, 2**20))
        if not chunk:
            raise EOFError("the other side has gone")
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def dumps(value: object) -> bytes:
    """A plain message (a dict of plain values) as bytes."""
    return json.dumps(encode(value)).encode()


def loads(payload: bytes) -> object:
    """:func:`dumps` inverted, checking that it holds plain values only."""
    return decode(json.loads(payload))
