"""The GPU figures the project records (``docs/gpu.md``), read by chapter 04: a student's laptop has no GPU.

``docs/scripts/gpu_measure.py`` measures, on a lent GPU, the learned checker and the exact check in torch
on the same device (issue 50) and writes ``gpu_record.json``; a copy travels with the package, beside this
file. Until a GPU has run it, the packaged record says ``"measured": false`` and holds no figures, and
the chapter says so instead of showing any::

    from toolkit.teaching import gpu_record
    record = gpu_record.packaged()
    gpu_record.measured(record)          # False until a GPU session records its run
    gpu_record.crossover_table(record)   # markdown: per batch, the cheapest checker and two ratios
"""

from __future__ import annotations

import json
from functools import cache
from importlib import resources

from toolkit.experiments.on_device import COLUMNS

NOT_MEASURED = (
    "The GPU figures are not yet measured: no GPU session has run `docs/scripts/gpu_measure.py` since the "
    "code it measures was written. This cell shows them once one has."
)


@cache
def packaged() -> dict:
    """The record as the package carries it (``gpu_record.json``)."""
    return json.loads(resources.files(__package__).joinpath("gpu_record.json").read_text(encoding="utf-8"))


def measured(record: dict) -> bool:
    """Whether ``record`` holds figures measured on a GPU (not a CPU try of the script, not the empty record)."""
    return bool(record.get("measured"))


def environment(record: dict) -> str:
    """One line: the device, CUDA and torch the figures were measured with, and the command."""
    env = record["environment"]
    return f"Measured on {env['device']} (CUDA {env['cuda']}, torch {env['torch']}) by `{record['command']}`."


def crossover_table(record: dict) -> str:
    """Markdown: per batch of 3DC-7's sweep on one device, the cheapest checker, and the network's cost over the
    exact check's with both on the device (resident) and with both on the CPU (below 1: the network is cheaper)."""
    found = record["crossover_3dc7"]
    lines = [
        "| configurations a call | cheapest | network / exact, both on the GPU | network / exact, both on the CPU |",
        "| ---: | --- | ---: | ---: |",
    ]
    for i, batch in enumerate(found["values"]):
        gpu = found["learned_device_us"][i] / found["exact_device_us"][i]
        cpu = found["learned_cpu_us"][i] / found["exact_cpu_us"][i]
        lines.append(f"| {batch:,} | {COLUMNS[found['fastest'][i]]} | {gpu:.2f} | {cpu:.2f} |")
    return "\n".join(lines)
