"""``toolkit bench``'s options: the checkers' speed, then ``--checkpoint``'s planning, ``--vs-ompl``'s race and
``--crossover``'s sweep, one function each (:func:`bench_options` joins them), built from the checked types and
shared options of :mod:`toolkit.cli.arguments`.
"""

from __future__ import annotations

import argparse

from toolkit.cli.arguments import SCENARIO_HELP, SEEDS, int_in, planner, preset, sampler_list, scenario, seed
from toolkit.planning import sampling

CROSSOVER_SCENARIO = "3dc9"  # --crossover without --scenario: the paper's dearest clutter check


def bench_options(cmd: argparse.ArgumentParser) -> None:
    """The checkers' speed (a scenario, a seed, the sizes), then the options of ``--checkpoint``
    (:func:`bench_planning_options`), ``--vs-ompl`` (:func:`bench_versus_ompl_options`) and ``--crossover``
    (:func:`bench_crossover_options`)."""
    scenario(cmd, help=SCENARIO_HELP + f"; needed but with --crossover (default {CROSSOVER_SCENARIO})")
    seed(cmd, "the workspace and the configurations timed")
    cmd.add_argument("--json", action="store_true", help="print one JSON object instead of lines")
    preset(cmd, "network sizes whose learned speed is measured (default paper; speed does not depend on the weights)")
    cmd.add_argument(
        "--batch",
        type=int_in(1, 1_000_000),
        metavar="N",
        help="configurations per call for every checker, 1..1000000 (default: 20,000 exact and FCL, "
        "10,000 learned; a sampler asks for 200-2,000)",
    )
    cmd.add_argument(
        "--device",
        metavar="DEVICE",
        help="cpu or cuda: also time the learned checker and the exact one in torch there, a batch in numpy and "
        "one already on the device (default: neither); with --crossover, sweep the batch, obstacles and links on "
        "that device instead (meshes stay on the CPU)",
    )
    bench_planning_options(cmd)
    bench_versus_ompl_options(cmd)
    bench_crossover_options(cmd)


def bench_planning_options(cmd: argparse.ArgumentParser) -> None:
    """`bench --checkpoint`: the trained model, and the queries planned with and without it."""
    cmd.add_argument(
        "--checkpoint",
        metavar="DIR",
        help="a trained model (from `toolkit train`, or DIR/cache/checkpoint of `toolkit reproduce`): also "
        "time one planner (--planner, default lazy) with it and without, with the default exact checker",
    )
    cmd.add_argument(
        "--workspaces",
        type=int_in(1, 100),
        default=2,
        metavar="N",
        help="with --checkpoint: query workspaces to plan in, 1..100 (default 2)",
    )
    cmd.add_argument(
        "--pairs",
        type=int_in(1, 10),
        default=2,
        metavar="N",
        help="with --checkpoint: start/goal pairs per workspace, 1..10 (default 2)",
    )
    cmd.add_argument(
        "--samplers",
        type=sampler_list,
        default=sampling.PAPER_SAMPLERS,
        metavar="LIST",
        help="with --checkpoint: comma-separated samplers to plan with, e.g. BT,OB (default: the paper's four)",
    )
    planner(cmd, "with --checkpoint: the planner that plans with and without the model, alike")


def bench_versus_ompl_options(cmd: argparse.ArgumentParser) -> None:
    """`bench --vs-ompl`: the race against OMPL's planners, and its queries and time limit; `--profile`, which
    times the same queries' stages."""
    cmd.add_argument(
        "--vs-ompl",
        action="store_true",
        help="instead: plan --queries N queries of each of --seeds with our planners (best exact, RRT-Connect, "
        "the paper's baseline, and with --checkpoint's model) and OMPL's on the same exact checker, "
        "in turns, one thread, and print for each seed the machine's load and a markdown table, OMPL's planners "
        "also with their checks at our batched rate (needs the ompl extra: "
        "pip install 'sample-collision-toolkit[ompl]')",
    )
    cmd.add_argument(
        "--seeds",
        type=lambda text: tuple(int_in(0, SEEDS - 1)(seed) for seed in text.split(",")),
        default=(7300, 9300),
        metavar="LIST",
        help="with --vs-ompl: comma-separated seeds of the query sets (--seed does not choose them), ones the "
        "planners were not tuned on (not 0 or 7100; default 7300,9300)",
    )
    cmd.add_argument(
        "--ompl-planners",
        type=lambda text: tuple(text.split(",")),
        default=("PRM", "RRTConnect"),
        metavar="LIST",
        help="with --vs-ompl: comma-separated planners of ompl.geometric to race (default PRM,RRTConnect)",
    )
    cmd.add_argument(
        "--paper-baseline",
        action=argparse.BooleanOptionalAction,
        default=True,
        help="with --vs-ompl: race the paper's Algorithm 1 too (default yes)",
    )
    cmd.add_argument(
        "--profile",
        action="store_true",
        help="instead: solve --queries N queries with the best exact planner and print where their time goes, "
        "stage by stage (set-up, sampling, neighbours, edge checks, search, verification; "
        "toolkit/experiments/profile.py)",
    )
    cmd.add_argument(
        "--queries",
        type=int_in(1, 1000),
        metavar="N",
        help="with --vs-ompl or --profile: the first N queries of the seed's query set (default 30 with --vs-ompl, "
        "10 with --profile)",
    )
    cmd.add_argument(
        "--ompl-seconds",
        type=float,
        default=30.0,
        metavar="S",
        help="with --vs-ompl: OMPL's time limit per query (default 30)",
    )


def bench_crossover_options(cmd: argparse.ArgumentParser) -> None:
    """`bench --crossover`: where prediction pays, the variables swept, quick sizes, a folder for the figure."""
    cmd.add_argument(
        "--crossover",
        action="store_true",
        help="instead: the exact checkers' and the learned one's cost per configuration as the obstacles, a mesh "
        "obstacle's triangles, the robot's links and the batch grow (toolkit/experiments/crossover.py), and "
        "where they cross; a few minutes",
    )
    cmd.add_argument(
        "--variables",
        type=lambda text: tuple(text.split(",")),
        default=(),
        metavar="LIST",
        help="with --crossover: comma-separated variables to sweep, of obstacles, triangles, links, batch "
        "(default: all that apply; 2D: obstacles, batch; with --device: batch, obstacles, links)",
    )
    cmd.add_argument(
        "--quick", action="store_true", help="with --crossover: two small values a variable, to try the command"
    )
    cmd.add_argument(
        "--out",
        metavar="DIR",
        help="with --crossover: also write DIR/crossover.json and DIR/crossover.png (the figure)",
    )
