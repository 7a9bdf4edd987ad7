"""Each roadmap planner's parameters, frozen and checked when they are made: a planner owns its own.

- :class:`PaperParams`: Algorithm 1 as the paper has it (§III-B; :mod:`toolkit.planning.paper_prm`,
  planner ``paper``): rounds of |S| = ``n_samples`` attempts, every candidate edge checked exactly as
  it is added;
- :class:`LazyParams`: the lazy PRM (:mod:`toolkit.planning.lazy_prm`, planner ``lazy``), the best
  exact planner we have, and with prediction the paper's future work, learned edge screening;
- :class:`BatchedParams`: the batched PRM (:mod:`toolkit.planning.batched_prm`, planner ``batched``),
  the lazy PRM with each round's samples decided in one checker call (a device call on a device).

No planner's parameters inherit another's: all take the fields every roadmap planner reads from
:class:`RoadmapParams` (what :mod:`toolkit.planning.query_roadmap` reads), the lazy planners those of
:class:`LazyEdgeParams`, and each adds its own.
The query's resolution and sampler are the problem's, not a planner's
(:class:`toolkit.planning.planner.Problem`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

AUXILIARY = {  # RoadmapParams.auxiliary: how rounds after the first sample, with prediction
    "exact": "with the exact checker (the paper: 'create additional valid samples using auxiliary samplers')",
    "confirmed": "with prediction, keeping what the exact checker confirms; every exact_every-th round "
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
    "True or False": lambda v: isinstance(v, bool),
    f"one of {', '.join(AUXILIARY)}": lambda v: v in AUXILIARY,
}


@dataclass(frozen=True)
class RoadmapParams:
    """What every roadmap planner reads; ``k`` follows OMPL's PRM, ``n_samples`` the paper's |S| (§IV-A)."""

    n_samples: int = 200  # sampler attempts per round (|S|; a query of a scenario: its plan_samples)
    k: int = 10  # nearest neighbours tried for each new node
    max_rounds: int = 20  # sampling rounds before reporting failure
    rebridge: int = 3  # when no path survives verification, bridge again up to this often before sampling again
    auxiliary: str = "exact"  # with prediction, rounds after the first: see AUXILIARY
    exact_every: int = 4  # auxiliary "confirmed": rounds 1 + exact_every, 1 + 2 * exact_every, ... sample exactly
    certify_spacing: float = 8.0  # path verification: intervals of resolution * this first (certify_edges)

    rules: ClassVar[dict[str, str]] = {  # field -> its RULES key (not a field: a subclass adds its fields' rules)
        **dict.fromkeys(("n_samples", "k", "max_rounds", "exact_every"), "a positive integer"),
        "rebridge": "a non-negative integer",
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


@dataclass(frozen=True)
class PaperParams(RoadmapParams):
    """Algorithm 1's parameters: the roadmap planners' and no more (with prediction, later rounds sample exactly)."""


@dataclass(frozen=True)
class LazyEdgeParams(RoadmapParams):
    """What the lazy planners read (no planner's parameters themselves): the roadmap planners', and how edges are
    decided lazily and rounds grow."""

    auxiliary: str = "confirmed"  # with prediction, rounds after the first: see AUXILIARY
    first_samples: int | None = 50  # round r samples min(first_samples * 2**(r-1), n_samples); None: n_samples
    lazy_screen: float | None = 32.0  # exact edges: points resolution * this apart checked as added (None: none)
    screen_edges: bool = True  # with prediction: learned edge screening; False: exact lazy edges
    screen_reject: float = 0.9  # screening drops edges with a larger predicted-invalid fraction
    screen_penalty: float = 10.0  # screened edge cost = length * (1 + penalty * predicted-invalid fraction)
    screen_spacing: float = 8.0  # screening predicts points resolution * this apart (an estimate of the fraction)

    rules: ClassVar[dict[str, str]] = {
        **RoadmapParams.rules,
        "first_samples": "a positive integer or None",
        "lazy_screen": "positive and finite, or None",
        "screen_edges": "True or False",
        "screen_spacing": "positive and finite",
        "screen_reject": "in [0, 1]",
        "screen_penalty": "non-negative and finite",
    }


@dataclass(frozen=True)
class LazyParams(LazyEdgeParams):
    """The lazy PRM's parameters: the roadmap planners', and how it decides edges lazily and grows its rounds."""


@dataclass(frozen=True)
class BatchedParams(LazyEdgeParams):
    """The batched PRM's parameters: the lazy PRM's fields, every round |S| attempts (on a device a call of |S|
    costs what one of 50 does, so rounds need not grow)."""

    first_samples: int | None = None  # round r samples min(first_samples * 2**(r-1), n_samples); None: n_samples
