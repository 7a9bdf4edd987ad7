"""RRT-Connect (toolkit.planning.rrt_connect): valid paths on every scenario, the same path for the same seed, the
verification's cut of a failed branch. Against an independent reference (2DS solvability by flood fill, and OMPL's
RRTConnect): tests/test_ompl.py."""

import json

import numpy as np
import pytest

from toolkit import scenarios
from toolkit.experiments.problems import scenario_resolution
from toolkit.experiments.queries import make_queries
from toolkit.geometry.collision import exact_checker
from toolkit.planning import prm
from toolkit.planning import rrt_connect as rrt
from toolkit.planning.local_planner import path_is_valid
from toolkit.planning.planner import REFINEMENT, Problem


def solve(scenario, workspace, start, goal, seed, params=None):
    """RRT-Connect from ``start`` to ``goal`` in ``workspace`` at the scenario's resolution, ``default_rng(seed)``."""
    problem = Problem.create(exact_checker(workspace, scenario.robot), start, goal, resolution=scenario.plan_resolution)
    return rrt.rrt_connect(problem, np.random.default_rng(seed), params)


@pytest.mark.parametrize("name", ["2ds", "3do", "3dc7", "3dc9"])
def test_paths_are_valid_at_the_resolution_and_ten_times_finer(name):
    scenario = scenarios.get(name)
    robot = scenario.robot
    resolution = scenario_resolution(scenario)
    params = rrt.RRTConnectParams()
    for i, q in enumerate(make_queries(scenario, seed=7300, n_workspaces=3, per_workspace=1)):
        result = solve(scenario, q.workspace, q.start, q.goal, i, params)
        assert result.success and result.planner == "rrt-connect", f"{name} query {i}: {result.stats}"
        np.testing.assert_array_equal(result.path[0], q.start)
        np.testing.assert_array_equal(result.path[-1], q.goal)
        fresh = exact_checker(q.workspace, robot)
        assert path_is_valid(fresh, result.path, resolution)
        assert path_is_valid(fresh, result.path, resolution / REFINEMENT)
        steps = robot.motion_bound(result.path[:-1], result.path[1:])  # (P-1,) no edge longer than an extension
        assert steps.max() <= resolution * params.range * (1 + 1e-9)
        assert result.stats["exact_checks"] > 0 and result.stats["nodes"] >= 2


def test_the_same_seed_gives_the_same_path_and_another_seed_another():
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=7300, n_workspaces=1, per_workspace=1)[0]
    first, again, other = (solve(scenario, q.workspace, q.start, q.goal, seed) for seed in (5, 5, 6))
    np.testing.assert_array_equal(first.path, again.path)
    assert first.stats["exact_checks"] == again.stats["exact_checks"]
    assert first.path.shape != other.path.shape or not np.array_equal(first.path, other.path)


def test_rrt_connect_is_offered_by_name_and_plans_from_the_command_line(capsys):
    from toolkit import cli

    assert prm.get("rrt-connect") is rrt.RRTConnect and "rrt-connect" in prm.names()
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=3, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    by_name = prm.plan(exact, q.start, q.goal, planner="rrt-connect", rng=np.random.default_rng(1))
    direct = solve(scenario, q.workspace, q.start, q.goal, 1)
    np.testing.assert_array_equal(by_name.path, direct.path)
    assert (
        cli.main(["plan", "--scenario", "3dc7", "--sampler", "BS", "--planner", "rrt-connect", "--seed", "3", "--json"])
        == 0
    )
    out = json.loads(capsys.readouterr().out)
    assert out["planner"] == "rrt-connect" and out["success"] and out["params"]["range"] == 64.0
    assert path_is_valid(exact, np.array(out["path"]), scenario_resolution(scenario))


def test_a_branch_that_fails_verification_is_cut_and_the_search_goes_on(monkeypatch):
    """The first candidate path is made to fail its verification on one edge: that edge's far end and everything
    beyond it leave their tree, and the path finally returned avoids them and is valid."""
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=7300, n_workspaces=1, per_workspace=1)[0]
    real, rejected = rrt.certify_edges, []

    def fail_first_edge_once(checker, Q0, Q1, resolution, *, spacing):
        ok = real(checker, Q0, Q1, resolution, spacing=spacing)
        if not rejected:
            rejected.append(Q1[0].copy())  # the first edge, start -> its child: fails
            ok[0] = False
        return ok

    monkeypatch.setattr(rrt, "certify_edges", fail_first_edge_once)
    result = solve(scenario, q.workspace, q.start, q.goal, 0)
    assert result.success and result.stats["cuts"] == 1
    assert not any(np.array_equal(node, rejected[0]) for node in result.path)
    nodes, edges = result.roadmap.nodes, result.roadmap.edges
    assert len(edges) < len(nodes) - 2  # a cut branch's nodes keep no edge: fewer than a tree's (two roots)
    assert np.array_equal(nodes[0], q.start) and result.roadmap.node_verified.all()
    assert path_is_valid(exact_checker(q.workspace, scenario.robot), result.path, 0.005)


def test_cutting_a_node_cuts_its_branch_only():
    tree = rrt.Tree(np.zeros(2))
    for parent in (0, 0, 1, 3, 2):  # nodes 1..5: 1 and 2 under the root, 3 under 1, 4 under 3, 5 under 2
        tree.add(np.ones(2), parent)
    tree.cut_below(1)
    np.testing.assert_array_equal(tree.cut[: tree.n], [False, True, False, True, True, False])
    assert tree.branch(4) == [4, 3, 1, 0]
    for _ in range(300):  # past the first capacity: the arrays grow and keep what they held
        tree.add(np.full(2, 2.0), 5)
    assert tree.n == 306 and tree.parent[305] == 5 and tree.cut[4] and not tree.cut[305]


def test_an_unsolvable_query_fails_after_its_iterations_and_bad_input_is_named(checkpoint_2ds):
    from toolkit.geometry.workspace import Workspace
    from toolkit.learning.learned import load_checker

    scenario = scenarios.get("2ds")
    walls = [[[18, 18], [28, 19]], [[18, 27], [28, 28]], [[18, 18], [19, 28]], [[27, 18], [28, 28]]]
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array(walls, dtype=float), family="2ds")
    result = solve(scenario, ws, [5.0, 5.0], [23.0, 23.0], 0, rrt.RRTConnectParams(max_iterations=200))
    assert not result.success and result.path.shape == (0, 2) and result.stats["iterations"] == 200
    with pytest.raises(ValueError, match=r"goal configuration \[18.5, 20.0\] is in collision"):
        solve(scenario, ws, [5.0, 5.0], [18.5, 20.0], 0)
    predicting = Problem.create(
        exact_checker(ws, scenario.robot), [5.0, 5.0], [9.0, 9.0], checker=load_checker(checkpoint_2ds, ws)
    )
    with pytest.raises(ValueError, match="RRT-Connect plans without prediction"):
        rrt.rrt_connect(predicting, np.random.default_rng(0))
    with pytest.raises(ValueError, match=r"RRTConnectParams\.range must be positive and finite, got 0"):
        rrt.RRTConnectParams(range=0)
    with pytest.raises(ValueError, match=r"RRTConnectParams\.coarse must be a positive integer, got 1\.5"):
        rrt.RRTConnectParams(coarse=1.5)
    with pytest.raises(ValueError, match=r"^RRTConnectParams\.range must be positive and finite, got 'far'$"):
        rrt.RRTConnectParams(range="far")  # as `--option range=far` gives it: a TypeError inside, one line out
