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


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="toolkit", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)

    bench = sub.add_parser("bench", help="measure exact and learned checker throughput")
    bench.add_argument("--scenario", choices=SCENARIO_NAMES, required=True)
    bench.add_argument("--seed", type=int, default=0)
    bench.add_argument("--json", action="store_true", help="print one JSON object")
    bench.set_defaults(func=cmd_bench)
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
