"""PRM and Algorithm 1: every returned path exactly valid (also with a lying checker), roadmap, queries, CLI."""

import dataclasses
import json

import numpy as np
import pytest
import torch
from threadpoolctl import threadpool_info, threadpool_limits

from toolkit import cli, scenarios
from toolkit.experiments import queries as queries_module
from toolkit.experiments.queries import make_queries, run_queries
from toolkit.geometry.collision import CollisionChecker, FCLChecker, exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.planning import local_planner, prm, query_roadmap
from toolkit.planning.lazy_prm import LazyPRM
from toolkit.planning.local_planner import (
    certify_edges,
    check_edges,
    invalid_fractions,
    path_at,
    path_is_valid,
    path_points,
    refute_at,
    segment_points,
)
from toolkit.planning.options import LazyParams, PaperParams
from toolkit.planning.paper_prm import PRM
from toolkit.planning.planner import Problem
from toolkit.planning.prm import plan
from toolkit.planning.query_roadmap import QueryRoadmap
from toolkit.planning.roadmap import Roadmap
from toolkit.planning.sampling import SAMPLERS, make_sampler


class NoisyChecker(CollisionChecker):
    """Test double for a learned checker: the exact answer, flipped for a fixed fraction of configurations."""

    def __init__(self, exact: CollisionChecker, flip: float, seed: int):
        super().__init__(exact.robot)
        self.exact, self.flip, self._rng = exact, flip, np.random.default_rng(seed)

    def validity(self, Q):
        return self.exact.validity(Q) ^ (self._rng.random(len(Q)) < self.flip)


def overlap_in_box(p0, p1, lo, hi) -> float:
    """Exact continuous test (Liang-Barsky slabs): the fraction of segment p0 -> p1 inside the closed box [lo, hi]."""
    t0, t1 = 0.0, 1.0
    for a, b, l, h in zip(p0, p1, lo, hi):
        d = b - a
        if d == 0:
            if a < l or a > h:
                return 0.0
            continue
        ta, tb = sorted(((l - a) / d, (h - a) / d))
        t0, t1 = max(t0, ta), min(t1, tb)
    return max(t1 - t0, 0.0)


def longest_hidden_overlap(ws, robot, path) -> float:
    """The 2D point robot's path against its configuration-space obstacles, continuously: the largest robot
    motion spent inside an obstacle along one segment (0 for a collision-free path)."""
    half = robot.half_extents[0]
    return max(
        overlap_in_box(p0, p1, lo - half, hi + half) * float(robot.motion_bound(p0, p1))
        for p0, p1 in zip(path[:-1], path[1:])
        for lo, hi in ws.boxes
    )


MODES = {  # name -> (flip fraction of the test double or None for exact, the planner's class)
    "exact": (None, LazyPRM),  # the best exact planner: lazy edges, growing rounds
    "exact-paper": (None, PRM),  # Algorithm 1 as the paper has it
    "noisy-screened": (0.15, LazyPRM),
    "noisy-paper": (0.15, PRM),
}


def solve_all(scenario, queries, sampler, mode, n_samples=None):
    flip, planner_class = MODES[mode]
    results = []
    for i, q in enumerate(queries):
        exact = exact_checker(q.workspace, scenario.robot)
        checker = None if flip is None else NoisyChecker(exact, flip, seed=i)
        planner = planner_class(n_samples=n_samples or scenario.plan_samples)
        results.append(
            (
                q,
                plan(
                    exact,
                    q.start,
                    q.goal,
                    sampler=sampler,
                    checker=checker,
                    planner=planner,
                    rng=np.random.default_rng(i),
                ),
            )
        )
    return results


def assert_paths_valid(scenario, results, continuous=False):
    for q, result in results:
        if not result.success:
            assert len(result.path) == 0
            continue
        path = result.path
        np.testing.assert_array_equal(path[0], q.start)
        np.testing.assert_array_equal(path[-1], q.goal)
        fresh = exact_checker(q.workspace, scenario.robot)
        fine = result.stats["resolution"] / 10  # the planner's verification resolution
        assert path_is_valid(fresh, path, fine)
        if continuous:  # checks every `fine` of motion: a collision it misses is shorter than one step
            assert longest_hidden_overlap(q.workspace, scenario.robot, path) < fine


@pytest.mark.parametrize("mode", sorted(MODES))
@pytest.mark.parametrize("sampler", sorted(SAMPLERS))
def test_2ds_paths_are_exactly_valid(sampler, mode):
    scenario = scenarios.get("2ds")
    queries = make_queries(scenario, seed=0, n_workspaces=2, per_workspace=5)
    results = solve_all(scenario, queries, sampler, mode)
    assert_paths_valid(scenario, results, continuous=True)
    assert np.mean([r.success for _, r in results]) >= 0.8
    if mode == "noisy-screened":  # the lying checker let invalid samples or edges in: verification removed them
        assert sum(r.stats["repairs"] for _, r in results) > 0


@pytest.mark.slow
@pytest.mark.parametrize("scenario_name", ["3dc7", "3dc9"])
@pytest.mark.parametrize("mode", sorted(MODES))
def test_3dc_paths_are_exactly_valid(scenario_name, mode):
    scenario = scenarios.get(scenario_name)
    queries = make_queries(scenario, seed=0, n_workspaces=2)
    for sampler in ("BS", "BT"):
        results = solve_all(scenario, queries, sampler, mode, n_samples=200)
        assert_paths_valid(scenario, results)
        assert all(r.success for _, r in results)


@pytest.mark.parametrize("planner_class, first_round", [(PRM, 200), (LazyPRM, 50)])
def test_exact_planners_never_repair_nodes_and_count_checks(planner_class, first_round):
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=1, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    result = plan(exact, q.start, q.goal, sampler="BS", planner=planner_class(), rng=np.random.default_rng(0))
    s = result.stats
    assert result.success and s["removed_nodes"] == 0 and s["predicted_checks"] == 0 and s["rounds"] == 1
    assert s["exact_checks"] == exact.n_checked
    assert s["node_checks"] == first_round  # plus 2: the start and goal
    assert s["exact_checks"] == 2 + s["node_checks"] + s["edge_checks"] + s["verify_checks"]
    assert s["total_s"] >= s["sampling_s"] + s["connection_s"] + s["query_s"]
    assert s["nodes"] == len(result.roadmap.nodes) and result.roadmap.edges.shape == (s["edges"], 2)


