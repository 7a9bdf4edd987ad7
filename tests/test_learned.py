"""The learned checker: same interface as the exact one, agreement with it, bounds, thresholds, bad input."""

import dataclasses
import json

import numpy as np
import pytest
import torch

from toolkit import cli, scenarios
from toolkit.experiments import pipeline, problems
from toolkit.experiments.config import RunConfig
from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.learning import checkpoints, presets
from toolkit.learning import learned as learned_module
from toolkit.learning.learned import LearnedChecker, load_checker
from toolkit.planning.options import LazyParams

SCENARIO = scenarios.get("2ds")


@pytest.fixture(scope="module")
def models():
    config = RunConfig.create(SCENARIO, "strong", quick=True, progress=False, device="cpu")
    return pipeline.train(config, pipeline.make_splits(config))


@pytest.fixture(scope="module")
def workspace():
    return SCENARIO.workspaces("query", 1, seed=0)[0]


def test_agrees_with_the_exact_checker(models, workspace, rng):
    checker, exact = LearnedChecker(workspace, models), exact_checker(workspace, SCENARIO.robot)
    assert isinstance(checker, CollisionChecker)
    Q = SCENARIO.robot.sample(rng, 5000)
    valid = exact.are_valid(Q)
    predicted = checker.are_valid(Q)
    assert np.mean(predicted == valid) > 0.9
    assert np.mean(predicted[valid]) > 0.9 and np.mean(~predicted[~valid]) > 0.7  # TPR, TNR on uniform samples
    assert checker.n_checked == 5000


def test_probability_and_threshold(models, workspace, rng):
    checker = LearnedChecker(workspace, models, threshold=0.5)
    Q = SCENARIO.robot.sample(rng, 1000)
    p = checker.probability(Q)
    assert p.shape == (1000,) and np.all((p >= 0) & (p <= 1))
    assert np.array_equal(checker.are_valid(Q), p >= 0.5)
    checker.threshold = 0.9
    assert np.array_equal(checker.are_valid(Q), p >= 0.9)
    assert checker.is_valid(Q[0]) == (p[0] >= 0.9)
    with pytest.raises(ValueError, match="threshold"):
        checker.threshold = 1.5


def test_default_threshold_is_the_models(models, workspace):
    assert LearnedChecker(workspace, models).threshold == models.threshold


def test_outside_the_bounds_is_invalid(models, workspace):
    checker = LearnedChecker(workspace, models, threshold=0.0)  # would accept anything inside
    Q = np.array([[-3.0, 10.0], [15.0, 40.0], [15.0, 15.0]])
    assert checker.are_valid(Q).tolist() == [False, False, True]
    assert checker.probability(Q)[:2].tolist() == [0.0, 0.0]


@pytest.mark.parametrize("Q", [np.zeros((4, 3)), np.zeros((2, 2, 2)), np.array([[1.0, np.nan]])])
def test_bad_configurations(models, workspace, Q):
    checker = LearnedChecker(workspace, models)
    with pytest.raises(ValueError):
        checker.are_valid(Q)
    with pytest.raises(ValueError):
        checker.probability(Q)


def test_workspace_of_another_scenario(models):
    other = scenarios.get("3dc7").workspaces("query", 1, seed=0)[0]
    with pytest.raises(ValueError, match="does not fit scenario '2ds'"):
        LearnedChecker(other, models)


def test_load_checker(models, workspace, tmp_path, rng):
    checkpoints.save_checkpoint(models, tmp_path)
    loaded, direct = load_checker(tmp_path, workspace), LearnedChecker(workspace, models)
    Q = SCENARIO.robot.sample(rng, 200)
    assert np.array_equal(loaded.probability(Q), direct.probability(Q))


@pytest.mark.parametrize(
    "change, message",
    [
        ({"format": 1}, "has format 1, this toolkit reads format 2"),  # before presets dropped planner settings
        ({"format": None}, "has format None, this toolkit reads format 2"),
        ({"format": "absent"}, "has format none recorded, this toolkit reads format 2"),
        (
            {"preset": "without dropout"},
            r"preset does not match this toolkit's Preset \(missing \['dropout'\], unknown \[\]\)",
        ),
        ({"preset": "with colour"}, r"\(missing \[\], unknown \['colour'\]\)"),
        ({"seed": "absent"}, r"meta.json lacks \['seed'\]"),
    ],
)
def test_a_checkpoint_of_another_format_is_refused_by_name(models, workspace, tmp_path, change, message):
    checkpoints.save_checkpoint(models, tmp_path)
    meta = json.loads((tmp_path / "meta.json").read_text())
    key, value = next(iter(change.items()))
    if value == "absent":
        del meta[key]
    elif value == "without dropout":
        del meta["preset"]["dropout"]
    elif value == "with colour":
        meta["preset"]["colour"] = "blue"
    else:
        meta[key] = value
    (tmp_path / "meta.json").write_text(json.dumps(meta))
    with pytest.raises(ValueError, match=message) as refused:
        load_checker(tmp_path, workspace)
    assert "toolkit train" in str(refused.value)  # and says how to write it again


