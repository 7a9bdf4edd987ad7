"""Reproduction of the paper's Tables 1-3 and Figures 5-7 (§V), with one resumable command.

``reproduce(scenario, preset, quick, seed, out)`` runs the stages

1. data: the seen / unseen splits (:mod:`toolkit.learning.data`);
2. models: the CAE and MLP (:mod:`toolkit.learning.training`), a checkpoint folder;
3. learning: Table 1 and Table 2 measures, and P(valid) on the unseen test set;
4. planning: every sampler, without and with prediction in turns query by query, on the paper's queries
   (:mod:`toolkit.queries`), the four samplers spread over one process per core;
5. throughput: exact and learned checker speed (:mod:`toolkit.experiments.bench`);

and writes ``out/results.json`` (the contract's keys), ``out/tables.md`` (our value
next to the published one in every cell) and PNG figures. Each stage's product is
cached under ``out/cache`` and written atomically, so an interrupted run resumes
where it stopped and a finished stage is not redone; each sampler's planning is a
stage of its own. ``out`` is checked before any work (:func:`check_out`), and an
interruption (Ctrl-C, or SIGTERM turned into one by ``toolkit``) stops the planning
processes before it goes on: nothing is left running, and :func:`finished_stages`
says what a rerun will reuse.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import contextmanager
from functools import partial
from pathlib import Path

import numpy as np
import torch
from tqdm.auto import tqdm

from toolkit import plots, scenarios
from toolkit.experiments import bench, paper_numbers
from toolkit.experiments.paper_numbers import SAMPLERS
from toolkit.learning import checkpoints, training
from toolkit.learning.data import SPLITS, CollisionDataset
from toolkit.learning.learned import LearnedChecker
from toolkit.planning import queries
from toolkit.util import outputs

MODES = ("without", "with")
QUICK_QUERIES = {"2ds": (2, 2), "3do": (1, 2), "3dc7": (3, 1), "3dc9": (3, 1)}  # (workspaces, pairs each)
QUICK_PLAN_SAMPLES = {"3do": 400}  # |S| in quick runs, where the paper's would take minutes
QUICK_MAX_ROUNDS = 5  # quick models predict poorly: give up sooner than a full run would
STAGES = ("data", "models", "learning", *(f"planning_{s}" for s in SAMPLERS), "throughput")


class Stages:
    """The cache folder of one run: each stage's file is written once, atomically, then reused.

    ``seconds`` holds how long each stage took when it was computed (kept in the cache,
    so a resumed run still reports them); ``recomputed`` the stages this run computed.
    """

    def __init__(self, out: Path, settings: dict, progress: bool):
        check_out(out, settings)
        self.cache = out / "cache"
        self.cache.mkdir(exist_ok=True)
        self.progress = progress
        outputs.write_json(self.cache / "settings.json", settings)
        self._seconds_file = self.cache / "stage_seconds.json"
        self.seconds: dict[str, float] = (outputs.read_json(self._seconds_file, "delete it (the cached stages' "
                                                            "times will read n/a)") if self._seconds_file.exists() else {})
        self.recomputed: list[str] = []

    def took(self, name: str, seconds: float) -> None:
        """Record that stage ``name`` was computed in ``seconds``."""
        self.seconds[name] = seconds
        self.recomputed.append(name)
        outputs.write_json(self._seconds_file, self.seconds)

    def has(self, name: str) -> bool:
        return (self.cache / f"{name}.json").exists()

    def load(self, name: str) -> dict:
        return outputs.read_json(self.cache / f"{name}.json", "delete it to compute that stage again")

    def save(self, name: str, value: dict, seconds: float) -> None:
        """Store stage ``name``'s JSON ``value`` atomically, computed in ``seconds`` (recorded first: a run
        stopped between the two computes the stage again and records its time again)."""
        self.took(name, seconds)
        outputs.write_json(self.cache / f"{name}.json", value)

    def json(self, name: str, compute, current=None) -> dict:
        """The cached JSON ``name``, or ``compute()`` written atomically. A cached value that ``current(value)``
        finds out of date (written by an older toolkit, without a measure this one reports) is computed again,
        and the run says so."""
        if self.has(name):
            cached = self.load(name)
            if current is None or current(cached):
                return cached
            tqdm.write(f"{self.cache / name}.json predates this toolkit's measures: computing the {name} stage again")
        began = time.perf_counter()
        value = compute()
        self.save(name, value, time.perf_counter() - began)
        return value


def check_out(out: Path, settings: dict) -> None:
    """Refuse, before any work, an output folder that cannot take this run: a file, a place that cannot be
    written, a folder holding something else (a checkpoint, other files), or a run with other settings. A
    folder holding a run with the same settings is what resuming needs."""
    recorded = out / "cache" / "settings.json"
    if out.is_dir() and not recorded.exists() and any(out.iterdir()):
        held = "a checkpoint of `toolkit train`" if (out / checkpoints.META).exists() else "other files"
        raise ValueError(f"--out {out} holds {held}, not a reproduction; choose a new or empty folder")
    outputs.writable_folder(out, "--out")
    if recorded.exists():
        previous = outputs.read_json(recorded, f"delete {out} to start again")
        if previous != settings:
            raise ValueError(f"{out} holds a run with other settings {previous}; "
                             f"choose another --out, or delete {out} to start again")


def finished_stages(out: str | Path) -> list[str]:
    """The stages of :data:`STAGES` whose products are cached in ``out/cache``: what a rerun reuses."""
    cache = Path(out) / "cache"
    files = {"data": list(_data_paths(cache).values()), "models": [cache / "checkpoint"]}
    return [name for name in STAGES if all(p.exists() for p in files.get(name, [cache / f"{name}.json"]))]


def _data_paths(cache: Path) -> dict[str, Path]:
    return {name: cache / f"data_{name}.npz" for name in SPLITS}


def _splits(stages: Stages, scenario, preset: str, seed: int, quick: bool) -> dict[str, CollisionDataset]:
    paths = _data_paths(stages.cache)
    if all(p.exists() for p in paths.values()):
        try:
            return {name: CollisionDataset.load(p, scenario.name) for name, p in paths.items()}
        except ValueError as err:
            raise ValueError(f"{err}; delete it to compute the data stage again") from None
    began = time.perf_counter()
    splits = training.preset_splits(scenario, preset, seed, quick=quick, progress=stages.progress)
    for name, dataset in splits.items():
        dataset.save(paths[name])
    stages.took("data", time.perf_counter() - began)
    return splits


def _models(stages: Stages, scenario, preset: str, splits, seed: int, quick: bool) -> training.TrainedModels:
    folder = stages.cache / "checkpoint"
    if folder.exists():
        return checkpoints.load_models(folder, scenario.name, remedy=f"delete {folder} to train again (the models "
                                                                     "stage)")
    began = time.perf_counter()
    models = training.train_models(scenario, preset, splits, seed, progress=stages.progress, quick=quick,
                                   cae=True)  # Table 1 reports the CAE, used or not
    checkpoints.save_checkpoint(models, folder)  # the folder appears whole or not at all
    stages.took("models", time.perf_counter() - began)
    return models


def _learning(models: training.TrainedModels, splits) -> dict:
    scores = training.evaluate(models, splits)
    unseen = splits["unseen_test"]
    scores["unseen_probability"] = training.probabilities(models.predictor, unseen).reshape(-1).tolist()
    scores["unseen_valid"] = unseen.valid.reshape(-1).tolist()
    scores["threshold"] = models.threshold
    return scores


def _planning(stages: Stages, scenario, models, seed: int, quick: bool, workers: int) -> dict:
    """Every sampler without and with prediction on the query set, the two in turns query by query. Samplers
    not yet in the cache go to ``workers`` processes (one per core, each timing its own queries) when there
    are several; each sampler's results are cached as soon as they arrive."""
    todo = [s for s in SAMPLERS if not stages.has(f"planning_{s}")]
    job = partial(_planning_run, scenario.name, str(stages.cache / "checkpoint"), models.preset.planner_options(), seed, quick)
    with (tqdm(total=len(todo), desc=f"planning {scenario.name}", disable=not stages.progress, leave=False) as bar,
          _processes(min(workers, len(todo))) as pool):
        if pool is None:
            runs = map(job, todo)  # one after another, in this process
        else:  # as each finishes
            runs = (future.result() for future in as_completed([pool.submit(job, s) for s in todo]))
        for sampler, summary, seconds in runs:
            stages.save(f"planning_{sampler}", summary, seconds)
            bar.update()
    return {s: stages.load(f"planning_{s}") for s in SAMPLERS}