def test_rounds_double_from_first_samples_up_to_n_samples():
    robot = scenarios.get("2ds").robot  # the goal walled in: every round is sampled, none solves it
    walls = [[[18, 18], [28, 19]], [[18, 27], [28, 28]], [[18, 18], [19, 28]], [[27, 18], [28, 28]]]
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array(walls, dtype=float), family="2ds")
    for planner, attempts in [
        (LazyPRM(max_rounds=5, first_samples=10, n_samples=50), 10 + 20 + 40 + 50 + 50),
        (LazyPRM(max_rounds=5, first_samples=None, n_samples=50), 5 * 50),
        (PRM(max_rounds=5, n_samples=50), 5 * 50),
    ]:  # the paper's: |S| a round
        trace = []
        result = plan(
            exact_checker(ws, robot),
            np.array([5.0, 5.0]),
            np.array([23.0, 23.0]),
            sampler="BS",
            planner=planner,
            rng=np.random.default_rng(0),
            trace=trace,
        )
        assert not result.success and result.stats["rounds"] == 5
        assert result.stats["node_checks"] == attempts  # BS checks each attempt once
        assert [step.round for step in trace if step.stage == "sample"] == [1, 2, 3, 4, 5]


@pytest.mark.slow
@pytest.mark.parametrize("name", ["3dc7", "3do"])
def test_lazy_exact_solves_what_the_paper_baseline_solves_with_far_fewer_checks(name):
    scenario = scenarios.get(name)
    queries = make_queries(scenario, seed=7100, n_workspaces=3, per_workspace=1)
    results = {mode: solve_all(scenario, queries, "BS", mode) for mode in ("exact", "exact-paper")}
    for mode in results:
        assert_paths_valid(scenario, results[mode])  # at 10x finer resolution than the roadmap's
        assert all(r.success for _, r in results[mode])
    lazy, paper = (
        [r.stats["exact_checks"] + r.stats["exact_clearances"] for _, r in results[mode]]
        for mode in ("exact", "exact-paper")
    )
    assert np.median(lazy) * 10 < np.median(paper)


def test_lazy_screen_rejects_only_edges_with_a_point_in_collision(monkeypatch):
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=7100, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    options = LazyParams(n_samples=100, first_samples=None, max_rounds=1, rebridge=0)
    query = QueryRoadmap(Problem.create(exact, q.start, q.goal), options)
    nodes = query.roadmap.add_nodes(make_sampler("BS", exact).sample(100, np.random.default_rng(0)), verified=True)
    pairs = query.roadmap.candidate_edges(nodes, options.k)
    LazyPRM(options).decide(query, pairs)
    roadmap = query.roadmap
    assert len(roadmap.edges) + len(roadmap.rejected) == len(pairs) and len(roadmap.rejected) > 0
    assert np.isinf(roadmap.edge_checked_at).all()  # lazy: none confirmed yet
    spacing = query.resolution * options.lazy_screen
    assert (invalid_fractions(exact, *roadmap.nodes[roadmap.rejected.T], spacing)[0] > 0).all()
    assert (invalid_fractions(exact, *roadmap.nodes[roadmap.edges.T], spacing)[0] == 0).all()
    np.testing.assert_allclose(roadmap.edge_cost, roadmap.distance(*roadmap.nodes[roadmap.edges.T]))


@pytest.mark.parametrize("flip", [None, 0.15])
def test_the_papers_planner_checks_every_edge_exactly_as_it_is_added(flip):
    scenario = scenarios.get("2ds")
    for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=2, per_workspace=2)):
        exact, trace = exact_checker(q.workspace, scenario.robot), []
        checker = None if flip is None else NoisyChecker(exact, flip, seed=i)
        result = plan(
            exact,
            q.start,
            q.goal,
            sampler="BS",
            checker=checker,
            planner=PRM(),
            rng=np.random.default_rng(i),
            trace=trace,
        )
        assert result.success
        roadmap, coarse = result.roadmap, result.stats["resolution"]
        assert result.planner == "paper"
        on_path = np.zeros(len(roadmap.edges), bool)
        on_path[roadmap.edge_index(roadmap.shortest_path(prm.START, prm.GOAL))] = True
        np.testing.assert_array_equal(roadmap.edge_checked_at[~on_path], coarse)  # checked as added
        np.testing.assert_array_equal(roadmap.edge_checked_at[on_path], coarse / 10)  # the path: also 10x finer
        assert check_edges(exact, *roadmap.nodes[roadmap.edges.T], coarse).all()
        assert not check_edges(exact, *roadmap.nodes[roadmap.rejected.T], coarse).any()
        if flip is None:  # rounds of |S| attempts each (BS checks each attempt once)
            assert result.stats["node_checks"] == result.stats["rounds"] * PaperParams().n_samples


def test_the_planner_is_chosen_by_name_and_owns_its_parameters():
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    problem = Problem.create(exact, q.start, q.goal, sampler="G")
    runs = {}
    for name, planner in [("paper", PRM), ("lazy", LazyPRM)]:
        by_plan = plan(exact, q.start, q.goal, sampler="G", planner=name, rng=np.random.default_rng(3))
        by_class = planner().solve(problem, np.random.default_rng(3))
        np.testing.assert_array_equal(by_plan.path, by_class.path)
        np.testing.assert_array_equal(by_plan.roadmap.edges, by_class.roadmap.edges)
        assert by_plan.planner == by_class.planner == name
        runs[name] = by_plan
    paper, lazy = runs["paper"], runs["lazy"]
    assert paper.success and lazy.success
    assert np.isfinite(paper.roadmap.edge_checked_at).all()  # every edge checked exactly ...
    assert np.isinf(lazy.roadmap.edge_checked_at).any()  # ... against edges never confirmed
    assert paper.stats["exact_checks"] > 5 * lazy.stats["exact_checks"]
    assert not issubclass(LazyParams, PaperParams) and not issubclass(PaperParams, LazyParams)
    with pytest.raises(TypeError, match=r"LazyPRM reads LazyParams, got PaperParams"):
        LazyPRM(PaperParams())
    with pytest.raises(TypeError, match=r"PRM reads PaperParams, got LazyParams"):  # its fields are another's
        PRM(LazyParams())
    assert type(PRM().params) is PaperParams and type(LazyPRM().params) is LazyParams
    assert PRM(k=15).params == PaperParams(k=15) and PaperParams().auxiliary == "exact"
    with pytest.raises(ValueError, match=r"unknown planner option\(s\) \['screen_edges'\]; PaperParams has"):
        PRM(screen_edges=False)
    with pytest.raises(dataclasses.FrozenInstanceError):
        PaperParams().k = 3
    default = plan(exact, q.start, q.goal, sampler="G", rng=np.random.default_rng(3))  # none named: prm.DEFAULT
    assert prm.DEFAULT == "lazy" and default.planner == "lazy"
    np.testing.assert_array_equal(default.roadmap.edges, lazy.roadmap.edges)
    made = plan(exact, q.start, q.goal, sampler="G", planner=PRM(), rng=np.random.default_rng(3))  # as by name
    assert made.planner == "paper"
    np.testing.assert_array_equal(made.roadmap.edges, paper.roadmap.edges)
    with pytest.raises(ValueError, match="unknown planner 'nope'; choose one of"):
        plan(exact, q.start, q.goal, planner="nope", rng=np.random.default_rng(3))


