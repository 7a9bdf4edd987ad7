"""The ``toolkit`` command (also ``python -m toolkit``): one sub-command per job.

Each sub-command parses its arguments here and calls the library; nothing here
computes what the library does not also offer from Python. The parser checks every
number (the flag named in the error), each command checks where it will write
before it starts, and Ctrl-C or SIGTERM stops a command within seconds: it says
what it kept and exits with 128 + the signal's number (130, 143), as shells expect.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import signal
import sys
from contextlib import contextmanager
from pathlib import Path

from toolkit import scenarios

SCENARIO_NAMES = sorted(scenarios.SCENARIOS)
SAMPLER_NAMES = ("BS", "OB", "G", "BT")
SEEDS = 2**32  # seeds are 0 .. 2**32 - 1

GLOSSARY = "\n".join(
    ["scenarios (--scenario), the paper's four:"]
    + [f"  {s.name:6}{s.title}" for s in scenarios.SCENARIOS.values()]
    + ["",
       "samplers (--sampler, --samplers), how PRM draws its nodes:",
       "  BS    basic: uniform random configurations",
       "  OB    obstacle-based: the last free configuration on a line towards a colliding one",
       "  G     Gaussian: of two nearby configurations, the free one when the other collides",
       "  BT    bridge test: the free midpoint of two colliding configurations (narrow passages)",
       "",
       "presets (--preset):",
       "  paper   the paper's networks and training settings",
       "  strong  ours: the MLP also sees the occupancy around the robot and where its links are;",
       "          far more accurate (docs/results.md)",
       "",
       "threads: torch and numpy use one thread, fastest when other programs share the machine;",
       "TOOLKIT_THREADS=N uses N (0: one per core). See toolkit/util/threads.py."])


class Interrupted(KeyboardInterrupt):
    """Ctrl-C (SIGINT) or SIGTERM, raised in the main thread so that every ``finally`` runs."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


# -- argument types: each names the rule it checks; argparse adds the flag ----------------------

def _int_in(low: int, high: int | None = None):
    """An argparse type: a whole number in ``low .. high`` (no upper limit when ``high`` is None)."""
    allowed = f"{low}..{high}" if high is not None else f"{low} or more"

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be a whole number, {allowed}; got {text!r}") from None
        if value < low or (high is not None and value > high):
            raise argparse.ArgumentTypeError(f"must be {allowed}, got {value}")
        return value

    parse.__name__ = "number"  # argparse names the type in some messages
    return parse


def _samplers(text: str) -> tuple[str, ...]:
    """An argparse type: comma-separated sampler names."""
    names = tuple(text.split(","))
    if unknown := [n for n in names if n not in SAMPLER_NAMES]:
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


# -- the commands -------------------------------------------------------------------------------

def cmd_bench(args: argparse.Namespace) -> int:
    from toolkit.experiments import bench
    from toolkit.learning import checkpoints

    scenario = scenarios.get(args.scenario)
    models = checkpoints.load_models(args.checkpoint, scenario.name) if args.checkpoint else None
    if args.vs_ompl:
        try:
            table = bench.versus_ompl(scenario, args.queries, args.seed, models, args.ompl_seconds)
        except ImportError as missing:  # ompl is an optional extra
            raise ValueError(str(missing)) from None
        print(json.dumps({"scenario": scenario.name, "seed": args.seed, "planners": table}) if args.json
              else bench.versus_ompl_markdown(scenario, table))
        return 0
    result = {"scenario": scenario.name,
              **bench.throughput(scenario, args.preset, args.batch, seed=args.seed, models=models)}
    result["edges"] = bench.edge_checks(scenario, seed=args.seed)
    if models is not None:
        result["planning"] = bench.planning_ratios(scenario, models, args.workspaces, args.pairs, args.seed,
                                                   args.samplers, dict(args.option))
        result["planning_options"] = dict(args.option)
    print(json.dumps(result) if args.json else "\n".join(f"{k}: {v}" for k, v in result.items()))
    return 0


