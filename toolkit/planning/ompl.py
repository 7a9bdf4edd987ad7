"""Our checkers and samplers inside OMPL (PyPI ``ompl``): the validity checker is the interface we share.

OMPL (Şucan, Moll, Kavraki 2012) splits a planner from the problem in the way this
toolkit does (``../shared/DESIGN.md``): a ``StateValidityChecker`` answers "is this
state valid?", a ``ValidStateSampler`` proposes valid states. So any of our checkers,
the exact one or the learned one (§III-B), can drive OMPL's planners, and our
samplers (BS, OB, G, BT, §IV-A) can feed OMPL's PRM:

- :func:`state_space`: one 1-D subspace per DoF, an ``SO2StateSpace`` for a base angle
  that wraps and a bounded ``RealVectorStateSpace(1)`` otherwise, weighted by
  ``robot.motion_weights``. OMPL's distance between two states is the weighted sum
  of the subspaces' distances, so here it equals ``robot.motion_bound``: a bound on
  how far any point of the robot moves. :func:`space_information` sets OMPL's
  validity-checking resolution to the fraction ``f = resolution / E`` of the space's
  maximum extent ``E = sum_i w_i e_i`` (``e_i``: DoF i's range). OMPL gives each
  subspace a longest valid segment ``f e_i`` and checks a motion at the most steps
  any one DoF needs, ``max_i ceil(|dq_i| / (f e_i))``; in each step every DoF moves
  at most ``f e_i``, so no robot point moves more than ``sum_i w_i f e_i =
  resolution``: the guarantee of our local planner. OMPL checks at least as many
  points as our planner does (as many when every DoF moves its share of the
  extent; up to ``dof`` times more when one DoF moves alone); :func:`motion_steps` counts
  them.
- :class:`ValidityChecker`: our checker as OMPL's, one configuration a call (OMPL asks
  about one state at a time, so our batched calls cannot help it; each call costs a
  whole checker call's fixed overhead). It keeps the configurations it was asked about
  and the time it spent answering, so a race can tell what OMPL would take with its
  checks at our batched rate (:mod:`toolkit.experiments.versus_ompl`).
- :class:`ToolkitValidStateSampler`: one of our samplers as OMPL's; it draws a batch
  of samples at a time and hands them out one by one.
- :func:`solve`: one query with an OMPL planner (``RRTConnect``, ``PRM``, ``PRMstar``, ...).

``ompl`` is an optional extra: ``pip install 'sample-collision-toolkit[ompl]'``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.planning.local_planner import default_resolution
from toolkit.planning.sampling import make_sampler

INSTALL = "pip install 'sample-collision-toolkit[ompl]'  (or: pip install ompl)"

try:
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou
except ImportError as error:  # an optional extra: say how to get it
    raise ImportError(
        f"toolkit.planning.ompl needs OMPL's Python bindings, which are not installed: {INSTALL}"
    ) from error


def state_space(robot: BoxRobot) -> ob.CompoundStateSpace:
    """OMPL's space for ``robot``: subspace ``i`` holds DoF ``i`` (SO2 where ``robot.wraps``), weight
    ``motion_weights[i]``."""
    space = ob.CompoundStateSpace()
    for i in range(robot.dof):
        if robot.wraps[i]:
            sub = ob.SO2StateSpace()
        else:
            sub = ob.RealVectorStateSpace(1)
            bounds = ob.RealVectorBounds(1)
            bounds.setLow(0, float(robot.lower[i]))
            bounds.setHigh(0, float(robot.upper[i]))
            sub.setBounds(bounds)
        space.addSubspace(sub, float(robot.motion_weights[i]))
    return space


def to_array(state, robot: BoxRobot) -> np.ndarray:
    """``(dof,)`` configuration of an OMPL state of :func:`state_space`."""
    return np.array([state[i].value if robot.wraps[i] else state[i][0] for i in range(robot.dof)])


def set_state(state, q, robot: BoxRobot) -> None:
    """Write configuration ``q (dof,)`` into an OMPL state of :func:`state_space`."""
    for i in range(robot.dof):
        if robot.wraps[i]:
            state[i].value = float(q[i])
        else:
            state[i][0] = float(q[i])


class ValidityChecker(ob.StateValidityChecker):
    """Our ``checker`` (exact or learned) as OMPL's state validity checker: ``isValid(state)`` asks about one state.

    ``asked``: the configurations asked about, in order; ``seconds``: the wall time spent inside ``isValid``
    (OMPL's call into Python, before and after, is not in it).
    """

    def __init__(self, si: ob.SpaceInformation, checker: CollisionChecker):
        super().__init__(si)
        self.checker = checker
        self.asked: list[np.ndarray] = []  # (dof,) each
        self.seconds = 0.0

    def isValid(self, state) -> bool:
        began = time.perf_counter()
        q = to_array(state, self.checker.robot)
        self.asked.append(q)
        valid = self.checker.is_valid(q)
        self.seconds += time.perf_counter() - began
        return valid


class ToolkitValidStateSampler(ob.ValidStateSampler):
    """One of our samplers (``make_sampler(name, checker)``) as OMPL's valid state sampler.

    ``sample`` hands out the next of a batch drawn with ``batch`` attempts (a batch
    may hold none: then it draws another, up to ``nr_attempts`` batches).
    ``sampleNear`` draws uniformly in the box of half-width ``distance`` around
    ``near`` and keeps a valid configuration within ``distance``.
    """

    def __init__(
        self,
        si: ob.SpaceInformation,
        sampler: str,
        checker: CollisionChecker,
        rng: np.random.Generator,
        batch: int = 64,
        **options,
    ):
        super().__init__(si)
        self.robot, self.checker, self.rng, self.batch = checker.robot, checker, rng, batch
        self.sampler = make_sampler(sampler, checker, **options)
        self.queue = np.zeros((0, self.robot.dof))

    def sample(self, state) -> bool:
        for _ in range(max(self.getNrAttempts(), 1)):
            if len(self.queue) == 0:
                self.queue = self.sampler.sample(self.batch, self.rng)
            if len(self.queue):
                set_state(state, self.queue[0], self.robot)
                self.queue = self.queue[1:]
                return True
        return False

    def sampleNear(self, state, near, distance: float) -> bool:
        robot, center = self.robot, to_array(near, self.robot)
        half = distance / np.maximum(robot.motion_weights, 1e-12)  # (dof,) per-axis reach within distance
        Q = robot.wrap(center + self.rng.uniform(-1, 1, (self.batch, robot.dof)) * half)  # (B, dof)
        Q = Q[robot.in_bounds(Q) & (robot.motion_bound(np.broadcast_to(center, Q.shape), Q) <= distance)]
        Q = Q[self.checker.are_valid(Q)] if len(Q) else Q
        if len(Q) == 0:
            return False
        set_state(state, Q[0], robot)
        return True


def space_information(checker: CollisionChecker, resolution: float | None = None) -> ob.SpaceInformation:
    """OMPL's space information (set up) for ``checker``'s robot, validity from ``checker``, motions checked so that no
    robot point moves farther than ``resolution`` (default: our local planner's) between two checks."""
    robot = checker.robot
    resolution = default_resolution(robot) if resolution is None else float(resolution)
    space = state_space(robot)
    si = ob.SpaceInformation(space)
    si.setStateValidityChecker(ValidityChecker(si, checker))
    si.setStateValidityCheckingResolution(resolution / space.getMaximumExtent())
    si.setup()
    return si


def motion_steps(si: ob.SpaceInformation, robot: BoxRobot, Q0, Q1) -> np.ndarray:
    """``(N,)`` states OMPL checks along each motion ``Q0[k] -> Q1[k]`` (``(N, dof)`` each): its valid segment count
    (the end state and the interior ones), to compare with ``local_planner.step_counts`` at the same resolution."""
    Q0, Q1 = robot.check_configs(Q0, "Q0"), robot.check_configs(Q1, "Q1")  # (N, dof)
    if len(Q0) != len(Q1):
        raise ValueError(f"Q0 and Q1 must hold as many configurations, got {len(Q0)} and {len(Q1)}")
    space, a, b = si.getStateSpace(), si.allocState(), si.allocState()
    counts = []
    for q0, q1 in zip(Q0, Q1):
        set_state(a, q0, robot)
        set_state(b, q1, robot)
        counts.append(space.validSegmentCount(a, b))
    return np.array(counts, dtype=int)


@dataclass
class OMPLResult:
    """``success`` (an exact solution), ``path (P, dof)`` (empty on failure), ``seconds``, ``checks``
    (configurations, our sampler's included); ``callback_s``: the seconds of ``seconds`` spent in our validity
    checker's Python calls, ``asked (C, dof)``: the configurations they asked about."""

    success: bool
    path: np.ndarray
    seconds: float
    checks: int
    callback_s: float
    asked: np.ndarray


def solve(
    checker: CollisionChecker,
    start,
    goal,
    *,
    planner: str = "RRTConnect",
    resolution: float | None = None,
    seconds: float = 30.0,
    sampler: str | None = None,
    rng: np.random.Generator | None = None,
) -> OMPLResult:
    """One query ``start -> goal`` with OMPL's ``planner`` (a class of ``ompl.geometric``), ``checker`` deciding
    validity; ``sampler``: one of ours for the planner's valid samples (PRM's), None: OMPL's uniform one.

    OMPL draws from its own generators, seeded from a global one: :func:`quiet` seeds
    it. ``rng`` feeds our ``sampler`` only.
    """
    robot = checker.robot
    if not hasattr(og, planner):
        raise ValueError(f"ompl.geometric has no planner {planner!r}")
    si = space_information(checker, resolution)
    if sampler is not None:
        rng = rng or np.random.default_rng()
        si.setValidStateSamplerAllocator(lambda info: ToolkitValidStateSampler(info, sampler, checker, rng))
    setup = og.SimpleSetup(si)
    ends = []
    for q in (start, goal):
        state = si.allocState()
        set_state(state, robot.check_configs(np.asarray(q, dtype=float), "start/goal").reshape(robot.dof), robot)
        ends.append(state)
    setup.setStartAndGoalStates(*ends)
    setup.setPlanner(getattr(og, planner)(si))
    validity = si.getStateValidityChecker()
    validity.asked, validity.seconds = [], 0.0  # the start and goal states' checks above are not the planner's
    before = checker.n_checked
    began = time.perf_counter()
    setup.solve(float(seconds))
    elapsed = time.perf_counter() - began
    asked = np.array(validity.asked).reshape(-1, robot.dof)  # (checks, dof)
    Q = np.zeros((0, robot.dof))
    if success := setup.haveExactSolutionPath():
        path = setup.getSolutionPath()
        Q = np.array([to_array(path.getState(i), robot) for i in range(path.getStateCount())])
    return OMPLResult(success, Q, elapsed, checker.n_checked - before, validity.seconds, asked)


def quiet(seed: int | None = None) -> None:
    """OMPL logs errors only; ``seed`` (not 0, which OMPL ignores) reseeds the global generator that seeds every new
    planner's and sampler's own: what is made afterwards draws the same numbers on every run."""
    ou.setLogLevel(ou.LOG_ERROR)
    if seed is not None:
        ou.setLogLevel(ou.LOG_NONE)  # after OMPL's first random number it logs an error, yet new generators follow
        ou.RNG.setSeed(int(seed))
        ou.setLogLevel(ou.LOG_ERROR)
