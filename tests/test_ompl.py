"""Cross-check against OMPL (PyPI ``ompl``): on the same 2DS problems with the same exact checker, OMPL's PRM
and ours solve every solvable query, and neither "solves" an unsolvable one.

Solvability is decided exactly: the point robot's configuration-space obstacles are the blocks grown by its
half extent, with sides on multiples of 0.25, so a grid of 0.25 cells lies either inside or outside them and a
4-connected flood fill of the free cells gives the connected components of free space.
"""

import numpy as np
import pytest
from scipy import ndimage

from toolkit import scenarios
from toolkit.collision import exact_checker
from toolkit.local_planner import path_is_valid
from toolkit.prm import PRMOptions, plan
from toolkit.queries import make_queries
from toolkit.workspace import Workspace

ob = pytest.importorskip("ompl.base")
og = pytest.importorskip("ompl.geometric")
ou = pytest.importorskip("ompl.util")

CELL = 0.25
ou.RNG.setSeed(1)  # OMPL's global seed, before any planner exists: same samples on every run
ou.setLogLevel(ou.LOG_ERROR)


def free_components(ws, robot):
    """Component label of every 0.25 cell of the robot's bounds (0 = blocked), and the cell lookup."""
    lo, hi = robot.lower, robot.upper
    n = np.round((hi - lo) / CELL).astype(int)  # (2,)
    centres = lo + CELL * (np.stack(np.meshgrid(*map(np.arange, n), indexing="ij"), axis=-1) + 0.5)  # (nx, ny, 2)
    free = exact_checker(ws, robot).are_valid(centres.reshape(-1, 2)).reshape(n)
    labels, _ = ndimage.label(free)  # 4-connectivity

    def label_of(q):
        return labels[tuple(np.minimum(((q - lo) // CELL).astype(int), n - 1))]

    return label_of


def ompl_solves(ws, robot, start, goal, resolution, seconds=10.0):
    """OMPL's PRM with our exact checker; the solution path ``(P, 2)``, or None if none within ``seconds``.

    PRM stops at its first solution, so a solvable query rarely takes more than a fraction of a second.
    """
    checker = exact_checker(ws, robot)
    space = ob.RealVectorStateSpace(2)
    bounds = ob.RealVectorBounds(2)
    for i in range(2):
        bounds.setLow(i, float(robot.lower[i]))
        bounds.setHigh(i, float(robot.upper[i]))
    space.setBounds(bounds)
    setup = og.SimpleSetup(space)
    setup.setStateValidityChecker(lambda s: checker.is_valid(np.array([s[0], s[1]])))
    states = []
    for q in (start, goal):
        state = space.allocState()
        state[0], state[1] = float(q[0]), float(q[1])
        states.append(state)
    setup.setStartAndGoalStates(*states)
    info = setup.getSpaceInformation()
    info.setStateValidityCheckingResolution(resolution / space.getMaximumExtent())
    setup.setPlanner(og.PRM(info))
    setup.solve(seconds)
    if not setup.haveExactSolutionPath():
        return None
    path = setup.getSolutionPath()
    return np.array([[path.getState(i)[0], path.getState(i)[1]] for i in range(path.getStateCount())])


@pytest.mark.slow
def test_ours_and_ompls_prm_solve_every_solvable_2ds_query():
    scenario = scenarios.get("2ds")
    robot = scenario.robot
    queries = make_queries(scenario, seed=0, n_workspaces=3, per_workspace=6)
    solvable_count = 0
    for i, q in enumerate(queries):
        label_of = free_components(q.workspace, robot)
        solvable = label_of(q.start) == label_of(q.goal) != 0
        exact = exact_checker(q.workspace, robot)
        ours = plan(exact, q.start, q.goal, sampler="BS", options=PRMOptions(n_samples=200, max_rounds=40),
                    rng=np.random.default_rng(i))
        resolution = ours.stats["resolution"] / 10
        assert ours.success == solvable, f"query {i}: ours {ours.success}, solvable {solvable}"
        if not solvable:
            continue
        solvable_count += 1
        theirs = ompl_solves(q.workspace, robot, q.start, q.goal, resolution)
        assert theirs is not None, f"OMPL's PRM missed solvable query {i}"
        assert path_is_valid(exact, theirs, resolution)  # the same checker accepts OMPL's path
        assert path_is_valid(exact, ours.path, resolution)
    assert solvable_count >= len(queries) // 2


def test_flood_fill_decides_solvability_exactly():
    scenario = scenarios.get("2ds")
    robot = scenario.robot
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    label_of = free_components(q.workspace, robot)
    lo, hi = q.workspace.boxes[0]
    assert label_of((lo + hi) / 2) == 0  # inside a block
    assert label_of(q.start) != 0 and label_of(q.goal) != 0


def test_an_enclosed_goal_is_unsolvable_for_both():
    robot = scenarios.get("2ds").robot
    walls = [[[18, 18], [28, 19]], [[18, 27], [28, 28]], [[18, 18], [19, 28]], [[27, 18], [28, 28]]]
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array(walls, dtype=float), family="2ds")
    start, goal = np.array([5.0, 5.0]), np.array([23.0, 23.0])
    label_of = free_components(ws, robot)
    assert label_of(start) != label_of(goal)
    ours = plan(exact_checker(ws, robot), start, goal, options=PRMOptions(max_rounds=5), rng=np.random.default_rng(0))
    assert not ours.success and len(ours.path) == 0 and ours.stats["rounds"] == 5
    assert ompl_solves(ws, robot, start, goal, ours.stats["resolution"] / 10, seconds=0.3) is None
