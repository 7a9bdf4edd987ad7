"""The batched PRM: the lazy PRM with each round's samples decided in one checker call, for a device.

A checker on a GPU answers a call of a few thousand configurations in about the time it
answers one of a few hundred: the call's fixed cost (launches, a copy each way, a wait) is
most of it (``docs/gpu.md``). The samplers of :mod:`toolkit.planning.sampling` ask their checker
in several dependent calls where they must: the obstacle-based sampler walks its segments 16
steps at a time, stopping each where it meets an obstacle; the bridge test asks a checker that
is not ``few_calls`` about its second ends only where the first collide. :class:`BatchedPRM`, the
planner ``batched``, is :class:`~toolkit.planning.lazy_prm.LazyPRM` with one step changed, how a
round's attempts are drawn (:meth:`BatchedPRM.draw`): every configuration an attempt could need
is drawn first, on the host from ``rng``, and the deciding checker is asked about all of them in
**one call** (a device call when the checker is on a device), whatever checker it is:

- ``BS``: the uniform draws;
- ``G``: both configurations of every pair;
- ``BT``: both ends and the midpoint of every pair;
- ``OB``: every point of every segment between two uniform draws, ends included, at the sampler's
  resolution (no bisections, the sampler's default); a segment whose ends differ gives the last
  valid point walking from its valid end towards its invalid one. Its pairs are fixed before the
  call (the sampler pairs the draws it found valid with those it found invalid): two independent
  uniform draws, one valid and one not, either way, so its samples have the same distribution,
  with fewer per attempt and more checks;
- a sampler registered later: its own ``sample`` (its own calls).

Rounds do not grow (:class:`~toolkit.planning.options.BatchedParams`: ``first_samples=None``):
each is |S| attempts. Edges are the lazy PRM's, decided in batches: all of a round's candidate
edges in one call, screened by prediction or looked at in a few exact points, and a candidate
path's edges verified exactly together. So every returned path has passed the exact checker, as
with every planner here. The planner has no device of its own: the device is the checker's, and
"with / without prediction" changes the checker only.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.local_planner import segment_points, step_counts
from toolkit.planning.options import BatchedParams
from toolkit.planning.sampling import (
    BridgeTestSampler,
    GaussianSampler,
    ObstacleBasedSampler,
    Sampler,
    UniformSampler,
)
from toolkit.util.ragged import ragged

Proposal = tuple[np.ndarray, Callable[[np.ndarray], np.ndarray]]  # candidates (C, dof), select(valid (C,)) -> (M, dof)


class BatchedPRM(LazyPRM):
    """The lazy PRM, each round's attempts decided in one call of the deciding checker."""

    name = "batched"
    Params = BatchedParams  # type: ignore[assignment]  # its own parameters, not the lazy PRM's

    def draw(self, sampler: Sampler, n: int, rng: np.random.Generator) -> np.ndarray:
        """``(M, dof)`` the samples of ``n`` attempts of ``sampler``: its candidates decided in one call."""
        propose = PROPOSALS.get(type(sampler))
        if propose is None:  # a sampler of one's own: its own calls
            return sampler.sample(n, rng)
        candidates, select = propose(sampler, n, rng)
        return select(sampler.valid(candidates))  # the bounds, then one call of the checker


def uniform(sampler: Sampler, n: int, rng: np.random.Generator) -> Proposal:
    """BS: ``n`` uniform draws; the valid ones."""
    Q = sampler.robot.sample(rng, n)  # (n, dof)
    return Q, lambda valid: Q[valid]


def gaussian(sampler: GaussianSampler, n: int, rng: np.random.Generator) -> Proposal:
    """G: ``n`` pairs ``(q1, q2 ~ N(q1, sigma))``; of a pair with exactly one valid, that one."""
    Q1 = sampler.robot.sample(rng, n)  # (n, dof)
    Q2 = sampler.near(Q1, rng)

    def select(valid: np.ndarray) -> np.ndarray:
        first, second = valid.reshape(2, n)
        one = first != second
        return np.where(first[one, None], Q1[one], Q2[one])

    return np.concatenate([Q1, Q2]), select


def bridge(sampler: BridgeTestSampler, n: int, rng: np.random.Generator) -> Proposal:
    """BT: ``n`` pairs ``(q1, q2 ~ N(q1, sigma))`` and their midpoints; a valid midpoint of two invalid ends."""
    Q1 = sampler.robot.sample(rng, n)  # (n, dof)
    Q2 = sampler.near(Q1, rng)
    middle = segment_points(sampler.robot, Q1, Q2, np.full(n, 0.5))

    def select(valid: np.ndarray) -> np.ndarray:
        first, second, mid = valid.reshape(3, n)
        return middle[~first & ~second & mid]

    return np.concatenate([Q1, Q2, middle]), select


def obstacle_based(sampler: ObstacleBasedSampler, n: int, rng: np.random.Generator) -> Proposal:
    """OB: ``n`` segments between two uniform draws, every point at the sampler's resolution, ends included; of a
    segment whose ends differ, the last valid point before the first invalid one, walking from its valid end."""
    robot = sampler.robot
    A, B = robot.sample(rng, 2 * n).reshape(2, n, robot.dof)  # (n, dof) each
    steps = step_counts(robot, A, B, sampler.resolution)  # (n,)
    owner, ordinal = ragged(steps + 1)  # (P,) each: ordinal 0 is A, ordinal steps is B
    points = segment_points(robot, A[owner], B[owner], ordinal / steps[owner])  # (P, dof)
    first_point = np.cumsum(steps + 1) - (steps + 1)  # (n,) where each segment's points begin

    def select(valid: np.ndarray) -> np.ndarray:
        bad = ~valid
        first_bad = np.full(n, np.iinfo(int).max)
        last_bad = np.full(n, -1)
        np.minimum.at(first_bad, owner[bad], ordinal[bad])
        np.maximum.at(last_bad, owner[bad], ordinal[bad])
        from_a = valid[first_point] & bad[first_point + steps]  # (n,) A valid, B not: walk from A
        from_b = bad[first_point] & valid[first_point + steps]  # B valid, A not: walk from B
        chosen = np.concatenate([(first_point + first_bad - 1)[from_a], (first_point + last_bad + 1)[from_b]])
        return points[np.sort(chosen)]

    return points, select


PROPOSALS: dict[type, Callable[..., Proposal]] = {  # sampler class -> its attempts as one call's candidates
    UniformSampler: uniform,
    GaussianSampler: gaussian,
    BridgeTestSampler: bridge,
    ObstacleBasedSampler: obstacle_based,
}