def test_prediction_is_a_property_of_the_checker_not_its_identity():
    """A second exact checker (FCL, same workspace) deciding samples is no prediction: the same roadmap as without
    one, every node verified, no predicted checks; a checker that is not exact is prediction."""
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    fcl = FCLChecker(q.workspace, scenario.robot)
    assert exact.is_exact and fcl.is_exact and not NoisyChecker(exact, 0.1, seed=0).is_exact
    assert (
        not Problem.create(exact, q.start, q.goal).predicts
        and not Problem.create(exact, q.start, q.goal, checker=fcl).predicts
    )
    assert Problem.create(exact, q.start, q.goal, checker=NoisyChecker(exact, 0.1, seed=0)).predicts
    for planner in ("paper", "lazy"):  # the roadmap planners (rrt-connect plans without prediction)
        alone = plan(exact, q.start, q.goal, planner=planner, rng=np.random.default_rng(0))
        second = plan(exact, q.start, q.goal, planner=planner, checker=fcl, rng=np.random.default_rng(0))
        np.testing.assert_array_equal(alone.roadmap.nodes, second.roadmap.nodes)
        np.testing.assert_array_equal(alone.roadmap.edges, second.roadmap.edges)
        assert second.roadmap.node_verified.all() and second.stats["predicted_checks"] == 0
        noisy = plan(exact, q.start, q.goal, planner=planner, checker=NoisyChecker(exact, 0.1, seed=0),
                     rng=np.random.default_rng(0))  # fmt: skip
        assert noisy.stats["predicted_checks"] > 0


def test_every_planner_default_comes_from_one_rule(monkeypatch):
    """Without a recipe the caller's planner, else prm.DEFAULT, with or without prediction; a recipe's runs
    (reproduce) plan with the planner it is paired with, both ways, with the scenario's |S|."""
    from toolkit.experiments import planners, problems
    from toolkit.learning import presets

    scenario = scenarios.get("3dc7")
    assert problems.make_planner(scenario).name == prm.DEFAULT == "lazy"
    assert problems.make_planner(scenario).params == LazyParams(n_samples=scenario.plan_samples) != LazyParams()
    assert problems.make_planner(scenario, "paper").params == PaperParams(n_samples=400)
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    with_ = problems.build(scenario, q, checker=NoisyChecker(exact, 0.1, seed=0))
    without = problems.build(scenario, q)
    assert with_.problem.predicts and not without.problem.predicts
    assert (with_.planner.name, with_.planner.params) == (without.planner.name, without.planner.params)
    assert problems.make_planner(scenario, preset=presets.get("paper")).name == "paper"
    assert problems.make_planner(scenario, preset=presets.get("strong")).name == "lazy"
    derived = dataclasses.replace(presets.get("paper"), name="paper-wider", mlp_hidden=(64, 64))
    assert derived.origin == "paper" and problems.make_planner(scenario, preset=derived).name == "paper"
    own = presets.Preset(**{**dataclasses.asdict(presets.get("strong")), "name": "my-recipe", "origin": ""})
    assert problems.make_planner(scenario, preset=own).params == LazyParams(n_samples=400)  # the default planner
    monkeypatch.setattr(planners, "PAIRINGS", dict(planners.PAIRINGS))  # a recipe of yours, paired by name
    planners.register("my-recipe", planners.Pairing("paper", {"auxiliary": "confirmed"}))
    mine = problems.make_planner(scenario, preset=own)
    assert mine.name == "paper" and mine.params.auxiliary == "confirmed"
    assert problems.make_planner(scenario, "lazy", preset=own).params == LazyParams(n_samples=400)  # named wins
    with pytest.raises(ValueError, match="a planner pairing called 'paper' exists"):
        planners.register("paper", planners.OWN_RECIPE)
    with pytest.raises(ValueError, match=r"unknown planner option\(s\) \['screen_edges'\]"):
        planners.register("mine-2", planners.Pairing("paper", {"screen_edges": False}))


@pytest.mark.parametrize(
    "options, sources",
    [
        (dict(auxiliary="exact"), ["predicted", "exact", "exact", "exact"]),
        (dict(auxiliary="confirmed", exact_every=2), ["predicted", "confirmed", "exact", "confirmed", "exact"]),
        (
            dict(auxiliary="confirmed", exact_every=3),
            ["predicted", "confirmed", "confirmed", "exact", "confirmed", "confirmed", "exact"],
        ),
        (dict(auxiliary="predicted"), ["predicted"] * 4),
    ],
)
@pytest.mark.parametrize("planner", [LazyPRM, PRM])  # both planners read RoadmapParams.auxiliary
def test_rounds_after_the_first_sample_as_options_auxiliary_says(options, sources, planner):
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    lying = NoisyChecker(exact, 0.3, seed=0)
    params = planner.Params(n_samples=200, **options)  # Algorithm 1's rounds of |S| (the lazy PRM: first_samples)
    if planner is LazyPRM:
        params = dataclasses.replace(params, first_samples=None)
    planner = planner(params)
    query = QueryRoadmap(Problem.create(exact, q.start, q.goal, checker=lying), params)
    rng = np.random.default_rng(0)
    for round_, source in enumerate(sources, start=1):
        query.stats["rounds"] = round_
        exact.reset_count(), lying.reset_count()
        S, vouched = planner.sample_round(query, rng)
        assert vouched == (source != "predicted")
        assert (lying.n_checked > 0) == (source != "exact")
        if source == "exact":
            assert exact.n_checked == 200  # every uniform draw
        elif source == "confirmed":
            assert 0 < len(S) < exact.n_checked < 200  # only the predicted-valid draws, and some of those fail
        else:
            assert exact.n_checked == 0
        assert exact.are_valid(S).all() == vouched  # 30 % lies: predicted samples include invalid ones


