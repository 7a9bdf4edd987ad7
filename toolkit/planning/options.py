"""The planners' settings, checked when they are made: the options' class says which planner runs.

- :class:`PRMOptions`: Algorithm 1 as the paper has it (§III-B; :mod:`toolkit.planning.paper_prm`):
  rounds of |S| = ``n_samples`` attempts, every candidate edge checked exactly as it is added;
- :class:`LazyPRMOptions` (``PRMOptions`` and the fields only the lazy planner reads): the lazy
  PRM (:mod:`toolkit.planning.lazy_prm`), the best exact planner we have, and with prediction the
  paper's future work, learned edge screening.

``plan(exact, start, goal, options=...)`` (:mod:`toolkit.planning.prm`) runs the planner of the
options' class; without options, the lazy PRM with ``LazyPRMOptions()``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

AUXILIARY = {  # PRMOptions.auxiliary: how rounds after the first sample, with prediction
    "exact": "with the exact checker (the paper: 'create additional valid samples using auxiliary samplers')",
    "confirmed": "with prediction, keeping what the exact checker confirms; every PRMOptions.exact_every-th round "
    "(counting from the first) with the exact checker",
    "predicted": "with prediction, like the first (nodes are checked when a candidate path uses them)",
}


RULES = {  # what a field must be: __post_init__ checks each field against its rule (``rules``)
    "a positive integer": lambda v: int(v) == v and v >= 1,
    "a positive integer or None": lambda v: v is None or (int(v) == v and v >= 1),
    "a non-negative integer": lambda v: int(v) == v and v >= 0,
    "positive and finite": lambda v: bool(np.isfinite(v)) and v > 0,
    "positive and finite, or None": lambda v: v is None or (bool(np.isfinite(v)) and v > 0),
    "non-negative and finite": lambda v: bool(np.isfinite(v)) and v >= 0,
    "in [0, 1]": lambda v: 0 <= v <= 1,
    f"one of {', '.join(AUXILIARY)}": lambda v: v in AUXILIARY,
}


@dataclass
class PRMOptions:
    """Algorithm 1's settings; ``k`` follows OMPL's PRM, ``n_samples`` the paper's |S| (§IV-A)."""

    n_samples: int = 200  # sampler attempts per round (|S|)
    k: int = 10  # nearest neighbours tried for each new node
    resolution: float | None = None  # local planner step bound; None: default_resolution(robot)
    verify_refinement: int = 10  # the returned path's edges are checked exactly at resolution / this
    max_rounds: int = 20  # sampling rounds before reporting failure
    rebridge: int = 3  # when no path survives verification, bridge again up to this often before sampling again
    auxiliary: str = "exact"  # with prediction, rounds after the first: see AUXILIARY
    exact_every: int = 4  # auxiliary "confirmed": rounds 1 + exact_every, 1 + 2 * exact_every, ... sample exactly
    certify_spacing: float = 8.0  # path verification: intervals of motion resolution * this first (certify_edges)
    sampler_options: dict = field(default_factory=dict)  # keyword arguments of the sampler (make_sampler)

    rules: ClassVar[dict[str, str]] = {  # field -> its RULES key (not a field: a subclass adds its fields' rules)
        **dict.fromkeys(("n_samples", "k", "verify_refinement", "max_rounds", "exact_every"), "a positive integer"),
        "rebridge": "a non-negative integer",
        "resolution": "positive and finite, or None",
        "certify_spacing": "positive and finite",
        "auxiliary": f"one of {', '.join(AUXILIARY)}",
    }

    def __post_init__(self):
        for name, rule in self.rules.items():
            value = getattr(self, name)
            try:
                ok = RULES[rule](value)
            except (TypeError, ValueError):  # e.g. None or a string where a number belongs
                ok = False
            if not ok:
                raise ValueError(f"{type(self).__name__}.{name} must be {rule}, got {value!r}")


@dataclass
class LazyPRMOptions(PRMOptions):
    """The lazy PRM's settings: Algorithm 1's, and how it decides edges lazily and grows its rounds."""

    auxiliary: str = "confirmed"  # (the lazy PRM's default) with prediction, rounds after the first: see AUXILIARY
    first_samples: int | None = 50  # round r samples min(first_samples * 2**(r-1), n_samples); None: n_samples
    lazy_screen: float | None = 32.0  # exact edges: points resolution * this apart checked as added (None: none)
    screen_edges: bool = True  # with prediction: learned edge screening; False: exact lazy edges
    screen_reject: float = 0.9  # screening drops edges with a larger predicted-invalid fraction
    screen_penalty: float = 10.0  # screened edge cost = length * (1 + penalty * predicted-invalid fraction)
    screen_spacing: float = 8.0  # screening predicts points resolution * this apart (an estimate of the fraction)

    rules: ClassVar[dict[str, str]] = {
        **PRMOptions.rules,
        "first_samples": "a positive integer or None",
        "lazy_screen": "positive and finite, or None",
        "screen_spacing": "positive and finite",
        "screen_reject": "in [0, 1]",
        "screen_penalty": "non-negative and finite",
    }
