"""What each sub-command of ``toolkit`` does: read its arguments, build one run configuration, call the library.

Nothing here computes what the library does not also offer from Python: ``toolkit
train`` is :func:`toolkit.experiments.pipeline.train_and_save` of a
:class:`~toolkit.experiments.config.RunConfig`, ``toolkit reproduce`` is
:func:`toolkit.experiments.reproduce.reproduce` of one, and so on. Each command checks
where it will write before it starts. :data:`KEPT` says, per command, what an
interrupted run leaves behind.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np

from toolkit import scenarios
from toolkit.experiments.config import RunConfig


def _config(args: argparse.Namespace, scenario: str, **settings) -> RunConfig:
    """The run configuration of a command's arguments (the modules it imported included, for worker processes)."""
    return RunConfig.create(
        scenario,
        getattr(args, "preset", "paper"),
        seed=args.seed,
        quick=getattr(args, "quick", False),
        imports=tuple(args.imports),
        **settings,
    )


def cmd_bench(args: argparse.Namespace) -> int:
    from toolkit.experiments import bench, versus_ompl
    from toolkit.learning import checkpoints, presets

    if args.crossover:
        return _bench_crossover(args)
    if args.scenario is None:
        raise ValueError("--scenario is needed (but with --crossover): one of the scenarios in `toolkit --help`")
    if (args.option or args.planner) and not args.checkpoint:
        raise ValueError(
            "--planner and --option choose the planner that --checkpoint's runs plan with: add --checkpoint DIR"
        )
    scenario = scenarios.get(args.scenario)
    if args.profile:
        from toolkit.experiments import profile

        profiled = profile.profile(scenario, n_queries=args.queries or 10, seed=args.seed)
        print(json.dumps(profiled) if args.json else profile.markdown(profiled))
        return 0
    models = checkpoints.load_models(args.checkpoint, scenario) if args.checkpoint else None
    if args.vs_ompl:
        try:
            raced = versus_ompl.race_seeds(
                scenario,
                n_queries=args.queries or 30,
                seeds=args.seeds,
                models=models,
                ompl_seconds=args.ompl_seconds,
                ompl_planners=args.ompl_planners,
                paper_baseline=args.paper_baseline,
            )
        except ImportError as missing:  # ompl is an optional extra
            raise ValueError(str(missing)) from None
        print(json.dumps(raced) if args.json else versus_ompl.race_seeds_markdown(scenario, raced))
        return 0
    timed = models or bench.untrained_models(scenario, presets.get(args.preset), seed=args.seed)
    device = bench.usable_device(args.device)
    result: dict = {
        "scenario": scenario.name,
        **bench.throughput(scenario, timed, batch=args.batch, seed=args.seed, device=device),
    }
    result["edges"] = bench.edge_checks(scenario, seed=args.seed)
    if models is not None:
        result["planning"] = bench.planning_ratios(
            scenario,
            models,
            n_workspaces=args.workspaces,
            per_workspace=args.pairs,
            seed=args.seed,
            samplers=args.samplers,
            overrides=dict(args.option),
            planner=args.planner,
        )
        result["planning_options"] = dict(args.option, **({"planner": args.planner} if args.planner else {}))
    print(json.dumps(result) if args.json else "\n".join(f"{k}: {v}" for k, v in result.items()))
    return 0


def _bench_crossover(args: argparse.Namespace) -> int:
    """`toolkit bench --crossover`: the sweep, printed (JSON or markdown), and written to ``--out`` with its figure."""
    from toolkit import plots
    from toolkit.cli.bench_parser import CROSSOVER_SCENARIO
    from toolkit.experiments import crossover
    from toolkit.learning import presets
    from toolkit.util import outputs

    out = outputs.writable_folder(args.out, "--out") if args.out else None  # before minutes of timing
    scenario = scenarios.get(args.scenario or CROSSOVER_SCENARIO)
    recipe = presets.get(args.preset)
    if args.device is not None:  # the batch, obstacles and links swept on one device
        from toolkit.experiments import bench, on_device

        device = bench.usable_device(args.device)
        assert device is not None  # (a device named is a device returned)
        found = on_device.one_device(
            scenario, recipe, device=device, variables=args.variables, quick=args.quick, seed=args.seed
        )
        if out is not None:
            outputs.write_json(out / "crossover_device.json", found)
        print(json.dumps(found) if args.json else on_device.markdown(found))
        return 0
    results = crossover.crossover(scenario, recipe, seed=args.seed, quick=args.quick, variables=args.variables)
    if out is not None:
        outputs.write_json(out / "crossover.json", results)
        plots.crossover(results).savefig(out / "crossover.png", dpi=110)
    print(json.dumps(results) if args.json else crossover.markdown(results))
    return 0


