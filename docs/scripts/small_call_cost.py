"""What a small call costs the compiled box checker per configuration, against one batch (docs/benchmarks.md,
"For maintainers", "Inside the compiled checker").

    python docs/scripts/small_call_cost.py [SCENARIOS [ROUNDS]]

Per scenario (default ``3dc7,3dc9,3do``), :func:`toolkit.experiments.bench.small_call_cost`: on the first query
workspace, 20,000 uniform configurations; each round times by the thread's CPU clock one call of all of them, 20,000
calls of none, and the same configurations cut in calls of 16, 32 and 64. Prints the medians over the rounds (default
7): the batch's cost per configuration, an empty call's cost, per call size a configuration's cost over its batched
cost (what ``toolkit bench --scenario S --json`` prints as ``exact_small_call_cost``: the same function), and what a
call of 16 costs beyond checking its configurations at the batch's rate (the fixed cost of a call: the target, calls
of 16 within twice the batched cost, needs it below 16 batched checks). Run it several times, in turns with the code
it is compared with, and take the median of the runs: on a shared machine one run moves by several per cent.
"""

import sys

from toolkit.experiments.bench import small_call_cost
from toolkit.experiments.small_calls import SMALL_CALLS
from toolkit.scenarios import get

if __name__ == "__main__":
    names = sys.argv[1].split(",") if len(sys.argv) > 1 else ["3dc7", "3dc9", "3do"]
    n_rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 7
    for name in names:
        cost = small_call_cost(get(name), repeats=n_rounds)
        ratios = "  ".join(f"{size}: {cost['ratios'][str(size)]:.2f}x" for size in SMALL_CALLS)
        line = f"{name}: batch {cost['batch_ns']:.1f} ns/cfg  empty {cost['empty_ns']:.0f} ns  {ratios}"
        print(f"{line}  fixed(16) {cost['fixed_16_ns']:.0f} ns", flush=True)
