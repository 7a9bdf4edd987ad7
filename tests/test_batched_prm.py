"""The batched PRM (issue 50, item 4): one checker call a round, exactly valid paths, the planner fixed with and
without prediction, and ``--device`` on ``plan`` and ``reproduce``."""

import json

import numpy as np
import pytest
import torch

from toolkit import cli, scenarios
from toolkit.experiments import bench, reproduce
from toolkit.experiments.config import RunConfig
from toolkit.experiments.queries import make_queries, run_interleaved
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.learning.presets import get as preset
from toolkit.planning import prm
from toolkit.planning.batched_prm import PROPOSALS, BatchedPRM
from toolkit.planning.local_planner import last_valid_along, path_is_valid, segment_points
from toolkit.planning.options import BatchedParams
from toolkit.planning.planner import Problem
from toolkit.planning.query_roadmap import QueryRoadmap
from toolkit.planning.sampling import PAPER_SAMPLERS, make_sampler


class Counting(CollisionChecker):
    """An exact checker's answers, the calls counted; ``flip``: a fraction answered wrong (a lying predictor,
    not exact), else it says it is exact."""

    def __init__(self, exact: CollisionChecker, flip: float = 0.0, seed: int = 0):
        super().__init__(exact.robot)
        self.exact, self.flip, self.calls = exact, flip, 0
        self.is_exact = flip == 0
        self._rng = np.random.default_rng(seed)

    def validity(self, Q):
        self.calls += 1
        return self.exact.validity(Q) ^ (self._rng.random(len(Q)) < self.flip)


def workspace_checker(name: str, seed: int = 0):
    scenario = scenarios.get(name)
    query = make_queries(scenario, seed=seed, n_workspaces=1, per_workspace=1)[0]
    return scenario, query, exact_checker(query.workspace, scenario.robot)


def test_batched_is_registered_with_parameters_of_its_own():
    assert prm.get("batched") is BatchedPRM and "batched" in prm.names()
    planner = prm.make("batched")
    assert type(planner.params) is BatchedParams and planner.params.first_samples is None  # rounds of |S|
    assert set(PROPOSALS) == {type(make_sampler(s, exact_checker(*_box_world()))) for s in PAPER_SAMPLERS}
    with pytest.raises(TypeError, match="BatchedPRM reads BatchedParams"):
        BatchedPRM(prm.LazyParams())


def _box_world():
    scenario, query, _ = workspace_checker("2ds")
    return query.workspace, scenario.robot


@pytest.mark.parametrize("sampler", PAPER_SAMPLERS)
def test_a_round_asks_the_checker_once_and_keeps_what_the_sampler_would(sampler):
    """One call a round for each of the paper's samplers; the kept samples are what the sampler's definition keeps,
    checked against the exact checker independently."""
    scenario, _, exact = workspace_checker("3dc7")
    robot = scenario.robot
    counting = Counting(exact)
    S = BatchedPRM().draw(make_sampler(sampler, counting), 300, np.random.default_rng(1))
    assert counting.calls == 1 and len(S) > 0 and exact.are_valid(S).all()
    if sampler == "BS":  # the valid ones of the same uniform draws
        Q = robot.sample(np.random.default_rng(1), 300)
        np.testing.assert_array_equal(S, Q[exact.are_valid(Q)])
    if sampler == "OB":  # walking from the valid end, the last valid point: as the sampler's own walk finds it
        rng = np.random.default_rng(1)
        A, B = robot.sample(rng, 600).reshape(2, 300, robot.dof)
        a, b = exact.are_valid(A), exact.are_valid(B)
        resolution = make_sampler("OB", exact).resolution
        walked = np.concatenate(
            [
                last_valid_along(exact, A[a & ~b], B[a & ~b], resolution),
                last_valid_along(exact, B[b & ~a], A[b & ~a], resolution),
            ]
        )
        assert len(S) == len(walked) == int((a != b).sum())
        distance = np.min(np.linalg.norm(robot.difference(S[:, None], walked[None]), axis=-1), axis=1)
        assert distance.max() < 1e-9
    if sampler in ("G", "BT"):  # the same draws, asked about one set at a time (bounds, then the exact checker)
        own = make_sampler(sampler, exact)
        rng = np.random.default_rng(1)
        Q1 = robot.sample(rng, 300)
        Q2 = own.near(Q1, rng)
        v1, v2 = own.valid(Q1), own.valid(Q2)
        if sampler == "G":  # the valid one of a pair with exactly one valid
            expected = np.array([q1 if ok1 else q2 for q1, q2, ok1, ok2 in zip(Q1, Q2, v1, v2) if ok1 != ok2])
        else:  # the valid midpoint of two invalid ends
            middle = segment_points(robot, Q1, Q2, np.full(300, 0.5))
            expected = middle[~v1 & ~v2 & own.valid(middle)]
        np.testing.assert_array_equal(S, expected)


