"""The ``toolkit`` command (also ``python -m toolkit``): one sub-command per job.

Each sub-command parses its arguments here and calls the library; nothing here
computes what the library does not also offer from Python.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import sys

from . import scenarios

SCENARIO_NAMES = sorted(scenarios.SCENARIOS)


def _positive_int(text: str) -> int:
    """An argparse type: an integer >= 1."""
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {text}")
    return value


def _samplers(text: str) -> tuple[str, ...]:
    """An argparse type: comma-separated sampler names."""
    names = tuple(text.split(","))
    if unknown := [n for n in names if n not in ("BS", "OB", "G", "BT")]:
        raise argparse.ArgumentTypeError(f"unknown sampler(s) {unknown}; choose from BS, OB, G, BT")
    return names


def _planner_option(text: str) -> tuple[str, object]:
    """An argparse type: ``NAME=VALUE``, the value read as JSON (``rebridge=0``, ``screen_edges=false``)."""
    name, sep, value = text.partition("=")
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {text!r}")
    try:
        return name, json.loads(value)
    except json.JSONDecodeError:
        return name, value  # a string, e.g. auxiliary=exact


def cmd_bench(args: argparse.Namespace) -> int:
    from . import bench, checkpoints

    scenario = scenarios.get(args.scenario)
    models = checkpoints.load_models(args.checkpoint, scenario.name) if args.checkpoint else None
    batches = {"batch": args.batch} if args.batch else {}  # default: each function's own
    result = {"scenario": scenario.name, "exact_cfg_per_s": bench.exact_throughput(scenario, seed=args.seed, **batches),
              "learned_cfg_per_s": bench.learned_throughput(scenario, args.preset, seed=args.seed, models=models,
                                                            **batches)}
    result["ratio"] = result["learned_cfg_per_s"] / result["exact_cfg_per_s"]
    result["edges"] = bench.edge_checks(scenario, seed=args.seed)
    if models is not None:
        result["planning"] = bench.planning_ratios(scenario, models, args.workspaces, args.pairs, args.seed,
                                                   args.samplers, dict(args.option))
        result["planning_options"] = dict(args.option)
    print(json.dumps(result) if args.json else "\n".join(f"{k}: {v}" for k, v in result.items()))
    return 0


def cmd_train(args: argparse.Namespace) -> int:
    from . import checkpoints, presets, training

    preset = presets.get(args.preset)
    overrides = {k: v for k, v in (("cae_epochs", args.cae_epochs), ("mlp_epochs", args.mlp_epochs)) if v is not None}
    preset = dataclasses.replace(preset.quick_version() if args.quick else preset, **overrides)
    splits = training.preset_splits(args.scenario, preset, args.seed, quick=args.quick)
    models = training.train_models(args.scenario, preset, splits, args.seed, device=args.device)
    scores = training.evaluate(models, splits)
    folder = checkpoints.save_checkpoint(models, args.out, evaluation=scores)
    print(json.dumps({"checkpoint": str(folder), "threshold": models.threshold, **scores}))
    return 0


def cmd_plan(args: argparse.Namespace) -> int:
    from . import queries

    if args.predict and not args.checkpoint:
        raise ValueError("--predict needs --checkpoint DIR (a folder written by `toolkit train`)")
    scenario = scenarios.get(args.scenario)
    query = queries.make_queries(scenario, args.seed, n_workspaces=1, per_workspace=1)[0]
    checker = None
    if args.predict:
        from . import learned

        checker = learned.load_checker(args.checkpoint, query.workspace)
    result = queries.solve_query(scenario, query, args.sampler, checker, seed=args.seed)
    out = {"scenario": scenario.name, "sampler": args.sampler, "predict": args.predict, "seed": args.seed,
           "success": result.success, "path": result.path.tolist(), "stats": result.stats,
           "start": query.start.tolist(), "goal": query.goal.tolist(), "workspace": query.workspace.to_dict()}
    if args.json:
        print(json.dumps(out))
    else:
        print(f"{'solved' if result.success else 'no path'}: {len(result.path)} configurations, "
              f"{result.stats['nodes']} nodes, {result.stats['edges']} edges, {result.stats['total_s']:.3f} s")
    return 0


def cmd_view(args: argparse.Namespace) -> int:
    from . import viewer

    v = viewer.launch(args.scenario, seed=args.seed, checkpoint=args.checkpoint, host=args.host, port=args.port,
                      quiet=bool(args.screenshot))
    try:
        if args.samples:
            v.sample("raw", args.samples, seed=args.seed)
        if args.screenshot:
            from .viewer_browser import screenshot

            print(f"toolkit view: wrote {screenshot(v.url, args.screenshot)}")
        else:
            viewer.serve_forever(v)
    finally:
        v.stop()
    return 0


def cmd_reproduce(args: argparse.Namespace) -> int:
    from . import experiments

    names = SCENARIO_NAMES if args.scenario == "all" else [args.scenario]
    if len(names) == 1:
        experiments.reproduce(names[0], args.preset, args.quick, args.seed, args.out, workers=args.workers)
    else:
        experiments.reproduce_many(names, args.preset, args.quick, args.seed, args.out, workers=args.workers)
    print(f"wrote {args.out}/tables.md and results.json; the tables:\n")
    print(open(f"{args.out}/tables.md").read())
    return 0


def cmd_grade(args: argparse.Namespace) -> int:
    from . import grading

    results = {}
    for notebook in grading.submissions(args.notebooks):
        results[notebook] = grading.grade(notebook, args.assignment, timeout=args.timeout)
        print(json.dumps({"submission": str(notebook), **results[notebook]}) if args.json
              else grading.report(results[notebook]), flush=True)
    if args.csv:
        grading.write_csv(results, args.csv)
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="toolkit", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)

    bench = sub.add_parser("bench", help="measure exact and learned checker throughput")
    bench.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    bench.add_argument("--seed", type=int, default=0)
    bench.add_argument("--json", action="store_true", help="print one JSON object")
    bench.add_argument("--preset", choices=["paper", "strong"], default="paper",
                       help="networks whose learned throughput is measured (untrained: speed does not depend on weights)")
    bench.add_argument("--batch", type=_positive_int, help="configurations per call for both checkers (default: "
                                                             "20,000 exact, 10,000 learned; a sampler asks 200-2,000)")
    bench.add_argument("--checkpoint", help="a trained model (from `toolkit train`, or DIR/cache/checkpoint of "
                                            "`toolkit reproduce`): also time PRM with and without it")
    bench.add_argument("--workspaces", type=int, default=2, help="with --checkpoint: query workspaces to plan in")
    bench.add_argument("--pairs", type=int, default=2, help="with --checkpoint: start/goal pairs per workspace")
    bench.add_argument("--samplers", type=_samplers, default=("BS", "OB", "G", "BT"),
                       help="with --checkpoint: comma-separated samplers to plan with (default: all four)")
    bench.add_argument("--option", type=_planner_option, action="append", default=[], metavar="NAME=VALUE",
                       help="with --checkpoint: a PRMOptions field for both modes, e.g. rebridge=0 (repeatable)")
    bench.set_defaults(func=cmd_bench)

    # -- train (learning issue) --
    train = sub.add_parser("train", help="train the CAE and the collision MLP, write a checkpoint folder")
    train.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    train.add_argument("--preset", choices=["paper", "strong"], default="paper")
    train.add_argument("--seed", type=int, default=0)
    train.add_argument("--out", required=True, help="checkpoint folder to write")
    train.add_argument("--quick", action="store_true", help="few workspaces and epochs: seconds, for trying things out")
    train.add_argument("--device", default=None, help="torch device (default: cuda when available, else cpu)")
    train.add_argument("--cae-epochs", type=int, help="override the preset's CAE epochs")
    train.add_argument("--mlp-epochs", type=int, help="override the preset's MLP epochs")
    train.set_defaults(func=cmd_train)

    # -- plan (planning issue) --
    plan = sub.add_parser("plan", help="solve one query with PRM, with or without prediction")
    plan.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    plan.add_argument("--sampler", choices=["BS", "OB", "G", "BT"], default="BS")
    plan.add_argument("--predict", action="store_true", help="decide sample validity with the learned checker (Algorithm 1)")
    plan.add_argument("--checkpoint", help="checkpoint folder from `toolkit train` (needed with --predict)")
    plan.add_argument("--seed", type=int, default=0)
    plan.add_argument("--json", action="store_true", help="print one JSON object")
    plan.set_defaults(func=cmd_plan)

    # -- view (viewer issue) --
    view = sub.add_parser("view", help="serve the Viser viewer of a scenario")
    view.add_argument("--scenario", choices=SCENARIO_NAMES, default="3do")
    view.add_argument("--seed", type=int, default=0)
    view.add_argument("--checkpoint", help="checkpoint folder: color samples by predicted validity too")
    view.add_argument("--host", default="127.0.0.1")
    view.add_argument("--port", type=int, default=8080, help="first port to try; a busy one moves to the next free")
    view.add_argument("--samples", type=int, default=0, help="show this many uniform samples at start")
    view.add_argument("--screenshot", help="save a headless-Chromium PNG of the page here and exit")
    view.set_defaults(func=cmd_view)

    # -- reproduce (reproduction issue) --
    reproduce = sub.add_parser("reproduce", help="reproduce the paper's Tables 1-3 and figures")
    reproduce.add_argument("--scenario", choices=SCENARIO_NAMES + ["all"], required=True)
    reproduce.add_argument("--preset", choices=["paper", "strong"], default="paper")
    reproduce.add_argument("--quick", action="store_true", help="small counts, minutes per scenario")
    reproduce.add_argument("--seed", type=int, default=0)
    reproduce.add_argument("--out", required=True, help="output folder (also the cache for resuming)")
    reproduce.add_argument("--workers", type=int, default=None,
                           help="processes for the planning runs (default: one per core; 1: plan in this process)")
    reproduce.set_defaults(func=cmd_reproduce)

    # -- grade (assignments issue) --
    grade = sub.add_parser("grade", help="grade filled-in assignment notebooks with otter (last line: score: X/Y)")
    grade.add_argument("notebooks", nargs="+", help="student notebooks, or folders of them")
    grade.add_argument("--assignment", help="assignment name (default: each notebook's file name)")
    grade.add_argument("--timeout", type=float, help="seconds a notebook may run before it scores 0 (default: 600)")
    grade.add_argument("--csv", help="also write one row of scores per notebook to this CSV file")
    grade.add_argument("--json", action="store_true", help="print one JSON object a notebook instead of the report")
    grade.set_defaults(func=cmd_grade)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args) or 0)
    except (ValueError, FileNotFoundError) as err:
        print(f"toolkit {args.command}: error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
