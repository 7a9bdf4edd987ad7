"""What a run over a query set reports (§V, Table 3): means, spreads and rates of the per-query records.

Each query's record holds the planner's ``stats`` (:class:`toolkit.planning.planner.PlanResult`),
``encode_s`` (its share of encoding the workspace), ``success`` and ``path_valid``.
:func:`summarize` turns a list of them into means and stds of the times and counts, medians and
quartiles of the times (robust to the odd slow query on a shared machine), each stage's share of
a query's time, and the success and path-validity rates in [0, 1].
"""

from __future__ import annotations

import numpy as np

TIMES = ("sampling_s", "connection_s", "query_s", "encode_s", "total_s")  # a query's times, in seconds
TIMED_STAGES = ("sampling_s", "connection_s", "query_s")  # the parts of total_s the planner times (the rest: set-up)
MEANS = ("sampling_s", "connection_s", "query_s", "total_s", "encode_s", "exact_checks", "predicted_checks")
COUNTS = ("rounds", "repairs")  # a roadmap planner's counters (0 for a planner without them)


def summarize(records: list[dict]) -> dict:
    """Means and stds over queries of the times and counts, medians and quartiles (``_q1``, ``_q3``) of the times,
    each query's total, each stage's mean share of a query's total (``_share``); success and path-validity rates
    in [0, 1]; ``planner``, the name of the planner that ran (when the records say)."""

    def values(key):
        return np.array([r.get(key, 0) for r in records], dtype=float)

    summary: dict = {"n_queries": len(records)}
    if planners := sorted({r["planner"] for r in records if "planner" in r}):
        summary["planner"] = ", ".join(planners)
    for key in MEANS + COUNTS:
        summary[key] = float(values(key).mean()) if records else 0.0
        summary[key + "_std"] = float(values(key).std()) if records else 0.0
    for key in TIMES:  # robust to the odd slow query on a noisy machine: median and quartiles
        q1, median, q3 = np.percentile(values(key), (25, 50, 75)) if records else (0.0, 0.0, 0.0)
        summary.update({key + "_median": float(median), key + "_q1": float(q1), key + "_q3": float(q3)})
    summary["total_s_per_query"] = values("total_s").tolist()  # in the order of the queries: names an outlier
    for key in TIMED_STAGES:  # where a typical query's time goes: each stage's share of a query's total, averaged
        summary[key + "_share"] = float(np.mean(values(key) / np.maximum(values("total_s"), 1e-12))) if records else 0.0
    solved = [r for r in records if r["success"]]
    summary["success_rate"] = len(solved) / len(records) if records else 0.0
    summary["path_valid_rate"] = float(np.mean([r["path_valid"] for r in solved])) if solved else 1.0
    return summary
