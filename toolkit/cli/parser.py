"""The ``toolkit`` command's parser: each sub-command's options, its help text and examples.

One function per sub-command adds its options (``reproduce_options``, ``plan_options``, ...;
``bench_options``, the longest, in :mod:`toolkit.cli.bench_parser`), built from the checked
types and shared options of :mod:`toolkit.cli.arguments`, so choices are read from the
registries when the parser is built. :data:`SUBCOMMANDS` holds what ``toolkit COMMAND
--help`` says about each one, and :func:`build_parser` joins them under ``toolkit``, whose
``--help`` lists the commands, scenarios, samplers and presets.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Mapping

from toolkit.cli.arguments import (
    SCENARIO_HELP,
    glossary,
    help_formatter,
    imports_parent,
    int_in,
    planner,
    positive_float,
    preset,
    sampler_list,
    sampler_names,
    scenario,
    seed,
    study,
)
from toolkit.cli.bench_parser import bench_options
from toolkit.experiments.config import BASELINES
from toolkit.planning import prm, sampling

# -- the sub-commands' own options ----------------------------------------------------------------


def reproduce_options(cmd: argparse.ArgumentParser) -> None:
    scenario(cmd, extra=["all"], required=True, help=SCENARIO_HELP + "; all: each of them in turn")
    preset(cmd, "paper: the paper's recipe (default); strong: ours, more accurate; or a registered one")
    cmd.add_argument(
        "--quick",
        action="store_true",
        help="small counts (few workspaces, epochs and queries) to try the whole pipeline in minutes; "
        "its figures mean little",
    )
    seed(cmd, "workspaces, samples, training and queries all follow from it")
    cmd.add_argument(
        "--out",
        required=True,
        metavar="DIR",
        help="folder for the results, new or empty, or holding this same run to resume it",
    )
    cmd.add_argument(
        "--workers",
        type=int_in(1),
        default=None,
        metavar="N",
        help="processes for planning, one sampler each (default: one per core; 1: all in this process)",
    )
    cmd.add_argument(
        "--samplers",
        type=sampler_list,
        default=sampling.PAPER_SAMPLERS,
        metavar="LIST",
        help="comma-separated samplers for Table 3 (default: the paper's four, BS,OB,G,BT; a registered "
        "one has no published figure beside it)",
    )
    cmd.add_argument(
        "--baseline",
        choices=list(BASELINES),
        default=None,
        help="what Table 3 compares prediction against (the medians table: always the best): "
        + "; ".join(f"{name}: {words}" for name, words in BASELINES.items())
        + " (default: the preset's own planner, so paper for the paper preset, best for strong)",
    )
    cmd.add_argument(
        "--planner",
        choices=prm.names(),
        default=None,
        help="plan Table 3 with this planner with and without prediction alike, e.g. batched (each round's samples "
        "in one checker call, a device call with --device cuda); default: the preset's pairing",
    )
    cmd.add_argument(
        "--device",
        metavar="DEVICE",
        help="cpu or cuda: where the networks train and the learned checker runs while planning and in the "
        "throughput stage (default: training on cuda if present; planning where the models are)",
    )


def ablate_options(cmd: argparse.ArgumentParser) -> None:
    study(cmd, "small counts, to try the command; its figures mean little", "ablation")


def tune_options(cmd: argparse.ArgumentParser) -> None:
    study(cmd, "a fraction of the epochs on few workspaces, to try the command", "tuning")


def train_options(cmd: argparse.ArgumentParser) -> None:
    scenario(cmd, required=True, help=SCENARIO_HELP)
    preset(cmd, "paper: the paper's networks and settings (default); strong: ours, more accurate; or a registered one")
    seed(cmd, "training data and initial weights")
    cmd.add_argument("--out", required=True, metavar="DIR", help="checkpoint folder to write (new or empty)")
    cmd.add_argument("--force", action="store_true", help="replace the checkpoint already in --out")
    cmd.add_argument(
        "--quick",
        action="store_true",
        help="few workspaces and epochs: a weak model in seconds to minutes, for trying things out",
    )
    cmd.add_argument("--device", default=None, help="torch device, e.g. cpu or cuda (default: cuda if present)")
    cmd.add_argument(
        "--cae-epochs", type=int_in(1), metavar="N", help="passes over the grids for the CAE (default: the preset's)"
    )
    cmd.add_argument(
        "--cae",
        action="store_true",
        help="train the CAE even when the preset's MLP does not use its code z (strong): for its "
        "reconstructions (Table 1); by default only the paper preset trains it",
    )
    cmd.add_argument(
        "--mlp-epochs", type=int_in(1), metavar="N", help="passes over the samples for the MLP (default: the preset's)"
    )


def plan_options(cmd: argparse.ArgumentParser) -> None:
    scenario(cmd, required=True, help=SCENARIO_HELP)
    cmd.add_argument(
        "--sampler",
        choices=sampler_names(),
        default="BS",
        help="how PRM draws its nodes (listed in `toolkit --help`; default BS)",
    )
    planner(cmd, "the planner that solves the query")
    cmd.add_argument(
        "--predict",
        action="store_true",
        help="decide which samples are free with the learned checker (needs --checkpoint); the planner stays the same",
    )
    cmd.add_argument("--checkpoint", metavar="DIR", help="a checkpoint folder from `toolkit train`")
    cmd.add_argument(
        "--device", metavar="DEVICE", help="with --predict: cpu or cuda, where the network runs (default cpu)"
    )
    seed(cmd, "the workspace, start and goal, and the sampler's draws")
    cmd.add_argument(
        "--json",
        action="store_true",
        help="print one JSON object (planner, params, success, path, stats, workspace) instead of a sentence",
    )


def view_options(cmd: argparse.ArgumentParser) -> None:
    scenario(cmd, default=None, help=SCENARIO_HELP + "; default: the checkpoint's, else 3do")
    seed(cmd, "which workspace is shown")
    cmd.add_argument("--checkpoint", metavar="DIR", help="a checkpoint folder: show the model's predictions too")
    cmd.add_argument(
        "--host",
        default="127.0.0.1",
        help="address to serve on (default 127.0.0.1: this computer only; 0.0.0.0: every network)",
    )
    cmd.add_argument(
        "--port",
        type=int_in(0, 65535),
        default=8080,
        help="first port to try, 0..65535 (default 8080; a busy one moves to the next free; 0: any free port)",
    )
    cmd.add_argument(
        "--base-url",
        metavar="URL",
        help="the base URL of the Jupyter server the browser reaches the viewer through, e.g. /user/NAME/: the "
        "printed address is then URLproxy/PORT/ (jupyter-server-proxy; `pip install sample-collision-toolkit[hub]`). "
        "Default: $TOOLKIT_VIEWER_BASE_URL, else JupyterHub's own variables; none: the port itself",
    )
    cmd.add_argument(
        "--samples",
        type=int_in(0, 100_000),
        default=0,
        metavar="N",
        help="show N uniform samples at the start, 0..100000 (default 0)",
    )
    cmd.add_argument(
        "--screenshot",
        metavar="PNG",
        help="save a picture of the page from a headless Chromium and exit (needs Chromium and "
        "Playwright: `make browser`, the dev extras)",
    )


def grade_options(cmd: argparse.ArgumentParser) -> None:
    cmd.add_argument("notebooks", nargs="+", help="student notebooks, or folders of them")
    cmd.add_argument("--assignment", help="assignment name (default: read from each notebook, else its file name)")
    cmd.add_argument(
        "--timeout", type=positive_float, help="seconds a notebook may run before it scores 0 (default: 600)"
    )
    cmd.add_argument(
        "--workers", type=int_in(1), help="notebooks graded at once (default: one per core; each runs its own kernel)"
    )
    cmd.add_argument(
        "--unisolated",
        action="store_true",
        help="run the notebooks without the bubblewrap sandbox, as you (only for code you trust)",
    )
    cmd.add_argument("--csv", help="also write one row of scores per notebook to this CSV file")
    cmd.add_argument("--json", action="store_true", help="print one JSON object a notebook instead of the report")


# (name, one-line summary, description, examples, options)
SUBCOMMANDS: list[tuple[str, str, str, list[str], Callable[[argparse.ArgumentParser], None]]] = [
    (
        "reproduce",
        "reproduce the paper's Tables 1-3 and figures",
        "Makes the data, trains the CAE and MLP, measures them (Tables 1, 2), plans with every\n"
        "sampler without and with prediction (Table 3) and writes DIR/results.json, DIR/tables.md\n"
        "(our figure next to the paper's in every cell) and PNG figures. Without prediction is the\n"
        "best exact planner and checker; Table 3 compares against --baseline (the paper preset:\n"
        "its Algorithm 1), and tables.md says which. Each finished stage is kept in DIR/cache:\n"
        "after Ctrl-C, the same command goes on where it stopped.",
        [
            "toolkit reproduce --scenario 2ds --out results/2ds            # the paper's 2D tables",
            "toolkit reproduce --scenario 3dc7 --quick --out results/try   # small counts, to try things",
            "toolkit reproduce --scenario all --preset strong --out results/strong",
            "toolkit reproduce --scenario 3dc9 --baseline paper-fcl --out results/3dc9-as-published",
        ],
        reproduce_options,
    ),
    (
        "ablate",
        "walk from the paper's recipe to ours, one change at a time",
        "Trains one model per row, each row keeping the changes above it (toolkit/experiments/ablation.py:\n"
        "the CAE's loss and data, dropout, optimizer, input scaling, more workspaces, a wider MLP,\n"
        "local features, no z) and scores each on the same seen and unseen samples, balanced and\n"
        "validity-blind as the paper. Writes DIR/ablation.md and ablation.json; each finished row\n"
        "is kept in DIR/cache: after Ctrl-C, the same command goes on where it stopped.",
        ["toolkit ablate --scenario 2ds --out results/ablation-2ds"],
        ablate_options,
    ),
    (
        "tune",
        "choose the paper preset's unstated settings on held-out training workspaces",
        "The paper does not say how long its networks train, the MLP's batch, initialization or\n"
        "input scaling. This tries each (toolkit/experiments/tuning.py), fitting on 80 % of the training\n"
        "workspaces and scoring on the other 20 %; the unseen test workspaces are never used.\n"
        "Writes DIR/tuning.md and tuning.json; finished rows are kept in DIR/cache (resumable).",
        ["toolkit tune --scenario 2ds --out results/tuning-2ds"],
        tune_options,
    ),
    (
        "train",
        "train the CAE and the collision MLP; write a checkpoint folder",
        "Makes the preset's training data, trains the CAE (it compresses a workspace's occupancy\n"
        "grid) and the MLP (it predicts whether a configuration is free), and writes DIR/weights.pt\n"
        "and DIR/meta.json with the test scores. `toolkit plan`, `view` and `bench` read DIR.",
        [
            "toolkit train --scenario 2ds --preset strong --out runs/2ds-strong",
            "toolkit train --scenario 3dc9 --quick --out runs/try --force   # replace runs/try",
        ],
        train_options,
    ),
    (
        "plan",
        "solve one planning query, with or without prediction",
        "Draws a workspace and a start and goal from --seed and solves the query with --planner\n"
        "(default lazy, the best exact planner; paper: the paper's Algorithm 1). With --predict the\n"
        "learned checker decides which samples are free and nothing else changes: the same planner,\n"
        "the same parameters. The returned path is always checked exactly; the output names the planner.",
        [
            "toolkit plan --scenario 2ds --sampler OB",
            "toolkit plan --scenario 3dc7 --planner paper --option k=15   # Algorithm 1, 15 neighbours",
            "toolkit plan --scenario 3dc7 --sampler BT --predict --checkpoint runs/3dc7-strong --json",
            "toolkit plan --import my_samplers --scenario 2ds --sampler MA   # a sampler registered in my_samplers.py",
        ],
        plan_options,
    ),
    (
        "bench",
        "measure how fast the exact and the learned checker are",
        "Prints configurations checked per second by the default exact checker (compiled for box\n"
        "worlds), by the python-fcl reference, and by the learned one (the networks; untrained ones\n"
        "of the preset's sizes unless --checkpoint), timed in turns, their ratios, and exact edge\n"
        "checking. With --checkpoint it also plans a few of the paper's queries with that model and\n"
        "without (one planner both ways: --planner, default lazy, the best exact planner, with the\n"
        "default exact checker) and prints the time ratios and the planner's name. With --vs-ompl it\n"
        "races our planners against OMPL's PRM and RRTConnect on the same queries and checker. With\n"
        "--crossover it sweeps what makes an exact check dear and shows where prediction pays.",
        [
            "toolkit bench --scenario 3dc7 --json",
            "toolkit bench --scenario 3dc9 --checkpoint runs/3dc9-strong --samplers BT --option rebridge=0",
            "toolkit bench --vs-ompl --scenario 3dc7 --queries 30 --seeds 7300,9300",
            "toolkit bench --crossover --scenario 3dc9 --out docs   # docs/crossover.png and .json",
        ],
        bench_options,
    ),
    (
        "view",
        "show a scenario in your browser (Viser)",
        "Serves a 3D scene on this computer and prints the address to open: the workspace, the\n"
        "robot colored by the exact checker (blue free, vermillion colliding), a slider per joint,\n"
        "samples, and a PRM roadmap with its path. Ctrl-C stops it. On a JupyterHub the address is\n"
        "the port's path through your Jupyter server, /user/NAME/proxy/PORT/.",
        [
            "toolkit view --scenario 3do",
            "toolkit view --base-url /user/student/              # through a Jupyter server with that base URL",
            "toolkit view --checkpoint runs/3dc7-strong          # also the model's predictions",
            "toolkit view --scenario 3dc9 --samples 300 --screenshot scene.png",
        ],
        view_options,
    ),
    (
        "grade",
        "grade filled-in assignment notebooks with otter",
        "Runs each student notebook with the assignment's public and hidden tests (otter-grader,\n"
        "no Docker), prints a report per notebook with feedback, and ends with `score: X/Y`.\n"
        "Questions answered in prose are graded by hand and not counted here.",
        [
            "toolkit grade submissions/bridge_test.ipynb",
            "toolkit grade submissions/ --csv scores.csv       # every notebook in the folder",
        ],
        grade_options,
    ),
]


def build_parser(commands: Mapping[str, Callable[[argparse.Namespace], int]]) -> argparse.ArgumentParser:
    """The whole parser; ``commands`` maps each sub-command's name to the function that runs it."""
    parent = imports_parent()
    parser = argparse.ArgumentParser(
        prog="toolkit",
        formatter_class=help_formatter,
        parents=[parent],
        epilog="examples:\n"
        "  toolkit reproduce --scenario 2ds --quick --out results/2ds-quick\n"
        "  toolkit train --scenario 3dc7 --preset strong --out runs/3dc7-strong\n"
        "  toolkit view --checkpoint runs/3dc7-strong\n"
        "  toolkit reproduce --help        (every command explains its options)",
    )
    sub = parser.add_subparsers(
        dest="command", required=True, metavar="COMMAND", help="one of the commands above, then its options"
    )
    for name, summary, description, examples, add_options in SUBCOMMANDS:
        cmd = sub.add_parser(
            name,
            description=f"{summary[0].upper()}{summary[1:]}.\n\n{description}",
            epilog="examples:\n" + "\n".join(f"  {line}" for line in examples),
            formatter_class=help_formatter,
            parents=[parent],
        )
        add_options(cmd)
        cmd.set_defaults(func=commands[name])
    parser.description = (
        'Learn, reproduce and extend "Predicting Sample Collision with Neural Networks"\n'
        "(Tran, Denny, Ekenna): a neural network that tells a planner, faster than geometry,\n"
        "whether a robot configuration collides.\n\n"
        "commands (toolkit COMMAND --help explains each one):\n"
        + "\n".join(f"  {name:11}{summary}" for name, summary, *_ in SUBCOMMANDS)
        + "\n\n"
        + glossary()
    )
    return parser
