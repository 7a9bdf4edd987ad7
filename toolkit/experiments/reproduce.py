"""Reproduction of the paper's Tables 1-3 and Figures 5-7 (§V), with one resumable command.

``reproduce(config, out)`` runs the stages of one run configuration
(:class:`~toolkit.experiments.config.RunConfig`):

1. data: the seen / unseen splits (:func:`toolkit.experiments.pipeline.make_splits`);
2. models: the CAE and MLP (:func:`toolkit.experiments.pipeline.train`), a checkpoint folder;
3. learning: Table 1 and Table 2 measures, and P(valid) on the unseen test set;
4. planning: every sampler, without and with prediction in turns query by query, on the paper's queries
   (:mod:`toolkit.experiments.queries`), the samplers spread over one process per core
   (:mod:`toolkit.experiments.workers`; one process when the learned checker is on a GPU). *Without* is the
   strongest exact planner and checker (the lazy PRM, the compiled checker); where Table 3's baseline is
   another (``RunConfig.baseline``: the ``paper`` preset's is Algorithm 1), that one is planned in the same
   turns too (:func:`planning_modes`); a run that names its planner (``--planner batched``) plans with it
   both ways;
5. throughput: the default exact, the python-fcl and the learned checker's speed (:mod:`toolkit.experiments.bench`;
   with ``config.device``, the learned checker and the exact one in torch on it, numpy in/out and resident);

and writes ``out/results.json`` (the contract's keys), ``out/tables.md`` (our value
next to the published one in every cell, :mod:`toolkit.experiments.tables`) and PNG
figures. Each stage's product is cached under ``out/cache``
(:mod:`toolkit.experiments.stages`), so an interrupted run resumes where it stopped
and a finished stage is not redone; each sampler's planning is a stage of its own.
:func:`finished_stages` says what a rerun will reuse.
"""

from __future__ import annotations

import os
import pickle
import time
from collections.abc import Iterable
from concurrent.futures import as_completed
from functools import partial
from pathlib import Path

import numpy as np
import torch
from tqdm.auto import tqdm

from toolkit import plots
from toolkit.experiments import bench, pipeline, queries, tables
from toolkit.experiments.config import FCL_ALIKE, FCL_BASELINES, RunConfig
from toolkit.experiments.problems import make_planner
from toolkit.experiments.stages import Stages, check_out
from toolkit.experiments.tables import BASELINE
from toolkit.experiments.workers import processes
from toolkit.geometry.collision import FCLChecker, exact_checker
from toolkit.learning import checkpoints, training
from toolkit.learning.data import SPLITS, CollisionDataset
from toolkit.learning.learned import LearnedChecker
from toolkit.planning import prm
from toolkit.planning.sampling import PAPER_SAMPLERS
from toolkit.util import outputs, plugins


def finished_stages(out: str | Path) -> list[str]:
    """The stages whose products are cached in ``out/cache``, in the order they run: what a rerun reuses."""
    cache = Path(out) / "cache"
    done = [
        name
        for name, files in (
            ("data", _data_paths(cache).values()),
            ("models", [cache / "checkpoint"]),
            ("learning", [cache / "learning.json"]),
        )
        if all(p.exists() for p in files)
    ]
    order = {f"planning_{s}": i for i, s in enumerate(PAPER_SAMPLERS)}  # the paper's four in its order, then others
    planned = sorted((p.stem for p in cache.glob("planning_*.json")), key=lambda name: (order.get(name, 4), name))
    return done + planned + (["throughput"] if (cache / "throughput.json").exists() else [])


def _data_paths(cache: Path) -> dict[str, Path]:
    return {name: cache / f"data_{name}.npz" for name in SPLITS}


def data_stage(stages: Stages, config: RunConfig) -> dict[str, CollisionDataset]:
    """Stage 1: the run's splits, made once and kept as npz files."""
    paths = _data_paths(stages.cache)
    if all(p.exists() for p in paths.values()):
        try:
            return {name: CollisionDataset.load(p, config.scenario.name) for name, p in paths.items()}
        except ValueError as err:
            raise ValueError(f"{err}; delete it to compute the data stage again") from None
    began = time.perf_counter()
    splits = pipeline.make_splits(config)
    for name, dataset in splits.items():
        dataset.save(paths[name])
    stages.took("data", time.perf_counter() - began)
    return splits


