"""Labelled datasets (issue 2, paper §IV-A): balance, labels, the seen / unseen splits, files."""

import json

import numpy as np
import pytest

from toolkit import scenarios
from toolkit.geometry.collision import FCLChecker, exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.learning import data
from toolkit.learning.data import CollisionDataset, balanced_samples, make_splits
from toolkit.scenarios import stream_rng

SMALL = dict(n_seen=3, n_seen_test=2, n_unseen=2, samples_per_workspace=20, progress=False)


@pytest.fixture(scope="module")
def splits_2ds():
    return make_splits(scenarios.get("2ds"), seed=4, **SMALL)


@pytest.fixture(scope="module")
def splits_3dc7():
    return make_splits(scenarios.get("3dc7"), seed=4, **SMALL)


# -- balanced samples -------------------------------------------------------------------


@pytest.mark.parametrize("name, fraction", [("2ds", 0.5), ("3do", 0.5), ("3dc9", 0.5), ("3dc7", 0.3), ("2ds", 1.0)])
def test_balanced_samples_have_the_fraction_and_the_exact_labels(name, fraction):
    scenario = scenarios.get(name)
    ws = scenario.make_workspace(np.random.default_rng(1))
    Q, valid = balanced_samples(
        exact_checker(ws, scenario.robot), np.random.default_rng(2), 101, valid_fraction=fraction
    )
    assert Q.shape == (101, scenario.robot.dof) and valid.shape == (101,) and valid.dtype == bool
    assert valid.sum() == round(101 * fraction)
    np.testing.assert_array_equal(valid, FCLChecker(ws, scenario.robot).are_valid(Q))  # FCL agrees with every label
    assert np.all(scenario.robot.in_bounds(Q))
    if 0 < fraction < 1:
        assert 0 < valid[:50].sum() < 50  # shuffled, not all valid first


def test_balanced_samples_are_reproducible():
    scenario = scenarios.get("3dc7")
    ws = scenario.make_workspace(np.random.default_rng(1))
    checker = exact_checker(ws, scenario.robot)
    a, b, c = (balanced_samples(checker, np.random.default_rng(seed), 40) for seed in (5, 5, 6))
    np.testing.assert_array_equal(a[0], b[0])
    np.testing.assert_array_equal(a[1], b[1])
    assert not np.array_equal(a[0], c[0])


def test_balanced_samples_give_up_when_no_valid_configuration_exists():
    scenario = scenarios.get("2ds")
    blocked = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[0, 0], [31, 31]]], float))
    with pytest.raises(ValueError, match="only 0 valid"):
        balanced_samples(exact_checker(blocked, scenario.robot), np.random.default_rng(0), 10, max_draws=1000)


@pytest.mark.parametrize("n, fraction", [(10, 1.5), (10, -0.1), (-1, 0.5)])
def test_balanced_samples_refuse_impossible_requests(n, fraction):
    scenario = scenarios.get("2ds")
    checker = exact_checker(scenario.make_workspace(np.random.default_rng(0)), scenario.robot)
    with pytest.raises(ValueError, match="valid_fraction"):
        balanced_samples(checker, np.random.default_rng(0), n, valid_fraction=fraction)


# -- splits ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "name, seen, seen_test, unseen, samples",
    [
        ("2ds", 30, 30, 10, 100),
        ("3do", 100, 100, 20, 200),
        ("3dc7", 50, 30, 10, 200),
        ("3dc9", 50, 30, 10, 200),
    ],
)
def test_paper_defaults(name, seen, seen_test, unseen, samples):
    s = scenarios.get(name)
    assert (s.n_seen, s.n_seen_test, s.n_unseen, s.samples_per_workspace) == (seen, seen_test, unseen, samples)