def cmd_train(args: argparse.Namespace) -> int:
    from toolkit.experiments import pipeline
    from toolkit.experiments.bench import usable_device
    from toolkit.learning import checkpoints

    checkpoints.check_destination(args.out, overwrite=args.force)  # before minutes of training, not after
    changes = {k: v for k, v in (("cae_epochs", args.cae_epochs), ("mlp_epochs", args.mlp_epochs)) if v is not None}
    config = _config(args, args.scenario, device=usable_device(args.device), **changes)
    models, scores, folder = pipeline.train_and_save(config, args.out, cae=args.cae or None, overwrite=args.force)
    print(json.dumps({"checkpoint": str(folder), "threshold": models.threshold, **scores}))
    return 0


def cmd_plan(args: argparse.Namespace) -> int:
    from toolkit.experiments import problems

    if args.predict and not args.checkpoint:
        raise ValueError("--predict needs --checkpoint DIR (a folder written by `toolkit train`)")
    scenario = scenarios.get(args.scenario)
    checker = None
    if args.predict:
        from functools import partial

        from toolkit.experiments.bench import usable_device
        from toolkit.learning import checkpoints, learned

        device = usable_device(args.device)  # before the checkpoint is read
        models = checkpoints.load_models(args.checkpoint, scenario)
        checker = partial(learned.LearnedChecker, models=models, device=device)
    task = problems.build(
        scenario, seed=args.seed, sampler=args.sampler, planner=args.planner, checker=checker, **dict(args.option)
    )
    result = task.solve(np.random.default_rng(args.seed))
    out = {
        "scenario": scenario.name,
        "sampler": args.sampler,
        "planner": result.planner,
        "params": dataclasses.asdict(task.planner.params),
        "predict": task.problem.predicts,
        "seed": args.seed,
        "success": result.success,
        "path": result.path.tolist(),
        "stats": result.stats,
        "start": task.query.start.tolist(),
        "goal": task.query.goal.tolist(),
        "workspace": task.query.workspace.to_dict(),
    }
    if args.json:
        print(json.dumps(out))
    else:
        print(
            f"{'solved' if result.success else 'no path'} by planner {result.planner!r}"
            f"{' with prediction' if task.problem.predicts else ''}: {len(result.path)} configurations, "
            f"{result.stats.get('nodes', 0)} nodes, {result.stats.get('edges', 0)} edges, "
            f"{result.stats['total_s']:.3f} s"
        )
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from toolkit import viewer

    scenario, predictor = args.scenario or "3do", None
    if args.checkpoint:  # read it here: a bad one is an error in this terminal, before anything is served
        from functools import partial

        from toolkit.learning import checkpoints, learned

        models = checkpoints.load_models(args.checkpoint, args.scenario)
        scenario, predictor = models.scenario, partial(learned.LearnedChecker, models=models)
    if args.screenshot:
        from toolkit.util import outputs

        outputs.writable_file(args.screenshot, "--screenshot")
    v = viewer.launch(
        scenario,
        seed=args.seed,
        predictor=predictor,
        host=args.host,
        port=args.port,
        base_url=args.base_url,
        quiet=bool(args.screenshot),
    )
    try:
        if args.samples:
            v.sample("raw", args.samples, seed=args.seed)
        if args.screenshot:
            from toolkit.viewer.browser import screenshot

            print(f"toolkit view: wrote {screenshot(v.url, args.screenshot)}")
        else:
            viewer.serve_forever(v)
    except KeyboardInterrupt:  # Ctrl-C once the address is printed is how a served viewer stops, even while it
        if args.screenshot:  # still samples or has not yet begun to wait; a screenshot cut short is interrupted
            raise
    finally:
        v.stop()
    return 0


