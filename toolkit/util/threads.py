"""How many threads torch and numpy's BLAS use: one, unless ``TOOLKIT_THREADS`` says otherwise.

The toolkit's work comes in small pieces: a learned checker's call is a few hundred
to a few ten thousand configurations, a 2D or 3D-clutter model trains on batches of
a few hundred. Split over several threads, each piece waits for its slowest thread,
and when another program keeps a core busy (a browser, a notebook, a second run: a
student's laptop) that wait is most of the time: one thread is several times faster
then (measured in tutorials/instructors.md, "On a busy machine").

So every ``toolkit`` command runs on :func:`configured` threads: 1 by default;
``TOOLKIT_THREADS=N`` for N, ``TOOLKIT_THREADS=0`` for the libraries' own defaults
(one per core; it may pay on an idle machine for large networks such as the paper's
3DO CAE). From Python, ``with threads.limited(n):`` does the same
for a block.
"""

from __future__ import annotations

import os
from contextlib import contextmanager

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
    import torch  # here, not at the top: commands that never touch a network do not wait for torch to load

    before = torch.get_num_threads()
    torch.set_num_threads(n)
    try:
        with threadpool_limits(limits=n, user_api="blas"):
            yield
    finally:
        torch.set_num_threads(before)