@contextmanager
def _processes(n: int):
    """``n`` fresh worker processes (None when ``n`` <= 1: work in this process).

    On any exception, Ctrl-C included, the workers are killed before it goes on: a
    ``ProcessPoolExecutor`` alone would wait for every task to finish first.
    """
    if n <= 1:
        yield None
        return
    spawn = multiprocessing.get_context("spawn")  # fresh interpreters: no forked torch thread pools
    pool = ProcessPoolExecutor(n, mp_context=spawn, initializer=_worker_start)
    try:
        yield pool
    except BaseException:
        if hasattr(pool, "terminate_workers"):  # Python >= 3.14
            pool.terminate_workers()
        else:  # the same by hand: the pool's own table of its worker processes
            for process in list((pool._processes or {}).values()):
                process.terminate()
        raise
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def _worker_start() -> None:
    """In each worker: leave Ctrl-C to the parent (which stops the workers), and exit if the parent dies
    without doing so (SIGKILL, a crash) rather than wait for work forever."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    parent = os.getppid()

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, daemon=True).start()


def _planning_run(scenario_name: str, checkpoint: str, planner: dict, seed: int, quick: bool,
                  sampler: str) -> tuple[str, dict, float]:
    """One sampler over the query set, without and with prediction in turns (also in a worker process):
    the sampler, ``{"without": summary, "with": summary}`` and seconds."""
    began = time.perf_counter()
    scenario = scenarios.get(scenario_name)
    counts = QUICK_QUERIES[scenario.name] if quick else (None, None)
    query_set = queries.make_queries(scenario, seed, *counts)
    n_samples = QUICK_PLAN_SAMPLES.get(scenario.name, scenario.plan_samples) if quick else scenario.plan_samples
    options = queries.default_options(scenario, n_samples=n_samples, **planner,
                                      **({"max_rounds": QUICK_MAX_ROUNDS} if quick else {}))
    models = checkpoints.load_models(checkpoint, scenario.name)
    factories = {"without": None, "with": partial(LearnedChecker, models=models)}
    runs = queries.run_interleaved(scenario, query_set, sampler, factories, options, seed)
    return sampler, {mode: runs[mode][1] for mode in MODES}, time.perf_counter() - began


def run_settings(scenario: str, preset: str, quick: bool, seed: int) -> dict:
    """What makes one run: a folder holding another run's cache is refused (its stages do not apply)."""
    return {"scenario": scenario, "preset": preset, "quick": bool(quick), "seed": int(seed)}