def test_weights_with_other_entries_are_refused(models, workspace, tmp_path):
    checkpoints.save_checkpoint(models, tmp_path)
    state = torch.load(tmp_path / "weights.pt", weights_only=True)
    state["encoding.offsets"] = torch.zeros(9, 2)  # an entry the networks do not have
    torch.save(state, tmp_path / "weights.pt")
    with pytest.raises(ValueError, match=r"weights\.pt is corrupted or does not match the networks"):
        load_checker(tmp_path, workspace)


@pytest.mark.parametrize("preset", ["paper", "strong"])
def test_a_learned_checker_changes_the_checker_and_never_the_planner(models, workspace, preset):
    """Issue 48: whatever the model's recipe, a query planned with its learned checker runs the planner the caller
    names (none: the default, the lazy PRM) with the same parameters as without it; the problem predicts because
    the checker is not exact."""
    checker = LearnedChecker(workspace, dataclasses.replace(models, preset=presets.get(preset)))
    assert not checker.is_exact
    with_ = problems.build(SCENARIO, checker=checker)
    without = problems.build(SCENARIO)
    assert with_.problem.predicts and not without.problem.predicts
    assert with_.planner.name == without.planner.name == "lazy" and with_.planner.params == without.planner.params
    assert with_.planner.params == LazyParams(n_samples=SCENARIO.plan_samples)


def test_a_predictor_is_built_from_a_preset_in_one_place_and_its_initialization_changes_no_loaded_result(
    models, workspace, tmp_path, rng
):
    """``Preset.build_predictor`` is the one way from a recipe to networks (training, checkpoints, benchmarks). Two
    of the three places that built them field by field dropped ``mlp_init``: it changed no result, since a
    checkpoint's weights replace the initial ones and a benchmark's speed does not depend on them; shown here."""
    assert presets.get("paper").mlp_init == "he"
    built = []
    for init in ("he", "torch"):
        torch.manual_seed(0)
        built.append(dataclasses.replace(models.preset, mlp_init=init).build_predictor(SCENARIO))
    he, default = built
    assert not torch.equal(he.mlp.linears[0].weight, default.mlp.linears[0].weight)  # the field matters here ...
    checkpoints.save_checkpoint(models, tmp_path)
    state = torch.load(tmp_path / "weights.pt", weights_only=True)
    Q = SCENARIO.robot.sample(rng, 300)
    answers = []
    for predictor in (he, default):
        predictor.load_state_dict(state)
        trained = dataclasses.replace(models, predictor=predictor.eval())
        answers.append(LearnedChecker(workspace, trained).probability(Q))
    np.testing.assert_array_equal(*answers)  # ... and not once the checkpoint's weights are in
    np.testing.assert_array_equal(answers[0], load_checker(tmp_path, workspace).probability(Q))


