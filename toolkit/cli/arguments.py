"""The pieces the ``toolkit`` command's options are made of: checked types, the registries' choices, shared options.

An argument type (:func:`int_in`, :func:`sampler_list`, :func:`planner_option`) names the
rule it checks, and argparse adds the flag, so every bad number or name is refused with
the flag in the message. Scenarios, samplers and presets are offered as the registries
hold them when the parser is built (``scenarios.register``,
``sampling.register_sampler``, ``presets.register``), so one registered by a module of
yours (``--import MODULE``, read by :func:`imports_in` before the parser is built) is
offered, listed in ``toolkit --help`` (:func:`glossary`) and checked like the
toolkit's own. The building blocks (:func:`seed`, :func:`scenario`, :func:`preset`,
:func:`study`) add an option several sub-commands share, worded alike in each;
:mod:`toolkit.cli.parser` puts them together.
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Callable, Sequence

from toolkit import scenarios
from toolkit.learning import presets
from toolkit.planning import prm, sampling

SEEDS = 2**32  # seeds are 0 .. 2**32 - 1
PRESET_WORDS = {
    "paper": "the paper's networks and training settings",
    "strong": "ours: the MLP also sees the occupancy around the robot and where its links are; far more accurate "
    "(docs/results.md)",
}


# -- argument types: each names the rule it checks; argparse adds the flag ----------------------


def int_in(low: int, high: int | None = None) -> Callable[[str], int]:
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


def positive_float(text: str) -> float:
    """An argparse type: a number above 0 (seconds, say)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a number above 0, got {text!r}") from None
    if not value > 0:
        raise argparse.ArgumentTypeError(f"must be above 0, got {text}")
    return value


def sampler_list(text: str) -> tuple[str, ...]:
    """An argparse type: comma-separated names of registered samplers."""
    try:
        return sampling.check_names(text.split(","))
    except ValueError as err:
        raise argparse.ArgumentTypeError(str(err)) from None


def planner_option(text: str) -> tuple[str, object]:
    """An argparse type: ``NAME=VALUE``, the value read as JSON (``rebridge=0``, ``screen_edges=false``)."""
    name, sep, value = text.partition("=")
    if not sep or not name:
        raise argparse.ArgumentTypeError(f"expected NAME=VALUE, got {text!r}")
    try:
        return name, json.loads(value)
    except json.JSONDecodeError:
        return name, value  # a string, e.g. auxiliary=exact


# -- what the registries hold -------------------------------------------------------------------


def scenario_names() -> list[str]:
    return sorted(scenarios.SCENARIOS)


def sampler_names() -> list[str]:
    """The paper's four first, then registered ones, in the order they were registered."""
    return list(sampling.SAMPLERS)


def glossary() -> str:
    """The scenarios, samplers and presets in words, for ``toolkit --help``."""

    def first_line(text: str | None) -> str:
        return (text or "").strip().splitlines()[0] if (text or "").strip() else "(registered)"

    return "\n".join(
        ["scenarios (--scenario):"]
        + [f"  {s.name:6}{s.title}" for s in scenarios.SCENARIOS.values()]
        + ["", "samplers (--sampler, --samplers), how PRM draws its nodes:"]
        + [f"  {name:6}{cls.summary or first_line(cls.__doc__)}" for name, cls in sampling.SAMPLERS.items()]
        + ["", "presets (--preset):"]
        + [f"  {name:8}{PRESET_WORDS.get(name, 'registered (--import)')}" for name in presets.PRESETS]
        + [
            "",
            "your own sampler, preset or scenario: --import MODULE (a module that registers it), on any command.",
            "",
            "threads: torch and numpy use one thread, fastest when other programs share the machine;",
            "TOOLKIT_THREADS=N uses N (0: one per core). See toolkit/util/threads.py.",
        ]
    )


# -- building blocks ----------------------------------------------------------------------------

SCENARIO_HELP = "one of the scenarios named in `toolkit --help`"


def help_formatter(prog: str) -> argparse.HelpFormatter:
    """Help as written (line breaks kept in descriptions and examples), options in a wide first column."""
    return argparse.RawDescriptionHelpFormatter(prog, max_help_position=28)


def imports_parent() -> argparse.ArgumentParser:
    """The ``--import`` option every sub-command takes (``main`` reads it before the parser is built)."""
    parent = argparse.ArgumentParser(add_help=False)
    parent.add_argument(
        "--import",
        dest="imports",
        action="append",
        default=[],
        metavar="MODULE",
        help="import MODULE (a module name or a .py file) first: what it registers (a sampler, "
        "preset or scenario) is offered like the toolkit's own; repeat for several",
    )
    return parent


def seed(parser: argparse.ArgumentParser, what: str) -> None:
    parser.add_argument(
        "--seed",
        type=int_in(0, SEEDS - 1),
        default=0,
        metavar="N",
        help=f"random seed, 0..{SEEDS - 1} (default 0): {what}",
    )


def scenario(parser: argparse.ArgumentParser, *, extra: Sequence[str] = (), **kwargs) -> None:
    parser.add_argument("--scenario", choices=scenario_names() + list(extra), **kwargs)


def planner(parser: argparse.ArgumentParser, help: str) -> None:
    """``--planner NAME``, a registered planner (``toolkit.planning.prm.names()``), and ``--option NAME=VALUE``, a
    parameter of it."""
    parser.add_argument(
        "--planner",
        choices=prm.names(),
        default=None,
        help=f"{help}; one of {', '.join(prm.names())} (paper: the paper's Algorithm 1; lazy: the lazy PRM, the "
        "best exact planner; batched: the lazy PRM with each round's samples in one checker call, for a GPU; or one "
        f"registered by --import). Default: {prm.DEFAULT}, with or without prediction",
    )
    parser.add_argument(
        "--option",
        type=planner_option,
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a parameter of the planner (a field of its Params, e.g. PaperParams or LazyParams in "
        "toolkit/planning/options.py), e.g. rebridge=0; repeat for several",
    )


def preset(parser: argparse.ArgumentParser, help: str) -> None:
    parser.add_argument("--preset", choices=list(presets.PRESETS), default="paper", help=help)


def study(parser: argparse.ArgumentParser, quick_help: str, what: str) -> None:
    """The options `ablate` and `tune` share: a scenario, a seed, --quick and a resumable --out folder."""
    scenario(parser, required=True, help=SCENARIO_HELP)
    seed(parser, "workspaces, samples and initial weights")
    parser.add_argument("--quick", action="store_true", help=quick_help)
    parser.add_argument(
        "--out",
        required=True,
        metavar="DIR",
        help=f"folder for the tables, new or empty, or holding this same {what} to resume it",
    )


def imports_in(argv: list[str]) -> list[str]:
    """The ``--import MODULE`` values anywhere in ``argv`` (read before the parser, whose choices they change)."""
    pre = argparse.ArgumentParser(add_help=False)
    pre.add_argument("--import", dest="imports", action="append", default=[])
    return pre.parse_known_args(argv)[0].imports
