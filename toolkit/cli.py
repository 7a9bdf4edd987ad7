"""The ``toolkit`` command (also ``python -m toolkit``): one sub-command per job.

Each sub-command parses its arguments here and calls the library; nothing here
computes what the library does not also offer from Python.
"""

from __future__ import annotations

import argparse
import json
import sys

from . import scenarios

SCENARIO_NAMES = sorted(scenarios.SCENARIOS)


def cmd_bench(args: argparse.Namespace) -> int:
    from . import bench

    scenario = scenarios.get(args.scenario)
    result = {"scenario": scenario.name, "exact_cfg_per_s": bench.exact_throughput(scenario, seed=args.seed)}
    print(json.dumps(result) if args.json else "\n".join(f"{k}: {v}" for k, v in result.items()))
    return 0


def cmd_train(args: argparse.Namespace) -> int:
    raise NotImplementedError("toolkit train: being written (learning issue)")


def cmd_plan(args: argparse.Namespace) -> int:
    raise NotImplementedError("toolkit plan: being written (planning issue)")


def cmd_view(args: argparse.Namespace) -> int:
    raise NotImplementedError("toolkit view: being written (viewer issue)")


def cmd_reproduce(args: argparse.Namespace) -> int:
    raise NotImplementedError("toolkit reproduce: being written (reproduction issue)")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="toolkit", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)

    bench = sub.add_parser("bench", help="measure exact and learned checker throughput")
    bench.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    bench.add_argument("--seed", type=int, default=0)
    bench.add_argument("--json", action="store_true", help="print one JSON object")
    bench.set_defaults(func=cmd_bench)

    # -- train (learning issue) --
    train = sub.add_parser("train", help="train the CAE and the collision MLP, write a checkpoint folder")
    train.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    train.add_argument("--preset", choices=["paper", "strong"], default="paper")
    train.add_argument("--seed", type=int, default=0)
    train.add_argument("--out", required=True, help="checkpoint folder to write")
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
    view.add_argument("--port", type=int, default=8080)
    view.set_defaults(func=cmd_view)

    # -- reproduce (reproduction issue) --
    reproduce = sub.add_parser("reproduce", help="reproduce the paper's Tables 1-3 and figures")
    reproduce.add_argument("--scenario", choices=SCENARIO_NAMES + ["all"], required=True)
    reproduce.add_argument("--preset", choices=["paper", "strong"], default="paper")
    reproduce.add_argument("--quick", action="store_true", help="small counts, minutes per scenario")
    reproduce.add_argument("--seed", type=int, default=0)
    reproduce.add_argument("--out", required=True, help="output folder (also the cache for resuming)")
    reproduce.set_defaults(func=cmd_reproduce)
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