def improvement(planning: dict, key: str) -> dict[str, float]:
    """Table 3's measure per sampler: ``(without - with) / without`` of the mean ``key`` time."""
    return {s: 1.0 - planning[s]["with"][key] / planning[s]["without"][key] for s in SAMPLERS}


def reproduce(scenario_name: str, preset: str = "paper", quick: bool = False, seed: int = 0,
              out: str | Path = "results", progress: bool = True, workers: int | None = None) -> dict:
    """Run every stage for one scenario; write ``results.json``, ``tables.md`` and figures into ``out``.

    ``workers``: processes for the planning runs (default: one per core; 1 plans in this process).
    """
    scenario = scenarios.get(scenario_name)
    out = Path(out)
    settings = run_settings(scenario.name, preset, quick, seed)
    stages = Stages(out, settings, progress)
    began = time.perf_counter()
    splits = _splits(stages, scenario, preset, seed, quick)
    models = _models(stages, scenario, preset, splits, seed, quick)
    learning = stages.json("learning", lambda: _learning(models, splits),
                           current=lambda cached: "unseen_uniform" in cached["mlp"])  # older caches lack the paper's unseen test
    planning = _planning(stages, scenario, models, seed, quick, workers or os.cpu_count() or 1)
    throughput = stages.json("throughput", lambda: bench.throughput(scenario, preset, seed=seed,
                                                                   repeats=3 if quick else 7))
    results = dict(settings, cae=learning["cae"], mlp=learning["mlp"], threshold=learning["threshold"],
                   planning=planning, throughput=throughput,
                   improvement={"sampling": improvement(planning, "sampling_s"), "total": improvement(planning, "total_s")},
                   stage_seconds=stages.seconds, recomputed=stages.recomputed, wall_seconds=time.perf_counter() - began,
                   versions={"torch": torch.__version__, "numpy": np.__version__})
    outputs.write_json(out / "results.json", results)
    (out / "tables.md").write_text(tables_markdown(results))
    _figures(out, scenario, models, splits, learning, planning)
    return results


def _figures(out: Path, scenario, models, splits, learning: dict, planning: dict) -> None:
    grids = {"seen": splits["seen_test"].occupancy[0], "unseen": splits["unseen_test"].occupancy[0]}
    with torch.no_grad():
        decoded = {k: models.predictor.cae(torch.as_tensor(g)[None])[0].numpy() for k, g in grids.items()}
    figures = {
        "cae_reconstruction.png": plots.cae_reconstruction(grids, decoded),
        "planning_times.png": plots.planning_times(planning, f"{scenario.title}: time per query"),
        "mlp_threshold.png": plots.threshold_sweep(np.array(learning["unseen_probability"]),
                                                   np.array(learning["unseen_valid"]), learning["threshold"]),
    }
    for name, fig in figures.items():
        fig.savefig(out / name, dpi=110)


