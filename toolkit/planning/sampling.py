"""The paper's four samplers (§III-B "Sample Generation"), each over any collision checker.

- ``BS`` uniform (Kavraki et al. 1996): uniform configurations the checker accepts.
- ``OB`` obstacle-based (Amato et al. 1998), as OMPL's ``ObstacleBasedValidStateSampler``:
  pair an invalid with a valid configuration and return the last valid state on the
  segment from the valid one towards the invalid one, next to an obstacle boundary.
- ``G`` Gaussian (Boor et al. 1999): ``q1`` uniform, ``q2 ~ N(q1, sigma^2 I)``; keep
  whichever of the two is valid when exactly one is.
- ``BT`` bridge test (Hsu et al. 2003): two invalid configurations at Gaussian
  distance; keep their midpoint when it is valid.

Every sampler asks its checker about whole batches (the bridge test asks a
``few_calls`` checker about fewer, larger ones). ``sample(n_attempts, rng)`` runs
``n_attempts`` independent attempts (one attempt yields at most one sample) and
returns the ``(M, dof)`` samples, ``M <= n_attempts``. Configurations outside the
robot's bounds count as invalid without asking the checker (the bounds act as
walls). Defaults follow OMPL: ``sigma = 0.1 x`` the diagonal of the bounds (OMPL's
``STD_DEV_AS_SPACE_EXTENT_FRACTION``); OB walks in steps of 1 % of that diagonal
(OMPL's longest valid segment).

A new sampler is a subclass of :class:`Sampler` that overrides one method,
``draw(n, rng)``: ``n`` attempts, returning the ``(M, dof)`` samples they yield. It asks
``self.valid(Q)`` (the bounds, then the checker, about a whole batch in one call) and may use
the local planner's batched helpers; callers use ``sample(n_attempts, rng)``, which checks its
arguments and calls ``draw``. :func:`register_sampler` gives the class a name, and then
``make_sampler(name, checker)`` and ``toolkit.planning.prm.plan(..., sampler=name)`` use it, with the
exact or the learned checker alike (``tutorials/add_a_sampler.ipynb``).
"""

from __future__ import annotations

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.planning.local_planner import last_valid_along, segment_points
from toolkit.util import registry


class Sampler:
    """Base class: holds the checker; ``sample(n_attempts, rng) -> (M, dof)`` valid configurations.

    Subclasses override :meth:`draw` and ask :meth:`valid` about whole batches; ``summary``
    is the line ``toolkit --help`` shows for the sampler (default: the docstring's first line).
    """

    summary = ""

    def __init__(self, checker: CollisionChecker):
        self.checker = checker
        self.robot = checker.robot

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self.robot.name!r})"

    def sample(self, n_attempts: int, rng: np.random.Generator) -> np.ndarray:
        """``(M, dof)`` samples of ``n_attempts`` independent attempts, ``M <= n_attempts``."""
        if int(n_attempts) != n_attempts or n_attempts < 0:
            raise ValueError(f"n_attempts must be a non-negative integer, got {n_attempts!r}")
        return self.draw(int(n_attempts), rng)

    def draw(self, n: int, rng: np.random.Generator) -> np.ndarray:
        """What a subclass overrides: ``(M, dof)`` samples of ``n`` attempts (``n`` already checked)."""
        raise NotImplementedError(f"{type(self).__name__} must override draw(n, rng), the sampler's one method")

    def valid(self, Q: np.ndarray) -> np.ndarray:
        """``(N,)`` validity of ``Q (N, dof)``: outside the bounds is invalid, the checker decides the rest (one
        call for the batch)."""
        ok = self.robot.in_bounds(Q)  # (N,)
        if ok.any():
            ok[ok] = self.checker.are_valid(Q[ok])
        return ok


