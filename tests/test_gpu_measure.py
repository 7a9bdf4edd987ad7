"""The one prepared GPU run (docs/scripts/gpu_measure.py) tried on the CPU, and the record chapter 04 reads."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from toolkit.experiments import on_device
from toolkit.teaching import gpu_record

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def quick_run(tmp_path_factory) -> Path:
    """``gpu_measure.py --device cpu --quick --out DIR``, once for the module."""
    out = tmp_path_factory.mktemp("gpu")
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONUNBUFFERED="1")
    script = ROOT / "docs" / "scripts" / "gpu_measure.py"
    done = subprocess.run(
        [sys.executable, str(script), "--device", "cpu", "--quick", "--out", str(out)],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    return out


def test_the_quick_run_measures_every_kind_and_every_exact_answer_agrees(quick_run):
    rows = [json.loads(line) for line in (quick_run / "gpu_measure.jsonl").read_text().splitlines()]
    kinds = [r["measure"] for r in rows]
    assert kinds == ["environment"] + ["agreement"] * 4 + ["throughput", "latency", "latency", "crossover", "table3"]
    for row in rows[1:5]:
        assert row["uniform_disagree_compiled"] == row["near_contact_disagree_compiled"] == 0, row
        assert row.get("disagree_fcl", 0) == 0, row
    throughput = rows[5]
    for key in ("learned_cfg_per_s", "learned_resident_cfg_per_s", "exact_device_cfg_per_s"):
        assert throughput[key] > 0
    for latency in rows[6:8]:
        assert latency["learned_direct_ms"] > 0 and latency["graph_equals_direct"] is True
    assert rows[8]["variables"]["batch"]["disagreements"] == [0] * len(on_device.QUICK_BATCHES)
    table3 = rows[9]
    assert table3["planner"] == "batched" and list(table3["planning"]) == ["BS"]
    for mode in ("without", "with"):
        summary = table3["planning"]["BS"][mode]
        assert summary["planner"] == "batched" and summary["path_valid_rate"] == 1.0 and summary["n_queries"] > 0
    results = json.loads((quick_run / "table3_3dc7" / "results.json").read_text())
    assert results["planner"] == "batched" and results["throughput"]["device"] == "cpu"
    text = (quick_run / "gpu_measure.md").read_text()
    assert "## table3" in text and "| BS | with |" in text and "# One device: 3dc7" in text


def test_the_record_a_cpu_run_writes_is_readable_and_says_it_was_not_measured_on_a_gpu(quick_run):
    record = json.loads((quick_run / "gpu_record.json").read_text())
    assert not gpu_record.measured(record) and record["environment"]["quick"] is True
    table = gpu_record.crossover_table(record).splitlines()
    assert len(table) == 2 + len(on_device.QUICK_BATCHES) and table[2].startswith("| 256 | ")
    assert gpu_record.environment(record).startswith("Measured on ")
    assert record["table3_3dc7"]["BS"]["with"]["planner"] == "batched"


def test_the_packaged_record_and_docs_gpu_md_agree_on_whether_the_gpu_was_measured():
    record = gpu_record.packaged()
    gpu_md = (ROOT / "docs" / "gpu.md").read_text()
    if gpu_record.measured(record):
        assert record["environment"]["device"] in gpu_md
    else:
        assert "not yet measured" in gpu_md and "not yet measured" in gpu_record.NOT_MEASURED