# -- tables -----------------------------------------------------------------------------

def _pct(x: float) -> str:
    return "n/a" if x is None or not np.isfinite(x) else f"{100 * x:.0f}%"


def _time(mean_std) -> str:
    mean, std = mean_std
    return f"{mean:.3g} ± {std:.2g}"


def _row(cells: list[str]) -> str:
    return "| " + " | ".join(cells) + " |"


def _table(header: list[str], rows: list[list[str]]) -> list[str]:
    return [_row(header), _row(["---"] * len(header))] + [_row(r) for r in rows]


def _ours_paper(ours: float, paper: float) -> str:
    return f"**{_pct(ours)}** / {_pct(paper)}"


def paper_tables(runs: list[dict]) -> list[str]:
    """Tables 1-3 of the paper and the times behind Table 3, one row per run (``results.json`` dicts),
    our value next to the published one (``ours / paper``) in every cell."""
    table1 = [[r["scenario"]] + [_ours_paper(r["cae"][k], paper_numbers.CAE[r["scenario"]][k]) for k in ("seen_acc", "unseen_acc")]
              + [f"{_pct(r['cae']['seen_all_free'])} / {_pct(r['cae']['unseen_all_free'])}"]
              if "seen_acc" in r["cae"] else  # a checkpoint whose CAE was left untrained (toolkit train without --cae)
              [r["scenario"], "not trained", "not trained", "n/a"] for r in runs]
    table2 = [[r["scenario"]] + [_ours_paper(r["mlp"][s][m], paper_numbers.MLP[r["scenario"]][p][m])
                                 for s, p in (("seen", "seen"), ("unseen_uniform", "unseen")) for m in ("acc", "tpr", "tnr")]
              + [_pct(r["mlp"]["unseen_uniform"]["always_valid"])]
              + [f"**{_pct(r['mlp']['unseen'][m])}**" for m in ("acc", "tpr", "tnr")]
              + [_pct(r["mlp"]["unseen"].get("always_valid", 0.5))]
              if "unseen_uniform" in r["mlp"] else  # results.json of a run older than the paper's unseen test
              [r["scenario"]] + [_ours_paper(r["mlp"]["seen"][m], paper_numbers.MLP[r["scenario"]]["seen"][m])
                                 for m in ("acc", "tpr", "tnr")] + ["n/a"] * 4
              + [f"**{_pct(r['mlp']['unseen'][m])}**" for m in ("acc", "tpr", "tnr")] + ["50%"] for r in runs]
    table3 = [[r["scenario"]] + [_ours_paper(r["improvement"][k][s], paper_numbers.IMPROVEMENT[r["scenario"]][k][s])
                                 for k in ("sampling", "total") for s in SAMPLERS] for r in runs]
    times = []
    for r in runs:
        for s in SAMPLERS:
            planning, published = r["planning"][s], paper_numbers.TIMES[r["scenario"]]
            cells = [f"**{_time((planning[m][key], planning[m].get(key + '_std', 0.0)))}** / {_time(published[key][s][i])}"
                     for key in ("sampling_s", "total_s") for i, m in enumerate(MODES)]
            times.append([r["scenario"], s] + cells + [" / ".join(_pct(planning[m][rate]) for m in MODES)
                                                        for rate in ("success_rate", "path_valid_rate")])
    thresholds = ", ".join(f"{r['scenario']} {r['threshold']:.2f}" for r in runs)
    return (["## Table 1: CAE reconstruction accuracy", ""]
            + _table(["", "Seen", "Unseen", "all free: Seen / Unseen"], table1)
            + ["", "*All free*: the accuracy of a CAE that ignores its input and answers \"free\" everywhere."]
            + ["", "## Table 2: MLP accuracy, TPR, TNR", ""]
            + _table(["", "Seen Acc", "Seen TPR", "Seen TNR", "Unseen Acc", "Unseen TPR", "Unseen TNR",
                      "Unseen always valid", "Balanced unseen Acc", "TPR", "TNR", "always valid"], table2)
            + ["", "*Seen*: balanced samples (half valid) in training workspaces. *Unseen*: as the paper (§IV-A), "
               "validity-blind samples in unseen workspaces (2DS 200, 3DO 2000, 3DC 400 each); *always valid*: the "
               "accuracy of answering \"valid\" on the same samples. *Balanced unseen*: half-valid samples in the same "
               "workspaces (ours only; the paper reports none). n/a: results of a run older than the validity-blind "
               "test (run the same `toolkit reproduce` again to add it).",
               "", f"Decision threshold on P(valid): {thresholds}.", "",
               "## Table 3: time improvement ratio (without − with) / without", ""]
            + _table([""] + [f"Sampling {s}" for s in SAMPLERS] + [f"Total {s}" for s in SAMPLERS], table3)
            + ["", "## Times behind Table 3 (seconds per query, mean ± std; ours / paper)", ""]
            + _table(["", "sampler", "sampling without", "sampling with", "total without", "total with",
                      "success without / with", "paths valid without / with"], times))


