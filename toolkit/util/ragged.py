"""Index arithmetic for ragged batches: items grouped under owners, each owner holding its own count."""

from __future__ import annotations

import numpy as np


def ragged(counts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For counts ``(A,)``: owner index and ordinal within its owner of ``sum(counts)`` items, ``(sum,)`` each."""
    counts = np.asarray(counts)
    owner = np.repeat(np.arange(len(counts)), counts)
    start = np.cumsum(counts) - counts
    return owner, np.arange(len(owner)) - start[owner]