def cmd_train(args: argparse.Namespace) -> int:
    from toolkit.learning import checkpoints, presets, training

    checkpoints.check_destination(args.out, overwrite=args.force)  # before minutes of training, not after
    preset = presets.get(args.preset)
    overrides = {k: v for k, v in (("cae_epochs", args.cae_epochs), ("mlp_epochs", args.mlp_epochs)) if v is not None}
    preset = dataclasses.replace(preset.quick_version() if args.quick else preset, **overrides)
    splits = training.preset_splits(args.scenario, preset, args.seed, quick=args.quick)
    models = training.train_models(args.scenario, preset, splits, args.seed, device=args.device, cae=args.cae or None)
    scores = training.evaluate(models, splits)
    folder = checkpoints.save_checkpoint(models, args.out, evaluation=scores, overwrite=args.force)
    print(json.dumps({"checkpoint": str(folder), "threshold": models.threshold, **scores}))
    return 0


def cmd_plan(args: argparse.Namespace) -> int:
    from toolkit.planning import queries

    if args.predict and not args.checkpoint:
        raise ValueError("--predict needs --checkpoint DIR (a folder written by `toolkit train`)")
    scenario = scenarios.get(args.scenario)
    query = queries.make_queries(scenario, args.seed, n_workspaces=1, per_workspace=1)[0]
    checker = None
    if args.predict:
        from toolkit.learning import learned

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
    from toolkit import viewer

    scenario, predictor = args.scenario or "3do", None
    if args.checkpoint:  # read it here: a bad one is an error in this terminal, before anything is served
        from functools import partial

        from toolkit.learning import checkpoints, learned

        models = checkpoints.load_models(args.checkpoint, args.scenario)
        scenario, predictor = models.scenario.name, partial(learned.LearnedChecker, models=models)
    if args.screenshot:
        from toolkit.util import outputs

        outputs.writable_file(args.screenshot, "--screenshot")
    v = viewer.launch(scenario, seed=args.seed, predictor=predictor, host=args.host, port=args.port,
                      quiet=bool(args.screenshot))
    try:
        if args.samples:
            v.sample("raw", args.samples, seed=args.seed)
        if args.screenshot:
            from toolkit.viewer.browser import screenshot

            print(f"toolkit view: wrote {screenshot(v.url, args.screenshot)}")
        else:
            viewer.serve_forever(v)
    finally:
        v.stop()
    return 0


def cmd_reproduce(args: argparse.Namespace) -> int:
    from toolkit.experiments import reproduce as experiments

    names = SCENARIO_NAMES if args.scenario == "all" else [args.scenario]
    if len(names) == 1:
        experiments.reproduce(names[0], args.preset, args.quick, args.seed, args.out, workers=args.workers)
    else:
        experiments.reproduce_many(names, args.preset, args.quick, args.seed, args.out, workers=args.workers)
    print(f"wrote {args.out}/tables.md and results.json; the tables:\n")
    print(open(f"{args.out}/tables.md").read())
    return 0


def cmd_ablate(args: argparse.Namespace) -> int:
    from toolkit.experiments import ablation

    ablation.ablate(args.scenario, args.out, args.seed, args.quick)
    print(f"wrote {args.out}/ablation.md and ablation.json:\n")
    print(open(f"{args.out}/ablation.md").read())
    return 0


def cmd_tune(args: argparse.Namespace) -> int:
    from toolkit.experiments import tuning

    tuning.tune(args.scenario, args.out, args.seed, args.quick)
    print(f"wrote {args.out}/tuning.md and tuning.json:\n")
    print(open(f"{args.out}/tuning.md").read())
    return 0


def cmd_grade(args: argparse.Namespace) -> int:
    from toolkit.teaching import grading

    if args.assignment:
        grading.master(args.assignment)  # an unknown name fails here, with the known ones
    notebooks = grading.submissions(args.notebooks)
    names = {notebook: args.assignment or grading.assignment_of(notebook) for notebook in notebooks}  # all, before grading
    results = {}
    for notebook, name in names.items():
        results[notebook] = grading.grade(notebook, name, timeout=args.timeout)
        print(json.dumps({"submission": str(notebook), **results[notebook]}) if args.json
              else grading.report(results[notebook]), flush=True)
    if args.csv:
        grading.write_csv(results, args.csv)
    return 0


# -- what an interrupted command leaves ---------------------------------------------------------

