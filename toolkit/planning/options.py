"""The planner's settings, :class:`PRMOptions`, checked when they are made.

Two planners read them (``PRMOptions.planner``):

- ``"paper"``: Algorithm 1 as the paper has it (§III-B; :mod:`toolkit.planning.paper_prm`):
  rounds of |S| = ``n_samples`` attempts, every candidate edge checked exactly as it is added;
- ``"lazy"`` (the default): the lazy PRM (:mod:`toolkit.planning.lazy_prm`), the best exact
  planner we have, and with prediction the paper's future work, learned edge screening.

Fields marked *lazy PRM only* below are read by the lazy planner alone; the paper's planner
ignores them. ``PAPER_BASELINE`` is the one field that makes a set of options the paper's:
``PRMOptions(**PAPER_BASELINE)`` or ``dataclasses.replace(options, **PAPER_BASELINE)``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

PLANNERS = {  # PRMOptions.planner
    "lazy": "the lazy PRM (Bohlin & Kavraki 2000): the best exact planner, and learned edge screening with prediction",
    "paper": "Algorithm 1 as the paper has it: rounds of |S|, every candidate edge checked exactly as it is added",
}
AUXILIARY = {  # PRMOptions.auxiliary: how rounds after the first sample, with prediction (both planners)
    "exact": "with the exact checker",
    "confirmed": "with prediction, keeping what the exact checker confirms; every PRMOptions.exact_every-th round "
    "(counting from the first) with the exact checker",
    "predicted": "with prediction, like the first (nodes are checked when a candidate path uses them)",
}

PAPER_BASELINE: dict[str, Any] = {"planner": "paper"}  # PRMOptions of Algorithm 1 as the paper has it


@dataclass
class PRMOptions:
    """Planner settings; ``k`` follows OMPL's PRM, ``n_samples`` the paper's |S| (§IV-A)."""

    planner: str = "lazy"  # "lazy" or "paper": see PLANNERS
    n_samples: int = 200  # sampler attempts per round (|S|)
    k: int = 10  # nearest neighbours tried for each new node
    resolution: float | None = None  # local planner step bound; None: default_resolution(robot)
    verify_refinement: int = 10  # the returned path's edges are checked exactly at resolution / this
    max_rounds: int = 20  # sampling rounds before reporting failure
    rebridge: int = 3  # when no path survives verification, bridge again up to this often before sampling again
    auxiliary: str = "confirmed"  # with prediction, rounds after the first: see AUXILIARY
    exact_every: int = 4  # auxiliary "confirmed": rounds 1 + exact_every, 1 + 2 * exact_every, ... sample exactly
    certify_spacing: float = 8.0  # path verification: intervals of motion resolution * this first (certify_edges)
    sampler_options: dict = field(default_factory=dict)  # keyword arguments of the sampler (make_sampler)
    # lazy PRM only:
    first_samples: int | None = 50  # round r samples min(first_samples * 2**(r-1), n_samples); None: n_samples
    lazy_screen: float | None = 32.0  # exact edges: points resolution * this apart checked as added (None: none)
    screen_edges: bool = True  # with prediction: learned edge screening; False: exact lazy edges
    screen_reject: float = 0.9  # screening drops edges with a larger predicted-invalid fraction
    screen_penalty: float = 10.0  # screened edge cost = length * (1 + penalty * predicted-invalid fraction)
    screen_spacing: float = 8.0  # screening predicts points resolution * this apart (an estimate of the fraction)

    def __post_init__(self):
        if self.planner not in PLANNERS:
            raise ValueError(f"PRMOptions.planner must be one of {sorted(PLANNERS)}, got {self.planner!r}")
        for name in ("n_samples", "k", "verify_refinement", "max_rounds", "exact_every", "first_samples"):
            value = getattr(self, name)
            if value is None and name == "first_samples":
                continue
            if int(value) != value or value < 1:
                raise ValueError(f"PRMOptions.{name} must be a positive integer, got {value!r}")
        if int(self.rebridge) != self.rebridge or self.rebridge < 0:
            raise ValueError(f"PRMOptions.rebridge must be a non-negative integer, got {self.rebridge!r}")
        for name in ("resolution", "screen_spacing", "certify_spacing", "lazy_screen"):
            value = getattr(self, name)
            if value is not None and not (np.isfinite(value) and value > 0):
                raise ValueError(f"PRMOptions.{name} must be positive and finite, got {value!r}")
        if self.auxiliary not in AUXILIARY:
            raise ValueError(f"PRMOptions.auxiliary must be one of {sorted(AUXILIARY)}, got {self.auxiliary!r}")
        if not 0 <= self.screen_reject <= 1:
            raise ValueError(f"PRMOptions.screen_reject must lie in [0, 1], got {self.screen_reject!r}")
        if not (np.isfinite(self.screen_penalty) and self.screen_penalty >= 0):
            raise ValueError(f"PRMOptions.screen_penalty must be non-negative and finite, got {self.screen_penalty!r}")