class NearSampler(Sampler):
    """A sampler that draws Gaussian neighbours (:meth:`near`) with standard deviation ``sigma`` (scalar or
    ``(dof,)``; default: OMPL's, a tenth of the bounds' diagonal)."""

    def __init__(self, checker: CollisionChecker, sigma=None):
        super().__init__(checker)
        diagonal = float(np.linalg.norm(self.robot.upper - self.robot.lower))
        sigma = 0.1 * diagonal if sigma is None else sigma
        self.sigma = np.broadcast_to(np.asarray(sigma, dtype=float), (self.robot.dof,))
        if not np.all(np.isfinite(self.sigma) & (self.sigma > 0)):
            raise ValueError(f"sigma must be positive and finite, got {sigma!r}")

    def near(self, Q: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """``(N, dof)`` Gaussian neighbours of ``Q``, angles wrapped."""
        return self.robot.wrap(Q + rng.standard_normal(Q.shape) * self.sigma)


class UniformSampler(Sampler):
    """BS: uniform samples that the checker accepts."""

    summary = "basic: uniform random configurations the checker accepts (Kavraki et al. 1996)"

    def draw(self, n, rng):
        Q = self.robot.sample(rng, n)  # (n, dof)
        return Q[self.valid(Q)]


class ObstacleBasedSampler(Sampler):
    """OB: per attempt two uniform draws; a (valid, invalid) pair gives the last valid state towards the invalid one.

    The walk takes steps of ``resolution`` (default: 1 % of the bounds' diagonal, OMPL's
    longest valid segment), so a sample lies within one step of the boundary, as in
    OMPL; ``bisections`` halvings of that step bring it closer (samples that hug the
    boundary connect badly around convex corners, hence the default 0).
    """

    summary = "obstacle-based: the last free configuration on a line towards a colliding one (Amato et al. 1998)"

    def __init__(self, checker: CollisionChecker, resolution: float | None = None, bisections: int = 0):
        super().__init__(checker)
        self.resolution = (
            0.01 * float(np.linalg.norm(self.robot.upper - self.robot.lower))
            if resolution is None
            else float(resolution)
        )
        self.bisections = int(bisections)

    def draw(self, n, rng):
        Q = self.robot.sample(rng, 2 * n)  # (2n, dof)
        valid = self.valid(Q)
        pairs = min(n, int(valid.sum()), int((~valid).sum()))
        free, blocked = Q[valid][:pairs], Q[~valid][:pairs]
        return last_valid_along(self.checker, free, blocked, self.resolution, bisections=self.bisections)


class GaussianSampler(NearSampler):
    """G: a uniform ``q1`` and ``q2 ~ N(q1, sigma)``; keep the valid one of a pair with exactly one valid."""

    summary = "Gaussian: of two nearby configurations, the free one when the other collides (Boor et al. 1999)"

    def draw(self, n, rng):
        Q1 = self.robot.sample(rng, n)  # (n, dof)
        Q2 = self.near(Q1, rng)
        valid = self.valid(np.concatenate([Q1, Q2])).reshape(2, n)
        one = valid[0] != valid[1]
        return np.where(valid[0, one, None], Q1[one], Q2[one])


class BridgeTestSampler(NearSampler):
    """BT: an invalid uniform ``q1``, an invalid ``q2 ~ N(q1, sigma)``; keep the midpoint when valid.

    A ``few_calls`` checker is asked about all three of every attempt at once; another
    one about ``q2`` only where ``q1`` is invalid, and then about the midpoints.
    """

    summary = "bridge test: the free midpoint of two colliding configurations, for narrow passages (Hsu et al. 2003)"

    def draw(self, n, rng):
        Q1 = self.robot.sample(rng, n)  # (n, dof)
        Q2 = self.near(Q1, rng)
        if self.checker.few_calls:
            middle = segment_points(self.robot, Q1, Q2, np.full(n, 0.5))
            valid = self.valid(np.concatenate([Q1, Q2, middle])).reshape(3, n)
            return middle[~valid[0] & ~valid[1] & valid[2]]
        blocked = np.flatnonzero(~self.valid(Q1))
        blocked = blocked[~self.valid(Q2[blocked])]  # both ends invalid
        middle = segment_points(self.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
        return middle[self.valid(middle)]


PAPER_SAMPLERS = ("BS", "OB", "G", "BT")  # the paper's four (§III-B), in its tables' order
SAMPLERS: dict[str, type[Sampler]] = {  # the registry: the paper's four, then registered ones in their order
    "BS": UniformSampler,
    "OB": ObstacleBasedSampler,
    "G": GaussianSampler,
    "BT": BridgeTestSampler,
}


def register_sampler(name: str, sampler: type[Sampler], *, replace: bool = False) -> type[Sampler]:
    """Make ``make_sampler(name, ...)``, and so the planner, build ``sampler`` (a subclass of :class:`Sampler`).

    Refuses to rebind a name already taken (the paper's four among them) unless ``replace``;
    returns ``sampler``. Registration lasts for the Python process: register again after a restart.
    """
    if not (isinstance(sampler, type) and issubclass(sampler, Sampler)):
        raise TypeError(f"{sampler!r} is not a subclass of toolkit.planning.sampling.Sampler")
    return registry.bind(SAMPLERS, name, sampler, kind="sampler", replace=replace)


def check_names(names) -> tuple[str, ...]:
    """``names`` as a tuple, every one a registered sampler; otherwise a ``ValueError`` naming the unknown ones."""
    names = tuple(names)
    if unknown := [n for n in names if n not in SAMPLERS]:
        raise ValueError(f"unknown sampler(s) {unknown}; choose from {', '.join(SAMPLERS)}")
    return names


def make_sampler(name: str, checker: CollisionChecker, **options) -> Sampler:
    """The sampler called ``name`` ('BS', 'OB', 'G', 'BT' or a registered one) over ``checker``; ``options`` go to
    its constructor."""
    sampler = registry.lookup(SAMPLERS, name, kind="sampler")
    try:
        return sampler(checker, **options)
    except TypeError as err:
        raise ValueError(f"bad options {sorted(options)} for sampler {name!r}: {err}") from None
