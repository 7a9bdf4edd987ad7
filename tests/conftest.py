"""Shared test set-up: headless plotting, few threads, a fixed seed."""

import os

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(0)


@pytest.fixture
def make_viewer():
    """Viewers on free ports (``port=0``), always stopped afterwards."""
    from toolkit import viewer

    started = []

    def make(scenario, **kwargs):
        v = viewer.Viewer(scenario, port=0, **kwargs)
        started.append(v)
        return v

    yield make
    for v in started:
        v.stop()
