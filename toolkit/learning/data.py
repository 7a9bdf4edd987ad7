"""Labelled, balanced datasets of configurations and their seen / unseen splits (paper §IV-A).

For every workspace we draw configurations uniformly, label them with the exact
checker and keep about as many valid as invalid ones (the paper: "approximately
distributed 50/50"). Three splits follow the paper:

- ``train``: the seen workspaces (2DS 30, 3DO 100, 3DC 50) with their samples;
- ``seen_test``: the first ``n_seen_test`` seen workspaces with *new* samples;
- ``unseen_test``: workspaces never trained on (2DS 10, 3DO 20, 3DC 10).

The paper evaluates unseen workspaces differently from seen ones: "we generate 200
samples regardless of their validity for each 2D simple workspace, 2000 samples for
each 3D office-like workspace, and 400 samples for each 3D clutter workspace. This
is evaluated as unseen scenarios" (§IV-A). :func:`validity_blind_split` draws those
(as many as ``Scenario.plan_samples``) in the unseen workspaces: most of them are
valid (2DS: about 85 %), so answering "valid" everywhere already scores well there.

Each workspace has its own seed, derived from ``(seed, split, index)``, so growing a
split keeps the workspaces it already had.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path

import numpy as np
from tqdm.auto import tqdm

from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace
from toolkit.scenarios import Scenario, stream_rng
from toolkit.util import outputs

SPLITS = ("train", "seen_test", "unseen_test")


def occupancy_grids(scenario: Scenario, stream: str, count: int, seed: int, *, progress: bool = False) -> np.ndarray:
    """``(count, *grid)`` int8 occupancy grids (-1 / +1) of a stream's workspaces, made one at a time: a CAE
    can train on thousands (2000 3DO grids: 20 MB) without keeping their workspaces."""
    grids = np.empty((count,) + tuple(scenario.grid_shape), dtype=np.int8)
    for i in tqdm(range(count), desc=f"{scenario.name} grids", disable=not progress, leave=False):
        grids[i] = scenario.make_workspace(stream_rng(seed, stream, i)).occupancy()
    return grids


def balanced_samples(
    checker, rng: np.random.Generator, n: int, *, valid_fraction: float = 0.5, max_draws: int = 2_000_000
) -> tuple[np.ndarray, np.ndarray]:
    """``n`` uniform configurations, ``round(n * valid_fraction)`` of them valid: ``(n, dof)``, ``(n,)`` bool.

    Draws batches until both quotas are met; a one-line ``ValueError`` if ``max_draws`` are not enough
    (a workspace almost entirely free or entirely blocked).
    """
    if not 0.0 <= valid_fraction <= 1.0 or n < 0:
        raise ValueError(f"need n >= 0 and 0 <= valid_fraction <= 1, got n={n}, valid_fraction={valid_fraction}")
    robot = checker.robot
    want_valid = int(round(n * valid_fraction))
    want = {True: want_valid, False: n - want_valid}
    kept: dict[bool, list[np.ndarray]] = {True: [], False: []}  # batches (M, dof) of each label
    drawn, batch = 0, max(64, 4 * n)
    while any(sum(map(len, kept[c])) < want[c] for c in (True, False)):
        if drawn >= max_draws:
            have = {c: sum(map(len, kept[c])) for c in kept}
            raise ValueError(
                f"after {drawn} draws only {have[True]} valid / {have[False]} invalid "
                f"configurations of the {want[True]} / {want[False]} wanted: a workspace almost all free or all blocked"
            )
        Q = robot.sample(rng, batch)
        valid = checker.are_valid(Q)
        drawn += batch
        for c in (True, False):
            kept[c].append(Q[valid == c])
    Q = np.concatenate([np.concatenate(kept[True])[: want[True]], np.concatenate(kept[False])[: want[False]]])
    labels = np.arange(n) < want[True]
    order = rng.permutation(n)
    return Q[order], labels[order]


@dataclass
class CollisionDataset:
    """Configurations labelled in a list of workspaces.

    ``occupancy (W, *grid)`` float32 of -1/+1, ``configs (W, n, dof)``, ``valid (W, n)`` bool.
    """

    scenario: str
    workspaces: list[Workspace]
    occupancy: np.ndarray
    configs: np.ndarray
    valid: np.ndarray
    meta: dict = field(default_factory=dict)

    def __post_init__(self):
        w = len(self.workspaces)
        if not (len(self.occupancy) == len(self.configs) == len(self.valid) == w):
            raise ValueError(
                f"dataset arrays disagree on the number of workspaces: {w} workspaces, "
                f"{len(self.occupancy)} grids, {len(self.configs)} config sets, {len(self.valid)} label sets"
            )
        if self.configs.shape[:2] != self.valid.shape:
            raise ValueError(f"configs {self.configs.shape} and labels {self.valid.shape} disagree")

    def __len__(self) -> int:
        return int(self.valid.size)

    def flat(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(workspace index (M,), configs (M, dof), valid (M,))`` with M = W * n."""
        w, n = self.valid.shape
        return np.repeat(np.arange(w), n), self.configs.reshape(w * n, -1), self.valid.reshape(-1)

    def save(self, path: str | Path) -> None:
        """Write an ``.npz`` (atomically: a temporary file, then a rename)."""
        path = Path(path)
        meta = dict(self.meta, scenario=self.scenario, workspaces=[ws.to_dict() for ws in self.workspaces])
        outputs.write_atomically(
            path,
            lambda tmp: np.savez_compressed(
                tmp, occupancy=self.occupancy, configs=self.configs, valid=self.valid, meta=np.array(json.dumps(meta))
            ),
        )

    @classmethod
    def load(cls, path: str | Path, scenario: str | None = None) -> CollisionDataset:
        """Read a dataset; a clear error for a corrupted file or another scenario's data."""
        path = Path(path)
        try:
            with np.load(path, allow_pickle=False) as data:
                arrays = {k: data[k] for k in ("occupancy", "configs", "valid", "meta")}
            meta = json.loads(str(arrays.pop("meta")))
            name, spaces = meta.pop("scenario"), [Workspace.from_dict(d) for d in meta.pop("workspaces")]
        except FileNotFoundError:
            raise
        except Exception as err:  # zipfile, zlib, KeyError, JSON, bad workspaces: the file cannot be trusted
            raise ValueError(f"{path} is not a valid dataset file (corrupted or truncated): {err}") from err
        if scenario is not None and name != scenario:
            raise ValueError(f"{path} holds data for scenario {name!r}, not {scenario!r}")
        return cls(name, spaces, arrays["occupancy"], arrays["configs"], arrays["valid"].astype(bool), meta)