def _reproduce_kept(args: argparse.Namespace) -> str:
    from toolkit.experiments import reproduce as experiments

    folders = ({name: Path(args.out) / name for name in SCENARIO_NAMES} if args.scenario == "all"
               else {args.scenario: Path(args.out)})
    kept = {name: experiments.finished_stages(folder) for name, folder in folders.items()}
    listed = "; ".join(f"{name}: {', '.join(stages) or 'nothing yet'}" for name, stages in kept.items())
    return (f"kept the finished stages in {args.out} ({listed}); run the same command again to go on from there"
            if any(kept.values()) else "nothing was finished; run the same command again to start over")


def _rows_kept(args: argparse.Namespace) -> str:
    """What an interrupted `ablate` or `tune` kept: its finished rows."""
    return f"kept the finished rows in {args.out}/cache; run the same command again to go on from there"


KEPT = {
    "bench": lambda args: "bench writes nothing; nothing is lost",
    "plan": lambda args: "plan writes nothing; nothing is lost",
    "train": lambda args: (f"{args.out} is as it was (the checkpoint is written only when training ends); "
                           "run the same command again to train from the start"),
    "view": lambda args: "the viewer stopped",
    "grade": lambda args: "grading writes its CSV only at the end; run the same command again",
    "reproduce": _reproduce_kept,
    "ablate": _rows_kept,
    "tune": _rows_kept,
}


@contextmanager
def _signals_interrupt():
    """SIGINT and SIGTERM raise :class:`Interrupted` inside, once: a second signal while the command stops ends
    it at once (planning processes notice within a second that it is gone, and end too)."""
    handlers = {}

    def interrupt(signum, frame):
        for sig in handlers:
            signal.signal(sig, signal.SIG_DFL)
        raise Interrupted(signum)

    for sig in (signal.SIGINT, signal.SIGTERM):
        handlers[sig] = signal.signal(sig, interrupt)
    try:
        yield
    finally:
        for sig, handler in handlers.items():
            signal.signal(sig, handler)


# -- the parser ---------------------------------------------------------------------------------

def _formatter(prog: str) -> argparse.HelpFormatter:
    """Help as written (line breaks kept in descriptions and examples), options in a wide first column."""
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=28)


def _subcommand(sub, name: str, summary: str, description: str, examples: list[str], func) -> argparse.ArgumentParser:
    """A sub-command with a one-line ``summary`` (listed by ``toolkit --help``), a ``description`` and ``examples``."""
    sub.summaries.append(f"  {name:11}{summary}")
    parser = sub.add_parser(name, description=f"{summary[0].upper()}{summary[1:]}.\n\n{description}",
                            epilog="examples:\n" + "\n".join(f"  {line}" for line in examples),
                            formatter_class=_formatter)
    parser.set_defaults(func=func)
    return parser


def _study_arguments(cmd: argparse.ArgumentParser, scenario_help: str, quick_help: str, study: str) -> None:
    """The options `ablate` and `tune` share: a scenario, a seed, --quick and a resumable --out folder."""
    cmd.add_argument("--scenario", choices=SCENARIO_NAMES, required=True, help=scenario_help)
    _seed(cmd, "workspaces, samples and initial weights")
    cmd.add_argument("--quick", action="store_true", help=quick_help)
    cmd.add_argument("--out", required=True, metavar="DIR",
                     help=f"folder for the tables, new or empty, or holding this same {study} to resume it")


