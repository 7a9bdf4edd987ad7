"""How many threads torch and numpy's BLAS use: one, unless ``TOOLKIT_THREADS`` says otherwise.

The toolkit's work comes in small pieces: a learned checker's call is a few hundred
to a few ten thousand configurations, a 2D or 3D-clutter model trains on batches of
a few hundred. Split over several threads, each piece waits for its slowest thread,
and when another program keeps a core busy (a browser, a notebook, a second run: a
student's laptop) that wait is most of the time. Measured on 2 cores shared with
other work (docs/benchmarks.md): ``toolkit train --scenario 2ds --quick`` took 27 s
on one thread and 46 s on torch's default two; beside a CPU-bound process per core,
97 s and 230 s. ``toolkit bench`` predicted 10 to 40 times fewer configurations a
second on two threads than on one, in every scenario. The queries' timing
(:func:`toolkit.queries.one_thread`) had shown the same: 3DC-7 bridge-test sampling
with prediction 2.4 ms a query on 2 threads, 1.2 ms on one.

So every ``toolkit`` command runs on :func:`configured` threads: 1 by default;
``TOOLKIT_THREADS=N`` for N, ``TOOLKIT_THREADS=0`` for the libraries' own defaults
(one per core; it may pay on an idle machine for large networks such as the paper's
3DO CAE, not measured here). From Python, ``with threads.limited(n):`` does the same
for a block.
"""

from __future__ import annotations

import os
from contextlib import contextmanager

import torch
from threadpoolctl import threadpool_limits

ENV = "TOOLKIT_THREADS"


def configured() -> int | None:
    """Threads from ``TOOLKIT_THREADS`` (default 1); None for ``0``: leave the libraries' defaults."""
    text = os.environ.get(ENV, "").strip()
    if not text:
        return 1
    if not text.isdigit():
        raise ValueError(f"{ENV}={text!r}: expected a whole number of threads, 1 or more (0: one per core)")
    return int(text) or None


@contextmanager
def limited(n: int | None):
    """Torch's intra-op threads and numpy's BLAS threads at ``n`` inside (None: unchanged); restored after."""
    if n is None:
        yield
        return
    before = torch.get_num_threads()
    torch.set_num_threads(n)
    try:
        with threadpool_limits(limits=n, user_api="blas"):
            yield
    finally:
        torch.set_num_threads(before)
