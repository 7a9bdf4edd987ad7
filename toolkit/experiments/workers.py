"""Worker processes that stop with their parent: how ``toolkit reproduce`` plans its samplers side by side.

Each sampler's queries are timed in a process of its own, one per core, so a
reproduction takes the time of its slowest sampler rather than their sum. A
``ProcessPoolExecutor`` alone would finish every task before an interruption goes
on; :func:`processes` kills its workers first, and every worker exits by itself
when its parent is gone, so nothing is left running after Ctrl-C, SIGTERM or a crash.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
import time
from collections.abc import Iterator
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager


@contextmanager
def processes(n: int) -> Iterator[ProcessPoolExecutor | None]:
    """``n`` fresh worker processes (None when ``n`` <= 1: work in this process).

    On any exception, Ctrl-C included, the workers are killed before it goes on.
    """
    if n <= 1:
        yield None
        return
    spawn = multiprocessing.get_context("spawn")  # fresh interpreters: no forked torch thread pools
    pool = ProcessPoolExecutor(n, mp_context=spawn, initializer=_worker_start)
    try:
        yield pool
    except BaseException:
        if hasattr(pool, "terminate_workers"):  # Python >= 3.14
            pool.terminate_workers()
        else:  # the same by hand: the pool's own table of its worker processes
            for process in list((pool._processes or {}).values()):
                process.terminate()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def _worker_start() -> None:
    """In each worker: leave Ctrl-C to the parent (which stops the workers), and exit if the parent dies
    without doing so (SIGKILL, a crash) rather than wait for work forever."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, daemon=True).start()
