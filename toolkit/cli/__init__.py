"""The ``toolkit`` command (also ``python -m toolkit``): one sub-command per job.

Reading order: :mod:`toolkit.cli.arguments` (the checked argument types, the choices read
from the registries, the options several sub-commands share), :mod:`toolkit.cli.parser`
(each sub-command's options and help text; ``bench``'s in :mod:`toolkit.cli.bench_parser`),
:mod:`toolkit.cli.commands` (each sub-command: a run configuration, then one library call),
and :func:`main` here, which imports the modules named by ``--import`` first (so that what
they register is offered), runs the command on :func:`toolkit.util.threads.configured`
threads and turns errors and signals into exit codes: a clear message and 2 for bad input;
Ctrl-C or SIGTERM stops a command within seconds, says what it kept and exits with 128 +
the signal's number (130, 143), as shells expect.
"""

from __future__ import annotations

import argparse
import signal
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType

from toolkit.cli import arguments, parser
from toolkit.cli.commands import COMMANDS, KEPT
from toolkit.util import plugins, threads

SIGNALS = (signal.SIGINT, signal.SIGTERM)  # what stops a command


class Interrupted(KeyboardInterrupt):
    """Ctrl-C (SIGINT) or SIGTERM, raised in the main thread so that every ``finally`` runs."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.signum = signum


@contextmanager
def signals_interrupt() -> Iterator[None]:
    """SIGINT and SIGTERM raise :class:`Interrupted` inside, once: a second signal while the command stops ends
    it at once (planning processes notice within a second that it is gone, and end too). A signal that comes
    while an output is written waits until the write is undone or done (:func:`toolkit.util.outputs.signals_held`),
    so neither signal leaves a temporary or half a file behind."""

    def interrupt(signum: int, frame: FrameType | None) -> None:
        for sig in SIGNALS:
            signal.signal(sig, signal.SIG_DFL)
        raise Interrupted(signum)

    handlers = {sig: signal.signal(sig, interrupt) for sig in SIGNALS}
    try:
        yield
    finally:
        for sig, handler in handlers.items():
            signal.signal(sig, handler)


def build_parser() -> argparse.ArgumentParser:
    """The ``toolkit`` parser, offering what the registries hold now."""
    return parser.build_parser(COMMANDS)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    try:
        for module in arguments.imports_in(argv):  # before the parser: they add to its choices
            plugins.import_module(module)
    except ValueError as err:
        print(f"toolkit: error: {err}", file=sys.stderr)
        return 2
    args = build_parser().parse_args(argv)
    try:
        with signals_interrupt(), threads.limited(threads.configured()):
            return int(args.func(args) or 0)
    except Interrupted as stop:
        name = signal.Signals(stop.signum).name
        print(f"toolkit {args.command}: stopped by {name}; {KEPT[args.command](args)}", file=sys.stderr)
        return 128 + stop.signum
    except (ValueError, OSError) as err:
        print(f"toolkit {args.command}: error: {err}", file=sys.stderr)
        return 2


__all__ = ["Interrupted", "build_parser", "main", "signals_interrupt"]