class StraightLine:
    """A planner of another family, no PRM: the straight segment, if the exact checker passes it at both
    resolutions; its own parameters."""

    name = "straight"

    @dataclasses.dataclass(frozen=True)
    class Params:
        tries: int = 1

    def __init__(self, params=None):
        self.params = params or self.Params()

    def solve(self, problem, rng):
        path = np.stack([problem.start, problem.goal])
        ok = path_is_valid(problem.exact, path, problem.fine_resolution)
        return prm.PlanResult(bool(ok), path if ok else path[:0], {"total_s": 0.0}, self.name)


def test_a_planner_of_another_family_registers_and_plans(monkeypatch, capsys):
    monkeypatch.setattr(prm, "PLANNERS", dict(prm.PLANNERS))
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    with pytest.raises(ValueError, match="unknown planner 'straight'"):
        plan(exact, q.start, q.goal, planner="straight", rng=np.random.default_rng(0))
    prm.register(StraightLine)
    assert prm.get("straight") is StraightLine and prm.names() == [
        "paper",
        "lazy",
        "batched",
        "rrt-connect",
        "straight",
    ]
    free = Workspace(np.zeros(2), np.full(2, 31.0), np.zeros((0, 2, 2)))
    start, goal = np.array([2.0, 2.0]), np.array([28.0, 28.0])
    result = plan(exact_checker(free, scenario.robot), start, goal, planner="straight", rng=np.random.default_rng(0))
    assert result.success and result.planner == "straight" and len(result.path) == 2
    blocked = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[10.0, 10.0], [20.0, 20.0]]]))
    assert not plan(exact_checker(blocked, scenario.robot), start, goal, planner="straight",
                    rng=np.random.default_rng(0)).success  # fmt: skip
    with pytest.raises(ValueError, match="planner 'paper' reads PaperParams already"):
        prm.register(type("Copy", (PRM,), {"name": "copy"}))
    with pytest.raises(TypeError, match="needs solve"):
        prm.register(type("NoSolve", (), {"name": "x", "Params": StraightLine.Params}))
    from toolkit.cli import main

    assert main(["plan", "--scenario", "2ds", "--planner", "straight", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["planner"] == "straight" and out["params"] == {"tries": 1}


def test_same_seed_same_result():
    scenario = scenarios.get("3dc7")
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    runs = [
        plan(
            exact,
            q.start,
            q.goal,
            sampler="G",
            checker=NoisyChecker(exact, 0.1, 7),
            planner=LazyPRM(n_samples=150),
            rng=np.random.default_rng(4),
        )
        for _ in range(2)
    ]
    np.testing.assert_array_equal(runs[0].path, runs[1].path)
    np.testing.assert_array_equal(runs[0].roadmap.edges, runs[1].roadmap.edges)
    assert runs[0].stats["exact_checks"] == runs[1].stats["exact_checks"]


def traced_2ds_queries(flip, n_queries=6):
    """Per 2DS query: (query, exact checker, result, trace) of a screened plan, a lying checker when ``flip``."""
    scenario = scenarios.get("2ds")
    runs = []
    for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=n_queries // 2, per_workspace=2)):
        exact, trace = exact_checker(q.workspace, scenario.robot), []
        checker = NoisyChecker(exact, flip, seed=i) if flip else None
        result = plan(
            exact,
            q.start,
            q.goal,
            sampler="BS",
            checker=checker,
            planner=LazyPRM(n_samples=150),
            rng=np.random.default_rng(i),
            trace=trace,
        )
        runs.append((q, exact, result, trace))
    return runs


def test_trace_follows_algorithm_1_and_ends_with_the_returned_path():
    for _, _, result, trace in traced_2ds_queries(flip=0.0):
        stages = [step.stage for step in trace]
        assert set(stages) <= set(prm.STAGES)
        assert stages[:3] == ["sample", "connect", "candidate"] and stages[-1] == "path"
        first, last = trace[0], trace[-1]
        assert first.round == 1 and {prm.START, prm.GOAL} <= set(first.new_nodes.tolist())
        assert len(first.edges) == 0 and len(trace[1].edges) > 0  # connecting adds the edges
        np.testing.assert_array_equal(last.nodes[last.path], result.path)
        np.testing.assert_array_equal(last.edges, result.roadmap.edges)


def test_tracing_changes_nothing_but_records():
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    runs = [
        plan(
            exact,
            q.start,
            q.goal,
            sampler="OB",
            checker=NoisyChecker(exact, 0.2, 3),
            planner=LazyPRM(n_samples=150),
            rng=np.random.default_rng(5),
            trace=trace,
        )
        for trace in (None, [])
    ]
    np.testing.assert_array_equal(runs[0].path, runs[1].path)
    np.testing.assert_array_equal(runs[0].roadmap.edges, runs[1].roadmap.edges)
    assert runs[0].stats["exact_checks"] == runs[1].stats["exact_checks"]


def test_traced_repairs_remove_what_the_exact_checker_rejects_from_the_candidate_path():
    repairs = 0
    for _, exact, result, trace in traced_2ds_queries(flip=0.3):
        assert result.success
        assert sum(step.stage == "repair" for step in trace) == result.stats["repairs"]
        for step, after in zip(trace[:-1], trace[1:]):
            if step.stage != "repair":
                continue
            repairs += 1
            assert len(step.removed_nodes) + len(step.removed_edges) > 0
            assert set(step.removed_nodes.tolist()) <= set(step.path.tolist())
            assert not exact.are_valid(step.nodes[step.removed_nodes]).any()
            path_edges = {tuple(sorted(pair)) for pair in zip(step.path[:-1], step.path[1:])}
            assert {tuple(step.edges[e]) for e in step.removed_edges} <= path_edges
            Q0, Q1 = step.nodes[step.edges[step.removed_edges].T]
            assert not check_edges(exact, Q0, Q1, result.stats["resolution"] / 10).any()
            if after.stage == "candidate":  # not a bridge or a new round, which add edges or nodes
                assert len(after.nodes) == len(step.nodes) - len(step.removed_nodes)
                if len(step.removed_nodes) == 0:
                    assert len(after.edges) == len(step.edges) - len(step.removed_edges)
    assert repairs > 0  # 30 % lies: some candidate paths fail verification


def test_bad_input_gives_clear_errors():
    scenario = scenarios.get("2ds")
    q = make_queries(scenario, seed=0, n_workspaces=1, per_workspace=1)[0]
    exact = exact_checker(q.workspace, scenario.robot)
    blocked = q.workspace.boxes[0].mean(axis=0)  # the centre of an obstacle
    with pytest.raises(ValueError, match=r"start configuration .* in collision"):
        plan(exact, blocked, q.goal, rng=np.random.default_rng(0))
    with pytest.raises(ValueError, match="goal must have shape \\(2,\\)"):
        plan(exact, q.start, np.zeros(3), rng=np.random.default_rng(0))
    with pytest.raises(ValueError, match="NaN"):
        plan(exact, q.start, np.array([np.nan, 1.0]), rng=np.random.default_rng(0))
    with pytest.raises(ValueError, match="unknown sampler"):
        plan(exact, q.start, q.goal, sampler="RRT", rng=np.random.default_rng(0))
    for bad, match in [
        (dict(n_samples=0), "n_samples must be a positive integer"),
        (dict(k=2.5), "k must"),
        (dict(screen_spacing=0), "screen_spacing must be positive"),
        (dict(screen_reject=1.5), r"screen_reject must be in \[0, 1\]"),
        (dict(screen_penalty=-1), "screen_penalty must be non-negative"),
        (dict(auxiliary="sometimes"), "auxiliary must be one of exact, confirmed, predicted, got 'sometimes'"),
        (dict(exact_every=0), "exact_every must be a positive integer"),
        (dict(rebridge=-1), "rebridge must be a non-negative integer"),
        (dict(rebridge=1.5), "rebridge must be"),
        (dict(first_samples=0), "first_samples must be a positive integer"),
        (dict(certify_spacing=None), "certify_spacing must be positive and finite, got None"),  # TypeError inside
        (dict(n_samples="many"), "n_samples must be a positive integer, got 'many'"),  # ValueError inside
    ]:
        with pytest.raises(ValueError, match=f"LazyParams.{match}"):
            LazyParams(**bad)
    with pytest.raises(ValueError, match=r"PaperParams\.k must"):
        PaperParams(k=0)
    with pytest.raises(TypeError, match="screen_spacing"):  # the lazy planner's field: not Algorithm 1's
        PaperParams(screen_spacing=4.0)
    with pytest.raises(ValueError, match="resolution must be positive and finite, got nan"):  # the problem's
        plan(exact, q.start, q.goal, resolution=np.nan, rng=np.random.default_rng(0))
    with pytest.raises(ValueError, match="checker is for a 8-DoF robot, the exact checker for 2"):
        Problem.create(exact, q.start, q.goal, checker=RecordingChecker(scenarios.get("3do").robot))


# -- local planner and roadmap ----------------------------------------------------------------


def test_check_edges_agrees_with_checking_every_step():
    scenario = scenarios.get("3dc9")
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact, robot = exact_checker(q.workspace, scenario.robot), scenario.robot
    rng = np.random.default_rng(0)
    Q0, Q1 = robot.sample(rng, 60), robot.sample(rng, 60)
    Q1 = Q0 + 0.05 * robot.difference(Q0, Q1)  # short segments, some valid, some not
    got = check_edges(exact, Q0, Q1, 0.05)
    n = np.maximum(np.ceil(robot.motion_bound(Q0, Q1) / 0.05).astype(int), 1)
    want = [
        exact.are_valid(
            segment_points(robot, np.repeat(a[None], k - 1, 0), np.repeat(b[None], k - 1, 0), np.arange(1, k) / k)
        ).all()
        for a, b, k in zip(Q0, Q1, n)
    ]
    np.testing.assert_array_equal(got, want)
    assert 0 < got.sum() < len(got)
    fractions, suspects = invalid_fractions(exact, Q0, Q1, 0.05)
    assert np.all(fractions[got] == 0) and np.all(fractions[~got] > 0)
    assert np.all(np.isnan(suspects[got]))
    assert np.all(refute_at(exact, Q0, Q1, suspects, 0.05) == ~got)  # the suspect points are the invalid ones


def test_path_points_walk_the_path_at_the_resolution_and_decide_as_path_is_valid():
    scenario = scenarios.get("3dc7")
    robot = scenario.robot
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact = exact_checker(q.workspace, robot)
    rng = np.random.default_rng(3)
    for _ in range(5):
        path = np.concatenate([q.start[None], robot.sample(rng, 2), q.goal[None]])  # (4, 7), most likely invalid
        for route in (path, np.stack([q.start, q.start + 0.02])):  # the second: one step, valid
            points = path_points(robot, route, 0.05)  # (T, 7)
            np.testing.assert_allclose(points[[0, -1]], route[[0, -1]])
            assert len(points) == local_planner.step_counts(robot, route[:-1], route[1:], 0.05).sum() + 1
            assert np.all(robot.motion_bound(points[:-1], points[1:]) <= 0.05 + 1e-9)
            assert exact.are_valid(points).all() == path_is_valid(exact, route, 0.05)
    assert len(path_points(robot, q.start[None], 0.05)) == 1  # a one-configuration path is itself


def test_path_at_moves_at_constant_speed_along_the_path_and_wraps_angles():
    robot = scenarios.get("3do").robot  # the youBot: its base angle wraps around
    path = np.stack([robot.lower + 0.1, (robot.lower + robot.upper) / 2, robot.upper - 0.1])  # (3, dof)
    path[:, 2] = [3.0, -3.0, -2.0]  # the base turns the short way round, through pi
    lengths = robot.distance(path[:-1], path[1:])  # (2,)
    assert lengths[0] < lengths[1]
    np.testing.assert_allclose(
        path_at(robot, path, [-1.0, 0.0, lengths[0] / lengths.sum(), 1.0, 2.0]), path[[0, 0, 1, 2, 2]]
    )
    t = np.linspace(0.0, 1.0, 101)
    Q = path_at(robot, path, t)  # (101, dof)
    steps = robot.distance(Q[:-1], Q[1:])  # (100,)
    corner = np.searchsorted(t, lengths[0] / lengths.sum()) - 1  # the step that cuts the corner at path[1]
    np.testing.assert_allclose(np.delete(steps, corner), lengths.sum() / 100)  # equal steps along each segment
    assert steps[corner] < lengths.sum() / 100
    assert np.all(np.abs(Q[:, 2]) <= np.pi)  # the angle stays wrapped
    with pytest.raises(ValueError, match="two configurations or more, got 1"):
        path_at(robot, path[:1], [0.5])


class RecordingChecker(CollisionChecker):
    """Test double: every configuration valid; remembers each batch it was asked about."""

    def __init__(self, robot):
        super().__init__(robot)
        self.batches = []

    def validity(self, Q):
        self.batches.append(Q.copy())
        return np.ones(len(Q), bool)


def forty_segments_and_their_points(resolution):
    """A robot, 40 random segments ``Q0 -> Q1``, and all their interior points at ``resolution``."""
    robot = scenarios.get("3dc7").robot
    rng = np.random.default_rng(1)
    Q0, Q1 = robot.sample(rng, 40), robot.sample(rng, 40)
    n = np.maximum(np.ceil(robot.motion_bound(Q0, Q1) / resolution).astype(int), 1)
    points = np.concatenate(
        [
            segment_points(robot, np.repeat(a[None], k - 1, 0), np.repeat(b[None], k - 1, 0), np.arange(1, k) / k)
            for a, b, k in zip(Q0, Q1, n)
        ]
    )
    return robot, Q0, Q1, points


def test_check_edges_visits_every_interior_point_once_coarse_to_fine(monkeypatch):
    robot, Q0, Q1, want = forty_segments_and_their_points(0.05)
    calls = {}
    for min_batch in (1, 256, 10**9):
        monkeypatch.setattr(local_planner, "MIN_BATCH", min_batch)
        checker = RecordingChecker(robot)
        assert check_edges(checker, Q0, Q1, 0.05).all()
        got = np.concatenate(checker.batches)
        assert len(got) == len(want)  # no point twice
        np.testing.assert_allclose(np.sort(got, axis=0), np.sort(want, axis=0), atol=1e-9)
        assert len(checker.batches[0]) >= min(min_batch, len(want))
        calls[min_batch] = len(checker.batches)
    assert calls[1] > calls[256] > calls[10**9] == 1  # plain bisection order, merged coarse levels, all at once


def test_screened_path_edges_are_confirmed_coarse_then_fine_each_once(monkeypatch):
    scenario = scenarios.get("2ds")
    checked = []  # (resolution, edge, passed) of every edge the planner confirms exactly

    def recording(check):  # certify_edges, or check_edges where certificates do not pay (2DS)
        def confirm(checker, Q0, Q1, resolution, **spacing):
            ok = check(checker, Q0, Q1, resolution, **spacing)
            checked.extend((resolution, q0.tobytes() + q1.tobytes(), bool(v)) for q0, q1, v in zip(Q0, Q1, ok))
            return ok

        return confirm

    monkeypatch.setattr(query_roadmap, "certify_edges", recording(certify_edges))
    monkeypatch.setattr(query_roadmap, "check_edges", recording(check_edges))
    repairs = 0
    for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=2, per_workspace=3)):
        exact = exact_checker(q.workspace, scenario.robot)
        result = plan(
            exact,
            q.start,
            q.goal,
            sampler="BS",
            checker=NoisyChecker(exact, 0.15, seed=i),
            planner=LazyPRM(screen_edges=True),
            rng=np.random.default_rng(i),
        )
        assert result.success
        roadmap, coarse = result.roadmap, result.stats["resolution"]
        steps = roadmap.edge_index(roadmap.shortest_path(0, 1))
        np.testing.assert_array_equal(roadmap.edge_checked_at[steps], coarse / 10)  # the returned path: all fine
        repairs += result.stats["repairs"]
    assert repairs > 0  # paths were abandoned: their confirmed edges were remembered, not checked again
    resolutions = sorted({r for r, _, _ in checked}, reverse=True)
    assert resolutions == [coarse, coarse / 10]
    for resolution in resolutions:
        edges = [e for r, e, _ in checked if r == resolution]
        assert len(edges) == len(set(edges))
    passed_coarse = {e for r, e, ok in checked if r == coarse and ok}
    assert {e for r, e, _ in checked if r == coarse / 10} <= passed_coarse


