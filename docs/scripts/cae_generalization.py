"""The CAE's reconstruction accuracy on seen and unseen workspaces, by training data and loss
reading (docs/fidelity.md §2-3).

    python docs/scripts/cae_generalization.py SCENARIO CONFIGS [LR STEPS [BATCH]]

CONFIGS: comma-separated ``DATA:LOSS``, DATA ``paper`` (the paper preset's CAE on the
scenario's seen grids) or a number of generated grids (AdamW, LR, STEPS, BATCH;
default 1e-3, 2500, 100), LOSS ``sum`` or ``mean`` (``Preset.cae_loss``). Prints one JSON
line per config: accuracy on (up to 200) training grids, the seen and unseen test
grids, the unseen grids' all-free share, seconds. One torch thread.
"""

import dataclasses
import json
import sys
import time

import numpy as np
import torch

from toolkit import scenarios
from toolkit.learning import data, metrics, models, presets, training

torch.set_num_threads(1)
name, configs = sys.argv[1], sys.argv[2].split(",")
lr, steps = (float(a) for a in (sys.argv[3:5] if len(sys.argv) > 4 else (1e-3, 2500)))
batch = int(sys.argv[5]) if len(sys.argv) > 5 else 100
s = scenarios.get(name)
seen = torch.as_tensor(np.stack([w.occupancy() for w in s.workspaces("seen", s.n_seen, 0)]))
unseen = torch.as_tensor(np.stack([w.occupancy() for w in s.workspaces("unseen", s.n_unseen, 0)]))
paper = presets.get("paper")
for config in configs:
    kind, loss = config.split(":")
    if kind == "paper":
        preset, grids = dataclasses.replace(paper, cae_loss=loss), seen
    else:
        preset = dataclasses.replace(
            paper, cae_loss=loss, cae_lr=lr, cae_batch=batch, cae_max_steps=int(steps), cae_epochs=10**6
        )
        grids = torch.as_tensor(data.occupancy_grids(s, "cae_grids", int(kind), 0))
    torch.manual_seed(0)
    predictor = models.build_predictor(s, "raw")
    began = time.perf_counter()
    training.train_cae(predictor, grids, preset, torch.Generator().manual_seed(0), progress=False)
    seconds = time.perf_counter() - began
    with torch.no_grad():
        acc = {
            k: float(metrics.reconstruction_accuracy(predictor.cae(g.float()).numpy(), g.numpy()).mean())
            for k, g in (("train", grids[:200]), ("seen", seen), ("unseen", unseen))
        }
    print(
        json.dumps(
            dict(
                scenario=name,
                config=config,
                lr=lr if kind != "paper" else paper.cae_lr,
                batch=batch if kind != "paper" else paper.cae_batch,
                seconds=round(seconds),
                **{k: round(v, 4) for k, v in acc.items()},
                all_free_unseen=round(float((unseen < 0).float().mean()), 4),
            )
        ),
        flush=True,
    )