def _seed(parser: argparse.ArgumentParser, what: str) -> None:
    parser.add_argument("--seed", type=_int_in(0, SEEDS - 1), default=0, metavar="N",
                        help=f"random seed, 0..{SEEDS - 1} (default 0): {what}")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="toolkit", formatter_class=_formatter,
        epilog="examples:\n"
               "  toolkit reproduce --scenario 2ds --quick --out results/2ds-quick\n"
               "  toolkit train --scenario 3dc7 --preset strong --out runs/3dc7-strong\n"
               "  toolkit view --checkpoint runs/3dc7-strong\n"
               "  toolkit reproduce --help        (every command explains its options)")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND",
                                help="one of the commands above, then its options")
    sub.summaries = []  # filled by _subcommand, listed in the description
    scenario_help = "one of the paper's four scenarios, named in `toolkit --help`"

    reproduce = _subcommand(
        sub, "reproduce", "reproduce the paper's Tables 1-3 and figures",
        "Makes the data, trains the CAE and MLP, measures them (Tables 1, 2), plans with every\n"
        "sampler without and with prediction (Table 3) and writes DIR/results.json, DIR/tables.md\n"
        "(our figure next to the paper's in every cell) and PNG figures. Each finished stage is\n"
        "kept in DIR/cache: after Ctrl-C, the same command goes on where it stopped.",
        ["toolkit reproduce --scenario 2ds --out results/2ds            # the paper's 2D tables",
         "toolkit reproduce --scenario 3dc7 --quick --out results/try   # small counts, to try things",
         "toolkit reproduce --scenario all --preset strong --out results/strong"],
        cmd_reproduce)
    reproduce.add_argument("--scenario", choices=SCENARIO_NAMES + ["all"], required=True,
                           help=scenario_help + "; all: each of them in turn")
    reproduce.add_argument("--preset", choices=["paper", "strong"], default="paper",
                           help="paper: the paper's recipe (default); strong: ours, more accurate")
    reproduce.add_argument("--quick", action="store_true",
                           help="small counts (few workspaces, epochs and queries) to try the whole pipeline; "
                                "on 2 busy cores 2DS took under a minute, 3DC 1-2, 3DO 6 minutes; its figures "
                                "mean little")
    _seed(reproduce, "workspaces, samples, training and queries all follow from it")
    reproduce.add_argument("--out", required=True, metavar="DIR",
                           help="folder for the results, new or empty, or holding this same run to resume it")
    reproduce.add_argument("--workers", type=_int_in(1), default=None, metavar="N",
                           help="processes for planning, one sampler each (default: one per core; 1: all in "
                                "this process)")

    ablate = _subcommand(
        sub, "ablate", "walk from the paper's recipe to ours, one change at a time",
        "Trains one model per row, each row keeping the changes above it (toolkit/experiments/ablation.py:\n"
        "the CAE's loss and data, dropout, optimizer, input scaling, more workspaces, a wider MLP,\n"
        "local features, no z) and scores each on the same seen and unseen samples, balanced and\n"
        "validity-blind as the paper. Writes DIR/ablation.md and ablation.json; each finished row\n"
        "is kept in DIR/cache: after Ctrl-C, the same command goes on where it stopped.",
        ["toolkit ablate --scenario 2ds --out results/ablation-2ds"],
        cmd_ablate)
    _study_arguments(ablate, scenario_help, "small counts, to try the command; its figures mean little", "ablation")

    tune = _subcommand(
        sub, "tune", "choose the paper preset's unstated settings on held-out training workspaces",
        "The paper does not say how long its networks train, the MLP's batch, initialization or\n"
        "input scaling. This tries each (toolkit/experiments/tuning.py), fitting on 80 % of the training\n"
        "workspaces and scoring on the other 20 %; the unseen test workspaces are never used.\n"
        "Writes DIR/tuning.md and tuning.json; finished rows are kept in DIR/cache (resumable).",
        ["toolkit tune --scenario 2ds --out results/tuning-2ds"],
        cmd_tune)
    _study_arguments(tune, scenario_help, "a tenth of the epochs on few workspaces, to try the command", "tuning")

    train = _subcommand(
        sub, "train", "train the CAE and the collision MLP; write a checkpoint folder",
        "Makes the preset's training data, trains the CAE (it compresses a workspace's occupancy\n"
        "grid) and the MLP (it predicts whether a configuration is free), and writes DIR/weights.pt\n"
        "and DIR/meta.json with the test scores. `toolkit plan`, `view` and `bench` read DIR.",
        ["toolkit train --scenario 2ds --preset strong --out runs/2ds-strong",
         "toolkit train --scenario 3dc9 --quick --out runs/try --force   # replace runs/try"],
        cmd_train)
    train.add_argument("--scenario", choices=SCENARIO_NAMES, required=True, help=scenario_help)
    train.add_argument("--preset", choices=["paper", "strong"], default="paper",
                       help="paper: the paper's networks and settings (default); strong: ours, more accurate")
    _seed(train, "training data and initial weights")
    train.add_argument("--out", required=True, metavar="DIR", help="checkpoint folder to write (new or empty)")
    train.add_argument("--force", action="store_true", help="replace the checkpoint already in --out")
    train.add_argument("--quick", action="store_true",
                       help="few workspaces and epochs: seconds for 2DS and 3DC, minutes for 3DO; a weak model "
                            "for trying things out")
    train.add_argument("--device", default=None, help="torch device, e.g. cpu or cuda (default: cuda if present)")
    train.add_argument("--cae-epochs", type=_int_in(1), metavar="N", help="passes over the grids for the CAE "
                                                                          "(default: the preset's)")
    train.add_argument("--cae", action="store_true",
                       help="train the CAE even when the preset's MLP does not use its code z (strong): for its "
                            "reconstructions (Table 1); by default only the paper preset trains it")
    train.add_argument("--mlp-epochs", type=_int_in(1), metavar="N", help="passes over the samples for the MLP "
                                                                          "(default: the preset's)")

    plan = _subcommand(
        sub, "plan", "solve one planning query with PRM, with or without prediction",
        "Draws a workspace and a start and goal from --seed, builds a PRM roadmap with the sampler\n"
        "and searches it. With --predict the learned checker decides which samples are free (the\n"
        "paper's Algorithm 1); the returned path is always checked exactly.",
        ["toolkit plan --scenario 2ds --sampler OB",
         "toolkit plan --scenario 3dc7 --sampler BT --predict --checkpoint runs/3dc7-strong --json"],
        cmd_plan)
    plan.add_argument("--scenario", choices=SCENARIO_NAMES, required=True, help=scenario_help)
    plan.add_argument("--sampler", choices=SAMPLER_NAMES, default="BS",
                      help="how PRM draws its nodes (listed in `toolkit --help`; default BS)")
    plan.add_argument("--predict", action="store_true",
                      help="decide which samples are free with the learned checker (needs --checkpoint)")
    plan.add_argument("--checkpoint", metavar="DIR", help="a checkpoint folder from `toolkit train`")
    _seed(plan, "the workspace, start and goal, and the sampler's draws")
    plan.add_argument("--json", action="store_true",
                      help="print one JSON object (success, path, stats, workspace) instead of a sentence")

    bench = _subcommand(
        sub, "bench", "measure how fast the exact and the learned checker are",
        "Prints configurations checked per second by the exact checker (geometry) and by the\n"
        "learned one (the networks; untrained ones of the preset's sizes unless --checkpoint),\n"
        "their ratio, and exact edge checking. With --checkpoint it also plans a few of the\n"
        "paper's queries with and without that model and prints the time ratios. With --vs-ompl\n"
        "it races our planners against OMPL's PRM and RRTConnect on the same queries and checker.",
        ["toolkit bench --scenario 3dc7 --json",
         "toolkit bench --scenario 3dc9 --checkpoint runs/3dc9-strong --samplers BT --option rebridge=0",
         "toolkit bench --vs-ompl --scenario 3dc7 --queries 20 --seed 9000"],
        cmd_bench)
    bench.add_argument("--scenario", choices=SCENARIO_NAMES, required=True, help=scenario_help)
    _seed(bench, "the workspace and the configurations timed")
    bench.add_argument("--json", action="store_true", help="print one JSON object instead of lines")
    bench.add_argument("--preset", choices=["paper", "strong"], default="paper",
                       help="network sizes whose learned speed is measured (default paper; speed does not depend "
                            "on the weights)")
    bench.add_argument("--batch", type=_int_in(1, 1_000_000), metavar="N",
                       help="configurations per call for both checkers, 1..1000000 (default: 20,000 exact, "
                            "10,000 learned; a sampler asks for 200-2,000)")
    bench.add_argument("--checkpoint", metavar="DIR", help="a trained model (from `toolkit train`, or "
                       "DIR/cache/checkpoint of `toolkit reproduce`): also time PRM with and without it")
    bench.add_argument("--workspaces", type=_int_in(1, 100), default=2, metavar="N",
                       help="with --checkpoint: query workspaces to plan in, 1..100 (default 2)")
    bench.add_argument("--pairs", type=_int_in(1, 10), default=2, metavar="N",
                       help="with --checkpoint: start/goal pairs per workspace, 1..10 (default 2)")
    bench.add_argument("--samplers", type=_samplers, default=SAMPLER_NAMES, metavar="LIST",
                       help="with --checkpoint: comma-separated samplers to plan with, e.g. BT,OB (default: all four)")
    bench.add_argument("--vs-ompl", action="store_true",
                       help="instead: plan --queries N queries with our planners (best exact, the paper's baseline, "
                            "and with --checkpoint's model) and OMPL's PRM and RRTConnect on the same exact checker, "
                            "in turns, one thread, and print a markdown table (needs the ompl extra: "
                            "pip install 'sample-collision-toolkit[ompl]'); use a --seed the planner was not tuned on "
                            "(not 0 or 7100), e.g. 9000")
    bench.add_argument("--queries", type=_int_in(1, 1000), default=10, metavar="N",
                       help="with --vs-ompl: the first N queries of the seed's query set (default 10)")
    bench.add_argument("--ompl-seconds", type=float, default=30.0, metavar="S",
                       help="with --vs-ompl: OMPL's time limit per query (default 30)")
    bench.add_argument("--option", type=_planner_option, action="append", default=[], metavar="NAME=VALUE",
                       help="with --checkpoint: a planner setting (a PRMOptions field in toolkit/planning/prm.py) for both "
                            "runs, e.g. rebridge=0; repeat for several")

    view = _subcommand(
        sub, "view", "show a scenario in your browser (Viser)",
        "Serves a 3D scene on this computer and prints the address to open: the workspace, the\n"
        "robot colored by the exact checker (green free, red colliding), a slider per joint,\n"
        "samples, and a PRM roadmap with its path. Ctrl-C stops it.",
        ["toolkit view --scenario 3do",
         "toolkit view --checkpoint runs/3dc7-strong          # also the model's predictions",
         "toolkit view --scenario 3dc9 --samples 300 --screenshot scene.png"],
        cmd_view)
    view.add_argument("--scenario", choices=SCENARIO_NAMES, default=None,
                      help=scenario_help + "; default: the checkpoint's, else 3do")
    _seed(view, "which workspace is shown")
    view.add_argument("--checkpoint", metavar="DIR", help="a checkpoint folder: show the model's predictions too")
    view.add_argument("--host", default="127.0.0.1",
                      help="address to serve on (default 127.0.0.1: this computer only; 0.0.0.0: every network)")
    view.add_argument("--port", type=_int_in(0, 65535), default=8080,
                      help="first port to try, 0..65535 (default 8080; a busy one moves to the next free; "
                           "0: any free port)")
    view.add_argument("--samples", type=_int_in(0, 100_000), default=0, metavar="N",
                      help="show N uniform samples at the start, 0..100000 (default 0)")
    view.add_argument("--screenshot", metavar="PNG",
                      help="save a picture of the page from a headless Chromium and exit (needs Chromium and "
                           "Playwright: `make browser`, the dev extras)")
    grade = _subcommand(
        sub, "grade", "grade filled-in assignment notebooks with otter",
        "Runs each student notebook with the assignment's public and hidden tests (otter-grader,\n"
        "no Docker), prints a report per notebook with feedback, and ends with `score: X/Y`.\n"
        "Questions answered in prose are graded by hand and not counted here.",
        ["toolkit grade submissions/bridge_test.ipynb",
         "toolkit grade submissions/ --csv scores.csv       # every notebook in the folder"],
        cmd_grade)
    grade.add_argument("notebooks", nargs="+", help="student notebooks, or folders of them")
    grade.add_argument("--assignment", help="assignment name (default: read from each notebook, else its file name)")
    grade.add_argument("--timeout", type=float, help="seconds a notebook may run before it scores 0 (default: 600)")
    grade.add_argument("--csv", help="also write one row of scores per notebook to this CSV file")
    grade.add_argument("--json", action="store_true", help="print one JSON object a notebook instead of the report")
    parser.description = ("Learn, reproduce and extend \"Predicting Sample Collision with Neural Networks\"\n"
                          "(Tran, Denny, Ekenna): a neural network that tells a planner, faster than geometry,\n"
                          "whether a robot configuration collides.\n\n"
                          "commands (toolkit COMMAND --help explains each one):\n" + "\n".join(sub.summaries)
                          + "\n\n" + GLOSSARY)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    from toolkit.util import threads

    try:
        with _signals_interrupt(), threads.limited(threads.configured()):
            return int(args.func(args) or 0)
    except Interrupted as stop:
        name = signal.Signals(stop.signum).name
        print(f"toolkit {args.command}: stopped by {name}; {KEPT[args.command](args)}", file=sys.stderr)
        return 128 + stop.signum
    except (ValueError, OSError) as err:
        print(f"toolkit {args.command}: error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