def models_stage(stages: Stages, config: RunConfig, splits: dict[str, CollisionDataset]) -> training.TrainedModels:
    """Stage 2: the CAE and MLP, trained once and kept as a checkpoint folder (the CAE always: Table 1 reports it)."""
    folder = stages.cache / "checkpoint"
    if folder.exists():
        return checkpoints.load_models(
            folder, config.scenario, remedy=f"delete {folder} to train again (the models stage)"
        )
    began = time.perf_counter()
    models = pipeline.train(config, splits, cae=True)
    checkpoints.save_checkpoint(models, folder)  # the folder appears whole or not at all
    stages.took("models", time.perf_counter() - began)
    return models


def learning_scores(models: training.TrainedModels, splits: dict[str, CollisionDataset]) -> dict:
    """Stage 3: Tables 1 and 2's measures, and P(valid) of the unseen test samples (for the threshold figure)."""
    scores = training.evaluate(models, splits)
    unseen = splits["unseen_test"]
    scores["unseen_probability"] = training.probabilities(models.predictor, unseen).reshape(-1).tolist()
    scores["unseen_valid"] = unseen.valid.reshape(-1).tolist()
    scores["threshold"] = models.threshold
    return scores


def planning_stage(stages: Stages, config: RunConfig, models: training.TrainedModels) -> dict:
    """Stage 4: every sampler without and with prediction on the query set, the two in turns query by query.

    Samplers not yet in the cache go to ``config.workers`` processes (default one per
    core, each timing its own queries; each receives the planning modes built here, with
    the models trained above) when there are several; each sampler's results are cached
    as soon as they arrive.
    """
    todo = [s for s in config.samplers if not stages.has(f"planning_{s}")]
    # built here, so a worker plans them as they are; sent as plain pickled bytes (torch would otherwise share the
    # tensors through file descriptors, and a worker stopped mid-transfer leaves a traceback in the parent)
    job = partial(plan_sampler, config, pickle.dumps(planning_modes(config, models)))
    workers = config.workers or (1 if on_gpu(config) else os.cpu_count() or 1)  # one GPU: one process times it
    with (
        tqdm(total=len(todo), desc=f"planning {config.scenario.name}", disable=not stages.progress, leave=False) as bar,
        processes(min(workers, len(todo))) as pool,
    ):
        runs: Iterable[tuple[str, dict, float]]
        if pool is None:
            runs = map(job, todo)  # one after another, in this process
        else:  # as each finishes
            runs = (future.result() for future in as_completed([pool.submit(job, s) for s in todo]))
        for sampler, summary, seconds in runs:
            stages.save(f"planning_{sampler}", summary, seconds)
            bar.update()
    return {s: stages.load(f"planning_{s}") for s in config.samplers}


def plan_sampler(config: RunConfig, pickled_modes: bytes, sampler: str) -> tuple[str, dict, float]:
    """One sampler over the query set, the pickled :func:`planning_modes` in turns (also in a worker process, which
    first imports ``config.imports`` to register what the parent registered, e.g. a sampler): the sampler,
    ``{"without": summary, "with": summary}`` (and ``"baseline"``) and seconds."""
    began = time.perf_counter()
    for module in config.imports:
        plugins.import_module(module)
    scenario = config.scenario
    n_workspaces, per_workspace = config.query_counts()
    query_set = queries.make_queries(scenario, seed=config.seed, n_workspaces=n_workspaces, per_workspace=per_workspace)
    modes: dict[str, queries.Mode] = pickle.loads(pickled_modes)  # the parent's own, pickled above
    runs = queries.run_interleaved(scenario, query_set, sampler, modes, seed=config.seed)
    return sampler, {mode: runs[mode][1] for mode in modes}, time.perf_counter() - began


def on_gpu(config: RunConfig) -> bool:
    """Whether the run's learned checker computes on a GPU (``config.device``)."""
    return config.device is not None and torch.device(config.device).type == "cuda"