def test_screened_edges_are_refuted_where_screening_saw_them_fail_and_only_when_invalid(monkeypatch):
    scenario = scenarios.get("3dc7")
    looked = []  # (edge, refuted, invalid at the roadmap's resolution) of every suspect point checked exactly

    def recording(checker, Q0, Q1, suspect, resolution):
        refuted = refute_at(checker, Q0, Q1, suspect, resolution)
        invalid = ~check_edges(checker, Q0, Q1, resolution)
        looked.extend(
            (q0.tobytes() + q1.tobytes(), r, v)
            for q0, q1, s, r, v in zip(Q0, Q1, suspect, refuted, invalid)
            if np.isfinite(s)
        )
        return refuted

    monkeypatch.setattr(query_roadmap, "refute_at", recording)
    for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=4)):
        exact = exact_checker(q.workspace, scenario.robot)
        result = plan(
            exact,
            q.start,
            q.goal,
            sampler="BT",
            checker=NoisyChecker(exact, 0.1, seed=i),
            planner=LazyPRM(n_samples=scenario.plan_samples),
            rng=np.random.default_rng(i),
        )
        assert result.success
    refuted = [r for _, r, _ in looked]
    assert sum(refuted) > 0  # screened edges failed where screening said, and cost one exact check each
    assert all(invalid for _, r, invalid in looked if r)  # a refutation is always right
    assert len({e for e, _, _ in looked}) == len(looked)  # each suspect point is looked at once