@pytest.mark.parametrize("sampler", PAPER_SAMPLERS)
def test_2ds_paths_are_exactly_valid_with_and_without_a_lying_predictor(sampler):
    scenario = scenarios.get("2ds")
    queries = make_queries(scenario, seed=0, n_workspaces=2, per_workspace=3)
    solved = 0
    for flip in (0.0, 0.2):
        for q in queries:
            exact = exact_checker(q.workspace, scenario.robot)
            checker = None if flip == 0 else Counting(exact, flip, seed=3)
            result = prm.plan(
                exact,
                q.start,
                q.goal,
                sampler=sampler,
                checker=checker,
                planner="batched",
                rng=np.random.default_rng(0),
            )
            assert result.planner == "batched"
            if result.success:
                solved += 1
                fresh = exact_checker(q.workspace, scenario.robot)
                assert path_is_valid(fresh, result.path, result.stats["resolution"] / 10)
                np.testing.assert_array_equal(result.path[[0, -1]], [q.start, q.goal])
    assert solved >= 0.8 * 2 * len(queries)


def test_3dc7_query_set_solved_with_valid_paths_and_the_planner_fixed_with_and_without():
    """Table 3's two modes in turns (run_interleaved) with the batched PRM named: both modes ran it, every path
    returned is valid under a fresh exact checker."""
    scenario = scenarios.get("3dc7")
    queries = make_queries(scenario, seed=0, n_workspaces=2, per_workspace=1)
    planner = BatchedPRM(n_samples=400)
    lying = lambda ws: Counting(exact_checker(ws, scenario.robot), 0.1, seed=1)
    runs = run_interleaved(scenario, queries, "BS", {"without": None, "with": lying}, planner=planner)
    for mode, (records, summary) in runs.items():
        assert summary["planner"] == "batched" and summary["success_rate"] == 1.0, mode
        assert all(r["path_valid"] for r in records)


def test_reproduce_names_one_planner_for_both_modes_and_passes_the_device():
    """``RunConfig.planner``: Table 3's with and without plan with it alike; ``device`` reaches the learned
    checker; the run's settings name the planner only when one is named (older caches stay valid)."""
    models = bench.untrained_models(scenarios.get("3dc7"), preset("strong"))
    config = RunConfig.create("3dc7", "strong", quick=True, planner="batched", device="cpu")
    modes = reproduce.planning_modes(config, models)
    assert {name: mode.planner.name for name, mode in modes.items()} == {"without": "batched", "with": "batched"}
    assert modes["without"].planner.params == modes["with"].planner.params
    assert modes["with"].checker.keywords["device"] == "cpu" and modes["without"].checker is None
    assert config.settings()["planner"] == "batched" and "planner" not in RunConfig.create("3dc7").settings()
    unnamed = reproduce.planning_modes(RunConfig.create("3dc7", "paper", quick=True), models)
    assert unnamed["with"].planner.name == "paper" and unnamed["without"].planner.name == prm.DEFAULT
    with pytest.raises(ValueError, match="unknown planner 'nope'"):
        RunConfig.create("3dc7", planner="nope")


def test_plan_runs_the_batched_planner_and_cuda_absent_is_one_line(capsys, tmp_path):
    assert cli.main(["plan", "--scenario", "3dc7", "--planner", "batched", "--seed", "1", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["planner"] == "batched" and out["params"]["first_samples"] is None and out["success"]
    _, _, exact = workspace_checker("3dc7", seed=1)
    path = np.array(out["path"])
    assert path_is_valid(exact, path, out["stats"]["resolution"] / 10)
    if torch.cuda.is_available():
        pytest.skip("this machine has a CUDA device")
    for command in (
        ["reproduce", "--scenario", "2ds", "--quick", "--device", "cuda", "--out", str(tmp_path / "r")],
        ["plan", "--scenario", "2ds", "--predict", "--checkpoint", str(tmp_path), "--device", "cuda"],
    ):
        assert cli.main(command) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "no CUDA device" in err, err
    assert not (tmp_path / "r").exists()  # refused before anything was written


def test_a_round_of_the_batched_planner_is_one_call_in_the_planner_too():
    """Through the planner's own round (PRM.sample_round), with prediction: round 1 one call of the predictor."""
    _, query, exact = workspace_checker("3dc7")
    lying = Counting(exact, 0.1)
    problem = Problem.create(exact, query.start, query.goal, sampler="G", checker=lying)
    planner = BatchedPRM(n_samples=500)
    round_ = QueryRoadmap(problem, planner.params)
    round_.stats["rounds"] = 1
    kept, verified = planner.sample_round(round_, np.random.default_rng(0))
    assert lying.calls == 1 and not verified and len(kept) > 0