def median_ratios(runs: list[dict]) -> list[str]:
    """Per sampler, the median time per query with prediction over the median without (n/a in older results)."""
    def ratio(planning: dict, key: str) -> str:
        with_, without = (planning[m].get(key + "_median") for m in ("with", "without"))
        return f"{with_ / without:.2f}" if with_ is not None and without else "n/a"

    rows = [[r["scenario"]] + [ratio(r["planning"][s], key) for key in ("sampling_s", "total_s") for s in SAMPLERS]
            for r in runs]
    return (["## Time with / without prediction, medians over the queries", ""]
            + _table([""] + [f"Sampling {s}" for s in SAMPLERS] + [f"Total {s}" for s in SAMPLERS], rows))


def run_costs(runs: list[dict]) -> list[str]:
    """Checker throughput and the seconds each stage took, one row per run."""
    rows = []
    for r in runs:
        t, seconds = r["throughput"], r["stage_seconds"]
        planning = sum(seconds.get(f"planning_{s}", 0.0) for s in SAMPLERS)  # not an older cache's stage names
        rows.append([r["scenario"], f"{t['exact_cfg_per_s']:,.0f}", f"{t['learned_cfg_per_s']:,.0f}", f"{t['ratio']:.3g}"]
                    + [f"{seconds[k]:.0f}" if k in seconds else "n/a" for k in ("data", "models")]
                    + [f"{planning:.0f}"])
    return (["## Checker throughput (configurations per second, median) and stage times (seconds)", "",
             "Each stage's time when it was computed (a resumed run keeps them). *planning*: the 4 samplers' runs "
             "(each query without and with prediction in turn) added up (by default in parallel, one process per core; "
             "`--workers`).", ""]
            + _table(["", "exact cfg/s", "learned cfg/s", "learned / exact", "data s", "models s", "planning s"], rows))


def tables_markdown(results: dict) -> str:
    """One run's tables: the paper's Tables 1-3 with the published numbers beside ours, and its costs."""
    title = (f"# {scenarios.get(results['scenario']).title} — preset `{results['preset']}`"
             f"{' (quick)' if results['quick'] else ''}, seed {results['seed']}")
    return "\n".join([title, "", "Every cell: **ours** / paper.", ""] + paper_tables([results]) + [""]
                     + median_ratios([results]) + [""] + run_costs([results]) + [""])


def summary_markdown(runs: list[dict]) -> str:
    """Several scenarios' tables in one: a row per scenario, as in the paper."""
    first = runs[0]
    title = f"# Preset `{first['preset']}`{' (quick)' if first['quick'] else ''}, seed {first['seed']}"
    return "\n".join([title, "", "Every cell: **ours** / paper.", ""] + paper_tables(runs) + [""]
                     + median_ratios(runs) + [""] + run_costs(runs) + [""])


def reproduce_many(names: list[str], preset: str = "paper", quick: bool = False, seed: int = 0,
                   out: str | Path = "results", progress: bool = True, workers: int | None = None) -> dict[str, dict]:
    """:func:`reproduce` for several scenarios into ``out/<scenario>``, plus ``out/tables.md`` with a row per scenario.

    Every scenario's folder is checked before the first one starts."""
    out = Path(out)
    if out.is_dir() and (other := sorted(p.name for p in out.iterdir() if p.name not in {*scenarios.SCENARIOS, "tables.md"})):
        raise ValueError(f"--out {out} holds {other}, not the scenario folders of a reproduction; choose a new or "
                         "empty folder")
    for name in names:
        check_out(out / name, run_settings(name, preset, quick, seed))
    results = {name: reproduce(name, preset, quick, seed, out / name, progress, workers) for name in names}
    (out / "tables.md").write_text(summary_markdown(list(results.values())))
    return results