def test_refute_at_checks_one_interior_grid_point():
    _, exact, Q0, Q1 = segments_near_obstacles("3dc9", 60, 0.1, seed=3)
    fractions, suspects = invalid_fractions(exact, Q0, Q1, 0.05)
    assert np.isfinite(suspects).any() and np.isnan(suspects).any()
    exact.reset_count()
    refuted = refute_at(exact, Q0, Q1, suspects, 0.05)
    assert exact.n_checked == np.isfinite(suspects).sum()
    np.testing.assert_array_equal(refuted, fractions > 0)  # the exact checker's own suspects: all invalid
    np.testing.assert_array_equal(refute_at(exact, Q0, Q1, np.full(len(Q0), np.nan), 0.05), False)
    ends = np.zeros(len(Q0))  # fraction 0 is an endpoint: the nearest interior grid point is looked at instead
    assert refute_at(exact, Q0, Q1, ends, 0.05).sum() <= (~check_edges(exact, Q0, Q1, 0.05)).sum()
    np.testing.assert_array_equal(refute_at(exact, Q0, Q0 + 1e-6, ends, 0.05), False)  # no interior point: nothing


def segments_near_obstacles(name, n, scale, seed):
    """A query workspace of ``name``, its exact checker, and ``n`` segments between valid configurations
    ``scale`` (a fraction of the bounds) apart: some valid, some grazing, some through obstacles."""
    scenario = scenarios.get(name)
    q = make_queries(scenario, seed=0, n_workspaces=1)[0]
    exact, robot, rng = exact_checker(q.workspace, scenario.robot), scenario.robot, np.random.default_rng(seed)
    Q = robot.sample(rng, 20 * n)
    Q = Q[exact.are_valid(Q)]
    Q1 = np.clip(Q + rng.normal(0, scale, Q.shape) * (robot.upper - robot.lower), robot.lower, robot.upper)
    keep = exact.are_valid(Q1)
    return scenario, exact, Q[keep][:n], Q1[keep][:n]


