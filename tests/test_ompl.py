"""Cross-check against OMPL (PyPI ``ompl``): on the same 2DS problems with the same exact checker, OMPL's PRM
and ours, and OMPL's RRTConnect and ours, solve every solvable query, and neither "solves" an unsolvable one.

Solvability is decided exactly: the point robot's configuration-space obstacles are the blocks grown by its
half extent, with sides on multiples of 0.25, so a grid of 0.25 cells lies either inside or outside them and a
4-connected flood fill of the free cells gives the connected components of free space.
"""

import numpy as np
import pytest
from scipy import ndimage

from toolkit import scenarios
from toolkit.experiments.problems import scenario_resolution
from toolkit.experiments.queries import make_queries
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.paper_prm import PRM
from toolkit.planning.planner import REFINEMENT, Problem
from toolkit.planning.prm import plan
from toolkit.planning.rrt_connect import RRTConnectParams, rrt_connect

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


def ompl_solves(ws, robot, start, goal, resolution, seconds=120.0):
    """OMPL's PRM with our exact checker; the solution path ``(P, 2)``, or None if none within ``seconds``.

    PRM stops at its first solution, so a solvable query rarely takes more than a fraction of a
    second: ``seconds`` is a budget, not a speed test (on a loaded machine 10 s were once too few).
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
        ours = plan(
            exact,
            q.start,
            q.goal,
            sampler="BS",
            planner=PRM(n_samples=200, max_rounds=40),
            rng=np.random.default_rng(i),
        )
        resolution = ours.stats["resolution"] / REFINEMENT
        assert ours.success == solvable, f"query {i}: ours {ours.success}, solvable {solvable}"
        if not solvable:
            continue
        solvable_count += 1
        theirs = ompl_solves(q.workspace, robot, q.start, q.goal, resolution)
        assert theirs is not None, f"OMPL's PRM missed solvable query {i}"
        assert path_is_valid(exact, theirs, resolution)  # the same checker accepts OMPL's path
        assert path_is_valid(exact, ours.path, resolution)
    assert solvable_count >= len(queries) // 2


def test_ours_and_ompls_rrtconnect_solve_every_solvable_2ds_query():
    scenario = scenarios.get("2ds")
    robot = scenario.robot
    params = RRTConnectParams(max_iterations=2_000)
    solvable_count = 0
    for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=3, per_workspace=6)):
        label_of = free_components(q.workspace, robot)
        solvable = label_of(q.start) == label_of(q.goal) != 0
        problem = Problem.create(exact_checker(q.workspace, robot), q.start, q.goal)
        ours = rrt_connect(problem, np.random.default_rng(i), params)
        assert ours.success == solvable, f"query {i}: ours {ours.success}, solvable {solvable}"
        if not solvable:
            continue
        solvable_count += 1
        resolution = ours.stats["resolution"]
        assert path_is_valid(exact_checker(q.workspace, robot), ours.path, resolution / REFINEMENT)
        theirs = toolkit_ompl.solve(
            exact_checker(q.workspace, robot), q.start, q.goal, planner="RRTConnect", resolution=resolution, seconds=20
        )
        assert theirs.success, f"OMPL's RRTConnect missed solvable query {i}"
    assert solvable_count >= 9


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
    ours = plan(exact_checker(ws, robot), start, goal, planner=PRM(max_rounds=5), rng=np.random.default_rng(0))
    assert not ours.success and len(ours.path) == 0 and ours.stats["rounds"] == 5
    assert ompl_solves(ws, robot, start, goal, ours.stats["resolution"] / REFINEMENT, seconds=0.3) is None


# -- toolkit.planning.ompl: our checkers and samplers inside OMPL -----------------------------------------------------

toolkit_ompl = pytest.importorskip("toolkit.planning.ompl")


def test_ompls_distance_is_our_motion_bound_and_its_motion_checks_at_least_our_steps():
    from toolkit.planning.local_planner import step_counts

    scenario = scenarios.get("3do")  # a base angle that wraps, and joints
    robot = scenario.robot
    q = make_queries(scenario, seed=7100, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, robot)
    resolution = scenario.plan_resolution
    si = toolkit_ompl.space_information(exact, resolution)
    rng = np.random.default_rng(0)
    Q0, Q1 = robot.sample(rng, 20), robot.sample(rng, 20)
    Q1[:, 2] = np.where(rng.random(20) < 0.5, Q0[:, 2] + 3.0, Q1[:, 2])  # some turns the short way across +-pi
    Q1 = robot.wrap(Q1)
    a, b = si.allocState(), si.allocState()
    free = exact_checker(q.workspace, robot)
    free.validity = lambda Q: np.ones(len(Q), dtype=bool)  # every state valid: OMPL checks the whole motion
    si_free = toolkit_ompl.space_information(free, resolution)
    ompl_steps = toolkit_ompl.motion_steps(si, robot, Q0, Q1)  # (20,)
    for q0, q1, steps, counted in zip(Q0, Q1, step_counts(robot, Q0, Q1, resolution), ompl_steps):
        toolkit_ompl.set_state(a, q0, robot)
        toolkit_ompl.set_state(b, q1, robot)
        np.testing.assert_allclose(toolkit_ompl.to_array(a, robot), q0)
        assert si.distance(a, b) == pytest.approx(float(robot.motion_bound(q0, q1)))
        before = free.n_checked
        assert si_free.checkMotion(a, b)
        checked = free.n_checked - before  # the end state and the interior ones
        assert checked == counted  # motion_steps counts what checkMotion checks
        assert checked >= steps  # at least our local planner's steps: no robot point moves farther between checks
        assert robot.motion_bound(q0, q1) / checked <= resolution
        assert checked <= steps * robot.dof  # OMPL takes the most steps any one DoF needs
    assert (ompl_steps > step_counts(robot, Q0, Q1, resolution)).any()  # not all equal: OMPL counts per DoF
    with pytest.raises(ValueError, match="as many"):
        toolkit_ompl.motion_steps(si, robot, Q0, Q1[:3])


def test_rrtconnect_with_our_exact_checker_returns_paths_our_checker_accepts():
    scenario = scenarios.get("3dc7")
    resolution = scenario_resolution(scenario)
    for q in make_queries(scenario, seed=7100, n_workspaces=2, per_workspace=1):
        exact = exact_checker(q.workspace, scenario.robot)
        result = toolkit_ompl.solve(exact, q.start, q.goal, planner="RRTConnect", resolution=resolution, seconds=20)
        assert result.success and result.checks > 0
        assert result.asked.shape == (result.checks, scenario.robot.dof)  # every check was one callback
        assert 0 < result.callback_s < result.seconds
        assert len(np.unique(result.asked, axis=0)) > len(result.path)  # states along motions, not the path only
        np.testing.assert_allclose(result.path[0], q.start)
        np.testing.assert_allclose(result.path[-1], q.goal)
        assert path_is_valid(exact_checker(q.workspace, scenario.robot), result.path, resolution)


def test_a_learned_checker_answers_inside_ompl_as_outside(checkpoint_2ds):
    from toolkit.learning.learned import load_checker

    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=7100, n_workspaces=1, per_workspace=1)[0]
    learned = load_checker(checkpoint_2ds, q.workspace)
    si = toolkit_ompl.space_information(learned)
    state = si.allocState()
    Q = scenario.robot.sample(np.random.default_rng(1), 50)
    inside = []
    for config in Q:
        toolkit_ompl.set_state(state, config, scenario.robot)
        inside.append(si.isValid(state))
    np.testing.assert_array_equal(inside, learned.are_valid(Q))


def test_our_samplers_feed_ompls_prm():
    scenario = scenarios.get("2ds")
    robot = scenario.robot
    q = make_queries(scenario, seed=7100, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, robot)
    si = toolkit_ompl.space_information(exact)
    sampler = toolkit_ompl.ToolkitValidStateSampler(si, "OB", exact, np.random.default_rng(0))
    state, near = si.allocState(), si.allocState()
    drawn = []
    for _ in range(100):
        assert sampler.sample(state)
        drawn.append(toolkit_ompl.to_array(state, robot))
    assert exact.are_valid(np.array(drawn)).all() and len(np.unique(drawn, axis=0)) == 100
    toolkit_ompl.set_state(near, q.start, robot)
    for _ in range(20):
        if sampler.sampleNear(state, near, 2.0):
            assert robot.motion_bound(q.start, toolkit_ompl.to_array(state, robot)) <= 2.0
            assert exact.is_valid(toolkit_ompl.to_array(state, robot))
    result = toolkit_ompl.solve(
        exact, q.start, q.goal, planner="PRM", sampler="OB", rng=np.random.default_rng(0), seconds=10
    )
    assert result.success and path_is_valid(exact, result.path, robot.half_extents.min())


def test_quiet_reseeds_ompl_so_a_planner_made_afterwards_repeats_itself():
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=9000, n_workspaces=1, per_workspace=1)[0]
    runs = []
    for _ in range(2):
        toolkit_ompl.quiet(5)  # the second time after OMPL has drawn random numbers: still takes effect
        runs.append(toolkit_ompl.solve(exact_checker(q.workspace, scenario.robot), q.start, q.goal, seconds=10))
    assert runs[0].success and runs[0].checks == runs[1].checks
    np.testing.assert_array_equal(runs[0].path, runs[1].path)