def label_workspaces(
    scenario: Scenario,
    spaces: list[Workspace],
    *,
    samples_per_workspace: int,
    seed: int,
    stream: str,
    progress: bool = True,
    desc: str = "",
    balanced: bool = True,
) -> CollisionDataset:
    """Labelled samples in each workspace, drawn from ``stream_rng(seed, stream, i)``: half valid, half invalid
    (``balanced``), or uniform configurations whatever their validity (``balanced=False``)."""
    configs, valid = [], []
    for i, ws in enumerate(tqdm(spaces, desc=desc or f"labelling {scenario.name}", disable=not progress, leave=False)):
        checker, rng = exact_checker(ws, scenario.robot), stream_rng(seed, stream, i)
        if balanced:
            Q, labels = balanced_samples(checker, rng, samples_per_workspace)
        else:
            Q = scenario.robot.sample(rng, samples_per_workspace)
            labels = checker.are_valid(Q)
        configs.append(Q)
        valid.append(labels)
    occupancy = (
        np.stack([ws.occupancy() for ws in spaces]) if spaces else np.zeros((0,) + scenario.grid_shape, np.float32)
    )
    return CollisionDataset(
        scenario.name,
        list(spaces),
        occupancy,
        np.array(configs, dtype=float).reshape(len(spaces), samples_per_workspace, -1),
        np.array(valid, dtype=bool).reshape(len(spaces), samples_per_workspace),
        meta={"seed": seed, "stream": stream, "samples_per_workspace": samples_per_workspace, "balanced": balanced},
    )


def validity_blind_split(
    scenario: Scenario, unseen: CollisionDataset, *, samples_per_workspace: int | None = None, progress: bool = False
) -> CollisionDataset:
    """The paper's unseen test (§IV-A): in the workspaces of ``unseen``, uniform samples regardless of their
    validity, as many as ``scenario.plan_samples`` each (200 in 2DS, 2000 in 3DO, 400 in 3DC), labelled exactly."""
    n = scenario.plan_samples if samples_per_workspace is None else samples_per_workspace
    return label_workspaces(
        scenario,
        unseen.workspaces,
        samples_per_workspace=n,
        seed=unseen.meta.get("seed", 0),
        stream="unseen_uniform",
        progress=progress,
        desc="validity-blind unseen samples",
        balanced=False,
    )


def make_splits(
    scenario: Scenario,
    seed: int = 0,
    *,
    samples_per_workspace: int | None = None,
    n_seen: int | None = None,
    n_seen_test: int | None = None,
    n_unseen: int | None = None,
    progress: bool = True,
) -> dict[str, CollisionDataset]:
    """The paper's three splits (``train``, ``seen_test``, ``unseen_test``); counts default to the paper's."""
    n = samples_per_workspace or scenario.samples_per_workspace
    n_seen = scenario.n_seen if n_seen is None else n_seen
    n_seen_test = min(n_seen, scenario.n_seen_test if n_seen_test is None else n_seen_test)
    n_unseen = scenario.n_unseen if n_unseen is None else n_unseen
    seen = scenario.workspaces("seen", n_seen, seed)
    unseen = scenario.workspaces("unseen", n_unseen, seed)
    label = partial(label_workspaces, scenario, samples_per_workspace=n, seed=seed, progress=progress)
    return {
        "train": label(seen, stream="train_samples", desc="train samples"),
        "seen_test": label(seen[:n_seen_test], stream="test_samples", desc="seen test samples"),
        "unseen_test": label(unseen, stream="unseen_samples", desc="unseen test samples"),
    }