@pytest.mark.parametrize("name, scale", [("3dc9", 0.05), ("3dc9", 0.1), ("3do", 0.08), ("2ds", 0.1)])
def test_certify_edges_answers_as_check_edges_with_far_fewer_checks(name, scale):
    scenario, exact, Q0, Q1 = segments_near_obstacles(name, 150, scale, seed=7)
    resolution = scenario.plan_resolution or local_planner.default_resolution(scenario.robot)
    for fine in (resolution, resolution / 10):
        exact.reset_count()
        want = check_edges(exact, Q0, Q1, fine)
        checks = exact.n_checked
        exact.reset_count()
        got = certify_edges(exact, Q0, Q1, fine, spacing=8 * resolution)
        np.testing.assert_array_equal(got, want)
        assert exact.n_checked < checks / 5 and exact.n_bounded < checks / 2
    assert 0.05 < want.mean() < 0.97  # both kinds of segment


def test_certified_intervals_are_free_throughout():
    """Two configurations whose clearances sum to more than the motion between them: every point between is valid."""
    scenario, exact, Q0, Q1 = segments_near_obstacles("3dc9", 400, 0.01, seed=8)
    robot = scenario.robot
    c0, c1 = exact.clearances(Q0, cap=1.0), exact.clearances(Q1, cap=1.0)
    certified = c0 + c1 > robot.motion_bound(Q0, Q1)
    assert certified.sum() > 100
    np.testing.assert_array_equal(check_edges(exact, Q0[certified], Q1[certified], 1e-3), True)


def test_certify_edges_without_clearances_checks_every_grid_point_once():
    robot, Q0, Q1, want = forty_segments_and_their_points(0.05)
    checker = RecordingChecker(robot)  # knows no geometry: clearances 0
    assert certify_edges(checker, Q0, Q1, 0.05, spacing=0.4).all()
    got = np.concatenate(checker.batches)
    assert len(got) == len(want)
    np.testing.assert_allclose(np.sort(got, axis=0), np.sort(want, axis=0), atol=1e-9)


def test_nearest_neighbours_wrap_around_angles():
    robot = scenarios.get("3dc7").robot
    roadmap = Roadmap(robot)
    base = np.array([5.0, 5, 5, 0, 0, 0, 0])
    far_linear, across_pi, same_side = base.copy(), base.copy(), base.copy()
    far_linear[0] += 1.0
    across_pi[3], same_side[3] = np.pi - 0.05, 0.5
    q = base.copy()
    q[3] = -np.pi + 0.05
    roadmap.add_nodes(np.stack([q, far_linear, across_pi, same_side]), verified=True)
    pairs = roadmap.candidate_edges(np.array([0]), k=1)
    np.testing.assert_array_equal(pairs, [[0, 2]])  # 0.1 rad away across +-pi, not 6.18
    np.testing.assert_allclose(roadmap.distance(q, across_pi), 0.1 * robot.motion_weights[3])


def test_remove_nodes_keeps_edges_consistent():
    robot = scenarios.get("2ds").robot
    roadmap = Roadmap(robot)
    roadmap.add_nodes(np.array([[1.0, 1], [2, 2], [3, 3], [4, 4]]), verified=True)
    roadmap.add_edges(np.array([[0, 1], [2, 3]]), np.ones(2), checked_at=0.5)
    roadmap.add_edges(np.array([[1, 2], [0, 3]]), np.ones(2), suspect=np.array([0.25, 0.75]))
    roadmap.remove_nodes(np.array([1]))
    np.testing.assert_array_equal(roadmap.edges, [[1, 2], [0, 2]])
    np.testing.assert_array_equal(roadmap.edge_checked_at, [0.5, np.inf])
    np.testing.assert_array_equal(roadmap.edge_suspect, [np.nan, 0.75])
    np.testing.assert_array_equal(roadmap.nodes[roadmap.shortest_path(0, 1)], [[1, 1], [4, 4], [3, 3]])


def test_rejected_pairs_are_remembered_across_renumbering_and_never_offered_again():
    robot = scenarios.get("2ds").robot
    roadmap = Roadmap(robot)
    roadmap.add_nodes(np.array([[1.0, 1], [1.2, 1], [5, 5], [1.4, 1], [1.6, 1]]), verified=True)
    roadmap.add_edges(np.array([[0, 1], [3, 4]]), np.ones(2))
    roadmap.remove_edges(np.array([1]))  # 3-4 failed
    roadmap.reject(np.array([[1, 3]]))
    assert roadmap.candidate_edges(np.array([3]), k=4).tolist() == [[0, 3], [2, 3]]  # neither 1-3 nor 3-4
    roadmap.remove_nodes(np.array([2]))  # 3 -> 2, 4 -> 3
    np.testing.assert_array_equal(roadmap.rejected, [[2, 3], [1, 2]])
    assert roadmap.candidate_edges(np.array([2]), k=3).tolist() == [[0, 2]]
    roadmap.remove_nodes(np.array([1]))
    np.testing.assert_array_equal(roadmap.rejected, [[1, 2]])


def test_bridging_again_tries_the_next_closest_pairs():
    robot = scenarios.get("2ds").robot
    roadmap = Roadmap(robot)
    left = np.array([[1.0, 1], [1.0, 1.5], [1.0, 2]])  # start's component: nodes 0-2
    right = np.array([[2.0, 1], [2.1, 1.45], [2.2, 2], [4, 4]])  # the rest: nodes 3-6
    roadmap.add_nodes(np.concatenate([left, right]), verified=True)
    roadmap.add_edges(np.array([[0, 1], [1, 2], [3, 4], [4, 5], [5, 6]]), np.ones(5))
    offered = []
    for _ in range(5):
        offered.append(roadmap.bridge_edges(0, k=2).tolist())
        roadmap.reject(np.array(offered[-1], dtype=int).reshape(-1, 2))
    # each member's nearest untried pair among its 2 nearest outside nodes, closest first:
    # 0-3 1.0, 1-4 1.10 (2-5 1.2 waits); 1-3 1.12, 0-4 1.19; 2-5; 2-4 1.23; none left
    assert offered == [[[0, 3], [1, 4]], [[1, 3], [0, 4]], [[2, 5]], [[2, 4]], []]