@pytest.mark.parametrize("fixture, dof, grid", [("splits_2ds", 2, (31, 31)), ("splits_3dc7", 7, (11, 11, 11))])
def test_split_shapes_balance_and_labels(request, fixture, dof, grid):
    splits = request.getfixturevalue(fixture)
    assert set(splits) == {"train", "seen_test", "unseen_test"}
    name = splits["train"].scenario
    robot = scenarios.get(name).robot
    for split, count in (("train", 3), ("seen_test", 2), ("unseen_test", 2)):
        ds = splits[split]
        assert ds.scenario == name and len(ds.workspaces) == count and len(ds) == count * 20
        assert ds.occupancy.shape == (count, *grid) and ds.occupancy.dtype == np.float32
        assert ds.configs.shape == (count, 20, dof) and ds.valid.shape == (count, 20)
        np.testing.assert_array_equal(ds.valid.sum(axis=1), 10)  # exactly 50/50 in every workspace
        for ws, grid_w, Q, valid in zip(ds.workspaces, ds.occupancy, ds.configs, ds.valid):
            np.testing.assert_array_equal(grid_w, ws.occupancy())
            np.testing.assert_array_equal(valid, FCLChecker(ws, robot).are_valid(Q))


def test_seen_test_reuses_training_workspaces_with_new_samples(splits_3dc7):
    train, seen, unseen = splits_3dc7["train"], splits_3dc7["seen_test"], splits_3dc7["unseen_test"]
    assert seen.workspaces == train.workspaces[:2]
    np.testing.assert_array_equal(seen.occupancy, train.occupancy[:2])
    assert not np.any(np.isclose(seen.configs[:, :, None], train.configs[:2, None]).all(axis=-1))  # no sample reused
    assert all(ws not in train.workspaces for ws in unseen.workspaces)
    assert train.workspaces == scenarios.get("3dc7").workspaces("seen", 3, seed=4)
    assert unseen.workspaces == scenarios.get("3dc7").workspaces("unseen", 2, seed=4)


@pytest.mark.parametrize("fixture", ["splits_2ds", "splits_3dc7"])
def test_validity_blind_split_is_the_papers_unseen_test(request, fixture):
    """§IV-A: in the unseen workspaces, |S| uniform samples each (2DS 200, 3DC 400), whatever their validity."""
    unseen = request.getfixturevalue(fixture)["unseen_test"]
    scenario = scenarios.get(unseen.scenario)
    blind = data.validity_blind_split(scenario, unseen)
    assert blind.workspaces == unseen.workspaces and blind.configs.shape == (
        2,
        scenario.plan_samples,
        scenario.robot.dof,
    )
    np.testing.assert_array_equal(blind.occupancy, unseen.occupancy)
    for ws, Q, valid in zip(blind.workspaces, blind.configs, blind.valid):
        np.testing.assert_array_equal(valid, FCLChecker(ws, scenario.robot).are_valid(Q))
        assert np.all(scenario.robot.lower <= Q) and np.all(scenario.robot.upper >= Q)
    assert 0.6 < blind.valid.mean() < 0.98  # not balanced: most uniform samples are free
    np.testing.assert_array_equal(data.validity_blind_split(scenario, unseen).configs, blind.configs)  # reproducible
    assert not np.isin(blind.configs, unseen.configs).all(axis=-1).any()  # its own stream, not the balanced samples


def test_same_seed_same_arrays_other_seed_other(splits_2ds):
    again = make_splits(scenarios.get("2ds"), seed=4, **SMALL)
    other = make_splits(scenarios.get("2ds"), seed=5, **SMALL)
    for split in splits_2ds:
        np.testing.assert_array_equal(again[split].configs, splits_2ds[split].configs)
        np.testing.assert_array_equal(again[split].valid, splits_2ds[split].valid)
        np.testing.assert_array_equal(again[split].occupancy, splits_2ds[split].occupancy)
        assert not np.array_equal(other[split].configs, splits_2ds[split].configs)


def test_growing_a_split_keeps_its_workspaces():
    scenario = scenarios.get("3do")
    assert scenario.workspaces("seen", 4, seed=1)[:2] == scenario.workspaces("seen", 2, seed=1)
    seen, query = scenario.workspaces("seen", 1, seed=1), scenario.workspaces("query", 1, seed=1)
    assert seen != query