def test_bench_json(capsys):
    assert cli.main(["bench", "--scenario", "2ds", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["learned_cfg_per_s"] > 0 and result["exact_cfg_per_s"] > 0
    assert result["ratio"] == pytest.approx(result["learned_cfg_per_s"] / result["exact_cfg_per_s"])


def test_a_checkpoint_loads_for_the_scenario_object_it_is_given(models, tmp_path):
    """Objects flow down: a caller holding a scenario gets its models for that very object, not a fresh lookup of
    the recorded name (a registered or changed scenario stays the caller's)."""
    checkpoints.save_checkpoint(models, tmp_path)
    own = dataclasses.replace(SCENARIO)  # equal to the registry's, but another object
    assert checkpoints.load_models(tmp_path, own).scenario is own
    assert checkpoints.load_models(tmp_path).scenario is scenarios.get("2ds")  # no scenario given: its name's
    with pytest.raises(ValueError, match="trained for scenario '2ds', not '3dc7'"):
        checkpoints.load_models(tmp_path, scenarios.get("3dc7"))


# -- on a device (issue 50): tensors answered in kind, float32 without copies, replayed calls --------------------


@pytest.fixture(scope="module")
def untrained_3dc7():
    """A learned checker of untrained `strong` networks in a 3DC-7 workspace, and uniform configurations."""
    from toolkit.experiments.bench import untrained_models

    scenario = scenarios.get("3dc7")
    models = untrained_models(scenario, presets.get("strong"))
    ws = scenario.workspaces("query", 1, seed=0)[0]
    return models, ws, scenario.robot.sample(np.random.default_rng(5), 3000)


def test_a_tensor_is_answered_on_its_device_as_numpy_is_in_numpy(untrained_3dc7):
    models, ws, Q = untrained_3dc7
    checker = LearnedChecker(ws, models, device="cpu")
    expected = checker.are_valid(Q)  # (N,) numpy bool
    assert 0.05 < expected.mean() < 0.95
    for batch in (torch.from_numpy(Q), torch.from_numpy(Q).float()):
        answer = checker.are_valid(batch)
        assert isinstance(answer, torch.Tensor) and answer.dtype == torch.bool and answer.device == batch.device
        np.testing.assert_array_equal(answer.numpy(), expected)
    np.testing.assert_array_equal(checker.are_valid(Q.astype(np.float32)), expected)
    assert checker.n_checked == 4 * len(Q)


def test_float32_bounds_are_rounded_inwards_so_they_compare_exactly(untrained_3dc7):
    """A float32 configuration one float32 step past a bound is out, as in float64; on the bound it is in."""
    models, ws, Q = untrained_3dc7
    checker = LearnedChecker(ws, models)
    robot = checker.robot
    lower32, upper32 = (torch.as_tensor(b) for b in learned_module.inward_bounds(robot, torch.float32))
    assert torch.all(lower32.double() >= torch.tensor(robot.lower))
    assert torch.all(upper32.double() <= torch.tensor(robot.upper))
    below = torch.from_numpy(Q[:50]).float()
    below[:, 0] = torch.nextafter(lower32[0], torch.tensor(-np.inf))  # just below the lowest float32 inside
    assert not checker.are_valid(below).any()
    assert not checker.are_valid(below.numpy()).any()


def test_replayed_calls_give_the_answers_of_direct_ones(untrained_3dc7):
    """graph_sizes records calls up to a size (a CUDA graph on a GPU; on the CPU the same function on a fixed
    batch): a call of fewer rows, or of exactly that many, answers as a direct one; larger calls go direct."""
    models, ws, Q = untrained_3dc7
    direct = LearnedChecker(ws, models).are_valid(Q)
    replayed = LearnedChecker(ws, models, graph_sizes=(1024, 256))
    assert [r.capacity for r in replayed._replays] == [256, 1024]
    for n in (1, 200, 256, 1000, 1024, 3000):
        np.testing.assert_array_equal(replayed.are_valid(torch.from_numpy(Q[:n]).float()).numpy(), direct[:n])
    first = replayed.are_valid(torch.from_numpy(Q[:10]).float())
    replayed.are_valid(torch.from_numpy(Q[10:20]).float())
    np.testing.assert_array_equal(first.numpy(), direct[:10])  # an answer is not overwritten by the next call


def test_bad_tensors_are_named_and_non_finite_rows_are_invalid(untrained_3dc7):
    models, ws, Q = untrained_3dc7
    checker = LearnedChecker(ws, models)
    with pytest.raises(ValueError, match=r"shape \(N, 7\)"):
        checker.are_valid(torch.zeros(4, 3))
    with pytest.raises(ValueError, match="floating-point"):
        checker.are_valid(torch.zeros(4, 7, dtype=torch.int32))
    bad = torch.from_numpy(Q[:3]).clone()
    bad[0, 2] = float("nan")
    assert checker.are_valid(bad).tolist()[0] is False
    with pytest.raises(ValueError, match="NaN"):
        checker.are_valid(bad.numpy())


def test_the_stager_answers_in_chunks_as_in_one_call():
    """The numpy path of a device checker, in chunks (pinned buffers need a GPU; the chunking runs here)."""
    from toolkit.geometry.device import Stager

    Q = np.random.default_rng(6).normal(size=(1000, 3))
    stager = Stager("cpu", 3, torch.float32, chunk=64)
    answer = stager(lambda chunk: chunk.sum(dim=1) > 0, Q)
    np.testing.assert_array_equal(answer, Q.astype(np.float32).sum(axis=1) > 0)
    assert stager(lambda chunk: chunk[:, 0] > 0, Q[:0]).shape == (0,)


def test_bench_on_a_device_times_numpy_in_out_and_resident(capsys):
    assert cli.main(["bench", "--scenario", "2ds", "--device", "cpu", "--batch", "500", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["device"] == "cpu"
    for key in ("learned_cfg_per_s", "learned_resident_cfg_per_s", "exact_device_cfg_per_s"):
        assert result[key] > 0
    assert result["device_ratio"] == pytest.approx(
        result["learned_resident_cfg_per_s"] / result["exact_device_resident_cfg_per_s"]
    )
    if not torch.cuda.is_available():
        assert cli.main(["bench", "--scenario", "2ds", "--device", "cuda", "--json"]) == 2
        assert "no CUDA device" in capsys.readouterr().err
    assert cli.main(["bench", "--scenario", "2ds", "--device", "tpu9", "--json"]) == 2
    assert "not a torch device" in capsys.readouterr().err