def test_the_planner_decides_no_pair_twice(monkeypatch):
    """Repairs split roadmaps and the planner bridges them again: every pair it screens or checks is new."""
    scenario = scenarios.get("3dc9")
    decided = []
    original = LazyPRM.decide

    def recording(self, query, pairs):
        Q = query.roadmap.nodes
        decided.append({Q[i].tobytes() + Q[j].tobytes() for i, j in pairs})
        assert len(decided[-1]) == len(pairs)
        original(self, query, pairs)

    monkeypatch.setattr(LazyPRM, "decide", recording)
    rounds = []
    for rebridge in (0, 3):
        stats = []
        for i, q in enumerate(make_queries(scenario, seed=0, n_workspaces=6)):
            decided.clear()
            exact = exact_checker(q.workspace, scenario.robot)
            result = plan(
                exact,
                q.start,
                q.goal,
                sampler="BT",
                checker=NoisyChecker(exact, 0.1, seed=i),
                planner=LazyPRM(n_samples=scenario.plan_samples, rebridge=rebridge, first_samples=None),
                rng=np.random.default_rng(i),
            )
            assert result.success
            assert sum(map(len, decided)) == len(set().union(*decided))
            stats.append(result.stats)
        rounds.append(sum(s["rounds"] for s in stats))
        assert (sum(s["rebridges"] for s in stats) > 0) == (rebridge > 0)
    assert rounds[1] < rounds[0]  # bridging again saved sampling rounds


# -- queries and the command ------------------------------------------------------------------


@pytest.mark.parametrize("name, count", [("2ds", 100), ("3dc7", 100)])
def test_paper_query_sets_are_valid_and_reproducible(name, count):
    scenario = scenarios.get(name)
    queries = make_queries(scenario, seed=0)
    assert len(queries) == count
    again = make_queries(scenario, seed=0, n_workspaces=3)
    for a, b in zip(queries, again):
        np.testing.assert_array_equal(a.start, b.start)
        assert a.workspace == b.workspace
    for q in queries[:: count // 10]:
        exact = exact_checker(q.workspace, scenario.robot)
        assert exact.are_valid(np.stack([q.start, q.goal])).all()


def _blas_threads() -> list[int]:
    return [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]


def test_run_queries_summary_with_a_checker_factory():
    scenario = scenarios.get("2ds")
    queries = make_queries(scenario, seed=0, n_workspaces=2, per_workspace=3)
    built, threads, before = [], [], torch.get_num_threads()

    def factory(ws):
        built.append(ws)
        threads.append((torch.get_num_threads(), _blas_threads()))
        return NoisyChecker(exact_checker(ws, scenario.robot), 0.05, seed=len(built))

    torch.set_num_threads(2)
    try:
        with threadpool_limits(limits=2, user_api="blas"):
            blas_before = _blas_threads()
            records, summary = run_queries(scenario, queries, "G", checker_factory=factory)
            # queries are timed on one torch and one BLAS thread, like the exact checker ...
            assert blas_before and blas_before != [1] * len(blas_before)
            assert threads == [(1, [1] * len(blas_before))] * 3  # the untimed warm-up's, then one a workspace
            assert torch.get_num_threads() == 2 and _blas_threads() == blas_before  # ... and the caller's come back
    finally:
        torch.set_num_threads(before)
    assert len(built) == 3 and built[0] is built[1] and len(records) == 6  # warm-up, then once a workspace
    assert summary["success_rate"] == 1.0 and summary["path_valid_rate"] == 1.0
    assert summary["predicted_checks"] > 0 and summary["sampling_s"] <= summary["total_s"]
    assert summary["total_s_std"] >= 0 and summary["n_queries"] == 6
    assert summary["total_s_median"] == np.median([r["total_s"] for r in records])
    totals = [r["total_s"] for r in records]
    assert summary["total_s_per_query"] == totals
    assert [summary["total_s_q1"], summary["total_s_q3"]] == pytest.approx(np.percentile(totals, [25, 75]))
    shares = [summary[f"{key}_share"] for key in ("sampling_s", "connection_s", "query_s")]
    assert shares[0] == pytest.approx(np.mean([r["sampling_s"] / r["total_s"] for r in records]))
    assert 0 < sum(shares) <= 1  # the rest of a query's time is its set-up and encoding


def test_run_interleaved_takes_turns_and_answers_as_separate_runs(monkeypatch):
    scenario = scenarios.get("2ds")
    queries = make_queries(scenario, seed=0, n_workspaces=2, per_workspace=2)

    def factory(ws):
        return NoisyChecker(exact_checker(ws, scenario.robot), 0.05, seed=1)

    separate = {"without": run_queries(scenario, queries, "OB"), "with": run_queries(scenario, queries, "OB", factory)}
    order, build = [], queries_module.build

    def recording(scenario, query, **settings):
        order.append("with" if settings["checker"] is not None else "without")
        return build(scenario, query, **settings)

    monkeypatch.setattr(queries_module, "build", recording)
    runs = queries_module.run_interleaved(scenario, queries, "OB", {"without": None, "with": factory})
    # an untimed warm-up solve per mode, then the timed queries, who goes first rotating
    assert order == ["without", "with"] + ["without", "with", "with", "without"] * 2
    for mode, (records, summary) in runs.items():
        keys = ("nodes", "edges", "rounds", "exact_checks", "predicted_checks", "success")
        assert [[r[k] for k in keys] for r in records] == [[r[k] for k in keys] for r in separate[mode][0]]
        assert summary["n_queries"] == 4


def test_plan_command_prints_json(capsys):
    assert cli.main(["plan", "--scenario", "2ds", "--sampler", "OB", "--seed", "2", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["success"] is True and len(out["path"]) >= 2
    assert set(out["workspace"]) >= {"lower", "upper", "boxes"} and out["stats"]["nodes"] > 2
    assert out["planner"] == prm.DEFAULT == "lazy" and out["params"]["n_samples"] == 200 and not out["predict"]
    assert cli.main(["plan", "--scenario", "2ds", "--planner", "paper", "--option", "k=12", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["planner"] == "paper" and out["params"]["k"] == 12 and out["success"]
    assert cli.main(["plan", "--scenario", "2ds", "--planner", "paper", "--option", "screen_edges=false"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "unknown planner option(s) ['screen_edges']; PaperParams has" in err
    assert cli.main(["plan", "--scenario", "2ds", "--predict"]) == 2
    assert "--checkpoint" in capsys.readouterr().err