def test_stream_rng_is_keyed_by_seed_stream_and_index():
    draw = lambda *key: stream_rng(*key).random(3)
    np.testing.assert_array_equal(draw(0, "seen", 1), draw(0, "seen", 1))
    for other in [(1, "seen", 1), (0, "unseen", 1), (0, "seen", 2)]:
        assert not np.array_equal(draw(0, "seen", 1), draw(*other))
    with pytest.raises(ValueError, match="unknown stream 'nonsense'"):
        stream_rng(0, "nonsense", 0)


def test_flat_view(splits_2ds):
    index, Q, valid = splits_2ds["train"].flat()
    np.testing.assert_array_equal(index, np.repeat([0, 1, 2], 20))
    np.testing.assert_array_equal(Q[20:40], splits_2ds["train"].configs[1])
    np.testing.assert_array_equal(valid[20:40], splits_2ds["train"].valid[1])


def test_inconsistent_dataset_is_refused(splits_2ds):
    ds = splits_2ds["train"]
    with pytest.raises(ValueError, match="disagree on the number of workspaces"):
        CollisionDataset("2ds", ds.workspaces[:2], ds.occupancy, ds.configs, ds.valid)
    with pytest.raises(ValueError, match=r"configs .* and labels .* disagree"):
        CollisionDataset("2ds", ds.workspaces, ds.occupancy, ds.configs, ds.valid[:, :10])


# -- files ------------------------------------------------------------------------------------


def test_save_load_round_trip(tmp_path, splits_3dc7):
    ds = splits_3dc7["seen_test"]
    ds.save(tmp_path / "seen.npz")
    back = CollisionDataset.load(tmp_path / "seen.npz", scenario="3dc7")
    assert back.scenario == "3dc7" and back.workspaces == ds.workspaces
    np.testing.assert_array_equal(back.occupancy, ds.occupancy)
    np.testing.assert_array_equal(back.configs, ds.configs)
    assert back.valid.dtype == bool
    np.testing.assert_array_equal(back.valid, ds.valid)
    assert back.meta == {"seed": 4, "stream": "test_samples", "samples_per_workspace": 20, "balanced": True}
    assert not list(tmp_path.glob("*.tmp*"))


def test_wrong_scenario_is_named(tmp_path, splits_2ds):
    splits_2ds["train"].save(tmp_path / "train.npz")
    with pytest.raises(ValueError, match="holds data for scenario '2ds', not '3dc9'"):
        CollisionDataset.load(tmp_path / "train.npz", scenario="3dc9")


def corrupt(path, how):
    raw = path.read_bytes()
    if how == "truncated":
        path.write_bytes(raw[: len(raw) // 2])
    elif how == "garbage":
        path.write_bytes(np.random.default_rng(0).bytes(len(raw)))
    elif how == "flipped":  # one byte changed inside the compressed arrays
        middle = len(raw) // 3
        path.write_bytes(raw[:middle] + bytes([raw[middle] ^ 0xFF]) + raw[middle + 1 :])
    elif how == "missing array":
        with np.load(path) as data:
            np.savez(path, occupancy=data["occupancy"], configs=data["configs"], meta=data["meta"])
    elif how == "meta without workspaces":
        with np.load(path) as data:
            arrays = dict(data)
        meta = json.loads(str(arrays["meta"]))
        del meta["workspaces"]
        np.savez(path, **dict(arrays, meta=np.array(json.dumps(meta))))
    elif how == "meta not json":
        with np.load(path) as data:
            np.savez(path, **dict(data, meta=np.array("{not json")))
    elif how == "empty":
        path.write_bytes(b"")


@pytest.mark.parametrize(
    "how", ["truncated", "garbage", "flipped", "missing array", "meta without workspaces", "meta not json", "empty"]
)
def test_corrupted_dataset_is_named(tmp_path, splits_2ds, how):
    path = tmp_path / "train.npz"
    splits_2ds["train"].save(path)
    corrupt(path, how)
    with pytest.raises(ValueError, match=r"train.npz is not a valid dataset file \(corrupted or truncated\)"):
        CollisionDataset.load(path, scenario="2ds")


def test_missing_dataset_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        CollisionDataset.load(tmp_path / "nowhere.npz")
