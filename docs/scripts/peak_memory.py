"""Peak memory of a command and every process it starts, sampled from /proc (Linux).

    python docs/scripts/peak_memory.py [--every SECONDS] -- COMMAND [ARG ...]

e.g. ``python docs/scripts/peak_memory.py -- toolkit reproduce --scenario 3dc9 --preset strong --out DIR``.
A reproduction plans in worker processes (``--workers``), so the peak of one process (``/usr/bin/time -v``'s
"maximum resident set size") says too little: this samples the resident memory of the whole process tree
every ``--every`` seconds (default 0.2) and prints one JSON line with the command's exit status, its wall time,
the peak of the tree's sum and the peak of its largest process, in MiB. Memory shared between processes
(numpy and torch's libraries) is counted once per process, so the sum is an upper bound.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

PAGE_MIB = os.sysconf("SC_PAGE_SIZE") / 2**20


def children_of() -> dict[int, list[int]]:
    """Every live process's children, read from /proc/PID/stat (the parent is its fourth field)."""
    tree: dict[int, list[int]] = {}
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:  # the process ended while we read
            continue
        parent = int(stat.rsplit(")", 1)[1].split()[1])
        tree.setdefault(parent, []).append(int(entry.name))
    return tree


def resident_mib(pid: int) -> float:
    """Resident memory of one process in MiB (the second field of /proc/PID/statm), 0 if it has ended."""
    try:
        return int(Path(f"/proc/{pid}/statm").read_text().split()[1]) * PAGE_MIB
    except (OSError, IndexError, ValueError):
        return 0.0


def tree_resident(root: int) -> tuple[float, float]:
    """(sum, largest) resident memory in MiB over ``root`` and all its descendants."""
    tree, pending, sizes = children_of(), [root], []
    while pending:
        pid = pending.pop()
        sizes.append(resident_mib(pid))
        pending.extend(tree.get(pid, []))
    return sum(sizes), max(sizes)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--every", type=float, default=0.2, help="seconds between samples (default 0.2)")
    parser.add_argument("command", nargs=argparse.REMAINDER, help="the command to measure, after --")
    args = parser.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("name the command to measure after --")
    if not args.every > 0:
        parser.error(f"--every must be a positive number of seconds, got {args.every}")
    start = time.perf_counter()
    process = subprocess.Popen(command)
    peak_sum = peak_one = 0.0
    while process.poll() is None:
        total, largest = tree_resident(process.pid)
        peak_sum, peak_one = max(peak_sum, total), max(peak_one, largest)
        time.sleep(args.every)
    report = {
        "command": " ".join(command),
        "returncode": process.returncode,
        "wall_s": round(time.perf_counter() - start, 1),
        "peak_tree_mib": round(peak_sum),
        "peak_one_process_mib": round(peak_one),
    }
    print(json.dumps(report), flush=True)
    return process.returncode


if __name__ == "__main__":
    sys.exit(main())