def cmd_reproduce(args: argparse.Namespace) -> int:
    from toolkit.experiments import reproduce
    from toolkit.experiments.bench import usable_device

    device = usable_device(args.device)  # before anything is made or written
    names = sorted(scenarios.SCENARIOS) if args.scenario == "all" else [args.scenario]
    settings = dict(workers=args.workers, samplers=args.samplers, baseline=args.baseline, planner=args.planner)
    configs = [_config(args, name, device=device, **settings) for name in names]
    if len(configs) == 1:
        reproduce.reproduce(configs[0], args.out)
    else:
        reproduce.reproduce_many(configs, args.out)
    print(f"wrote {args.out}/tables.md and results.json; the tables:\n")
    print(Path(args.out, "tables.md").read_text())
    return 0


def cmd_ablate(args: argparse.Namespace) -> int:
    from toolkit.experiments import ablation

    ablation.ablate(_config(args, args.scenario), args.out)
    print(f"wrote {args.out}/ablation.md and ablation.json:\n")
    print(Path(args.out, "ablation.md").read_text())
    return 0


def cmd_tune(args: argparse.Namespace) -> int:
    from toolkit.experiments import tuning

    tuning.tune(_config(args, args.scenario), args.out)
    print(f"wrote {args.out}/tuning.md and tuning.json:\n")
    print(Path(args.out, "tuning.md").read_text())
    return 0


def cmd_grade(args: argparse.Namespace) -> int:
    from toolkit.teaching import classroom, grading

    if args.assignment:
        grading.master(args.assignment)  # an unknown name fails here, with the known ones
    if args.unisolated:
        print(
            "WARNING: --unisolated: the students' code runs as you, with your files (the masters among them) and the "
            "network in reach",
            file=sys.stderr,
        )
    notebooks = classroom.submissions(args.notebooks)
    results = classroom.grade_all(
        notebooks, args.assignment, timeout=args.timeout, workers=args.workers, isolate=not args.unisolated
    )
    for notebook, result in results.items():
        print(json.dumps({"submission": str(notebook), **result}) if args.json else grading.report(result))
    if args.csv:
        classroom.write_csv(results, args.csv)
    return 0


COMMANDS: dict[str, Callable[[argparse.Namespace], int]] = {
    "reproduce": cmd_reproduce,
    "ablate": cmd_ablate,
    "tune": cmd_tune,
    "train": cmd_train,
    "plan": cmd_plan,
    "bench": cmd_bench,
    "view": cmd_view,
    "grade": cmd_grade,
}


# -- what an interrupted command leaves ---------------------------------------------------------


def _reproduce_kept(args: argparse.Namespace) -> str:
    from toolkit.experiments import reproduce

    folders = (
        {name: Path(args.out) / name for name in sorted(scenarios.SCENARIOS)}
        if args.scenario == "all"
        else {args.scenario: Path(args.out)}
    )
    kept = {name: reproduce.finished_stages(folder) for name, folder in folders.items()}
    listed = "; ".join(f"{name}: {', '.join(stages) or 'nothing yet'}" for name, stages in kept.items())
    return (
        f"kept the finished stages in {args.out} ({listed}); run the same command again to go on from there"
        if any(kept.values())
        else "nothing was finished; run the same command again to start over"
    )


def _rows_kept(args: argparse.Namespace) -> str:
    """What an interrupted `ablate` or `tune` kept: its finished rows."""
    return f"kept the finished rows in {args.out}/cache; run the same command again to go on from there"


KEPT: dict[str, Callable[[argparse.Namespace], str]] = {
    "bench": lambda args: (
        "bench --crossover writes its files only at the end; nothing was written"
        if args.crossover and args.out
        else "bench writes nothing; nothing is lost"
    ),
    "plan": lambda args: "plan writes nothing; nothing is lost",
    "train": lambda args: (
        f"{args.out} is as it was (the checkpoint is written only when training ends); "
        "run the same command again to train from the start"
    ),
    "view": lambda args: "the viewer stopped",
    "grade": lambda args: "grading writes its CSV only at the end; run the same command again",
    "reproduce": _reproduce_kept,
    "ablate": _rows_kept,
    "tune": _rows_kept,
}