def planning_modes(config: RunConfig, models: training.TrainedModels) -> dict[str, queries.Mode]:
    """What the planning stage plans, in turns: ``without`` prediction, the strongest exact planner and checker (the
    lazy PRM with the default exact checker); ``with``, the planner paired with the run's recipe
    (:mod:`toolkit.experiments.planners`) with the learned checker deciding samples, on ``config.device``; and,
    when Table 3's baseline (``config.baseline``) is the paper's, ``baseline``: Algorithm 1 without prediction,
    with the default exact checker (``paper``) or python-fcl's (``paper-fcl``; ``paper-fcl-alike``: ``with`` checks its
    edges and paths with python-fcl too, so only prediction differs between them). A run that names its planner
    (``config.planner``, e.g. ``batched``) plans ``without`` and ``with`` with it alike. Each mode names its
    planner."""
    scenario, settings, named = config.scenario, config.planner_settings(), config.planner
    learned = partial(LearnedChecker, models=models, device=config.device)
    with_exact = FCLChecker if config.baseline == FCL_ALIKE else exact_checker
    modes = {
        "without": queries.Mode(planner=make_planner(scenario, named or prm.DEFAULT, **settings)),
        "with": queries.Mode(
            learned, exact=with_exact, planner=make_planner(scenario, named, preset=config.preset, **settings)
        ),
    }
    if config.baseline != "best":
        exact = FCLChecker if config.baseline in FCL_BASELINES else exact_checker
        modes[BASELINE] = queries.Mode(exact=exact, planner=make_planner(scenario, "paper", **settings))
    return modes


def improvement(planning: dict, key: str) -> dict[str, float]:
    """Table 3's measure per sampler: ``(without - with) / without`` of the mean ``key`` time, "without" being
    Table 3's baseline (:func:`toolkit.experiments.tables.table_3_mode`)."""
    return {s: 1.0 - planning[s]["with"][key] / planning[s][tables.table_3_mode(planning[s])][key] for s in planning}


def reproduce(config: RunConfig, out: str | Path) -> dict:
    """Run every stage for one run configuration; write ``results.json``, ``tables.md`` and figures into ``out``."""
    out = Path(out)
    settings = config.settings()
    stages = Stages(out, settings, config.progress)
    began = time.perf_counter()
    splits = data_stage(stages, config)
    models = models_stage(stages, config, splits)
    learning = stages.json("learning", lambda: learning_scores(models, splits))
    planning = planning_stage(stages, config, models)
    throughput = stages.json(
        "throughput",
        lambda: bench.throughput(
            config.scenario, models, seed=config.seed, repeats=config.throughput_repeats(), device=config.device
        ),
    )
    results = dict(
        settings,
        cae=learning["cae"],
        mlp=learning["mlp"],
        threshold=learning["threshold"],
        planning=planning,
        throughput=throughput,
        improvement={"sampling": improvement(planning, "sampling_s"), "total": improvement(planning, "total_s")},
        stage_seconds=stages.seconds,
        recomputed=stages.recomputed,
        wall_seconds=time.perf_counter() - began,
        versions={"torch": torch.__version__, "numpy": np.__version__},
    )
    outputs.write_json(out / "results.json", results)
    (out / "tables.md").write_text(tables.tables_markdown(results))
    _figures(out, config, models, splits, learning, planning)
    return results


def _figures(out: Path, config: RunConfig, models, splits, learning: dict, planning: dict) -> None:
    grids = {"seen": splits["seen_test"].occupancy[0], "unseen": splits["unseen_test"].occupancy[0]}
    with torch.no_grad():
        decoded = {k: models.predictor.cae(torch.as_tensor(g)[None])[0].numpy() for k, g in grids.items()}
    figures = {
        "cae_reconstruction.png": plots.cae_reconstruction(grids, decoded),
        "planning_times.png": plots.planning_times(planning, f"{config.scenario.title}: time per query"),
        "mlp_threshold.png": plots.threshold_sweep(
            np.array(learning["unseen_probability"]), np.array(learning["unseen_valid"]), learning["threshold"]
        ),
    }
    for name, fig in figures.items():
        fig.savefig(out / name, dpi=110)


def reproduce_many(configs: list[RunConfig], out: str | Path) -> dict[str, dict]:
    """:func:`reproduce` for several scenarios into ``out/<scenario>``, plus ``out/tables.md`` with a row per scenario.

    Every scenario's folder is checked before the first one starts."""
    out = Path(out)
    names = {config.scenario.name for config in configs}
    if out.is_dir() and (other := sorted(p.name for p in out.iterdir() if p.name not in {*names, "tables.md"})):
        raise ValueError(
            f"--out {out} holds {other}, not the scenario folders of a reproduction; choose a new or empty folder"
        )
    for config in configs:
        check_out(out / config.scenario.name, config.settings())
    results = {config.scenario.name: reproduce(config, out / config.scenario.name) for config in configs}
    (out / "tables.md").write_text(tables.summary_markdown(list(results.values())))
    return results
