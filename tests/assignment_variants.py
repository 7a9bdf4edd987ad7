"""Wrong answers to the course assignments, each one a test of its grader (tests/test_assignments.py).

A variant is the code a student might write for one function of an assignment, wrong in one way;
it replaces the solution cell that defines the same function in the master's solved notebook.
Graded like a submission, it must score below full marks on every question in ``loses`` and full
marks on the others. To plant another wrong answer, add one entry to :data:`VARIANTS`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Variant:
    assignment: str
    loses: frozenset[str]  # the questions it must lose points on; every other question scores full marks
    code: str  # one function definition, replacing the solution cell that defines the same name

    @property
    def function(self) -> str:
        """The name of the function the variant defines."""
        found = re.search(r"^def (\w+)\(", self.code, re.MULTILINE)
        assert found, f"a variant defines a function: {self.code[:80]!r}"
        return found[1]


def _variant(assignment: str, loses: str, code: str) -> Variant:
    return Variant(assignment, frozenset(loses.split()), code.strip() + "\n")


VARIANTS: dict[str, Variant] = {
    # bridge_test, Q1: the sampler
    "bridge_sigma_squared": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + sigma**2 * rng.standard_normal(Q1.shape)  # the variance where the deviation belongs
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
    ),
    "bridge_keeps_invalid_midpoints": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + sigma * rng.standard_normal(Q1.shape)
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    return middles, Q1[blocked], Q2[blocked]  # the midpoint is never checked
""",
    ),
    "bridge_checks_one_end": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + sigma * rng.standard_normal(Q1.shape)
    blocked = np.flatnonzero(~free(checker, Q1))  # q2 is never checked
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
    ),
    "bridge_returns_nothing": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    empty = np.zeros((0, checker.robot.dof))
    return empty, empty, empty
""",
    ),
    "bridge_keeps_every_other_sample": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + sigma * rng.standard_normal(Q1.shape)
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = np.flatnonzero(free(checker, middles))[::2]  # half of what qualifies
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
    ),
    "bridge_calls_the_library": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    middles = sampling.BridgeTestSampler(checker, sigma).sample(n_attempts, rng)
    return middles, middles - sigma / 2, middles + sigma / 2  # made-up ends
""",
    ),
    # bridge_test, Q2: the share in the passage
    "passage_half_hard_coded": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    return 0.5
""",
    ),
    "passage_boundary_excluded": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    if len(Q) == 0:
        return 0.0
    return float(np.all((Q > passage[0]) & (Q < passage[1]), axis=1).mean())
""",
    ),
    "passage_empty_is_nan": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    return float(np.all((Q >= passage[0]) & (Q <= passage[1]), axis=1).mean())
""",
    ),
}

VARIANTS |= {
    # verify_and_repair, Q1: the loop
    "repair_trusts_the_liar": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    return roadmap.shortest_path(start, goal)  # nothing verified
""",
    ),
    "repair_checks_nodes_only": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while True:
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        ok = exact.are_valid(roadmap.nodes[path])
        if ok.all():
            return path
        roadmap.remove_edges(np.isin(roadmap.edges, path[~ok]).any(axis=1))
""",
    ),
    "repair_checks_edges_only": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while True:
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~ok])
""",
    ),
    "repair_skips_the_last_edge": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while True:
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        ok = exact.are_valid(roadmap.nodes[path])
        if not ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~ok]).any(axis=1))
            continue
        steps = roadmap.edge_index(path)[:-1]  # every step but the last
        ok = check_edges(exact, roadmap.nodes[path[:-2]], roadmap.nodes[path[1:-1]], resolution)
        if ok.all():
            return path
        roadmap.remove_edges(steps[~ok])
""",
    ),
    "repair_checks_edges_8x_coarser": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while True:
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        ok = exact.are_valid(roadmap.nodes[path])
        if not ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~ok]).any(axis=1))
            continue
        ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], 8 * resolution)
        if ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~ok])
""",
    ),
}

VARIANTS |= {
    # evaluating_a_checker, Q1: rates per workspace
    "rates_tpr_and_tnr_swapped": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    predicted_valid, valid = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    with np.errstate(invalid="ignore"):
        return {
            "acc": (predicted_valid == valid).mean(axis=1),
            "tnr": (predicted_valid & valid).sum(axis=1) / valid.sum(axis=1),  # the names swapped
            "tpr": (~predicted_valid & ~valid).sum(axis=1) / (~valid).sum(axis=1),
        }
""",
    ),
    "rates_call_the_library": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    from toolkit.learning.metrics import classification

    per_workspace = [classification(p, v) for p, v in zip(predicted_valid, valid)]
    return {key: np.array([r[key] for r in per_workspace]) for key in ("acc", "tpr", "tnr")}
""",
    ),
    "rates_pooled_not_per_workspace": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool).ravel(), np.asarray(valid, bool).ravel()
    W = len(predicted_valid)
    return {
        "acc": np.full(W, np.mean(p == v)),
        "tpr": np.full(W, np.mean(p[v]) if v.any() else np.nan),
        "tnr": np.full(W, np.mean(~p[~v]) if (~v).any() else np.nan),
    }
""",
    ),
    "rates_absent_class_is_zero": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    predicted_valid, valid = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    return {
        "acc": (predicted_valid == valid).mean(axis=1),
        "tpr": (predicted_valid & valid).sum(axis=1) / np.maximum(valid.sum(axis=1), 1),
        "tnr": (~predicted_valid & ~valid).sum(axis=1) / np.maximum((~valid).sum(axis=1), 1),
    }
""",
    ),
    # evaluating_a_checker, Q2: the threshold
    "threshold_upper_median": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: sorted(r["total_s"] for r in records) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(sorted(ok), key=lambda t: ok[t][len(ok[t]) // 2]) if ok else None
""",
    ),
    "threshold_lower_median": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: sorted(r["total_s"] for r in records) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(sorted(ok), key=lambda t: ok[t][(len(ok[t]) - 1) // 2]) if ok else None
""",
    ),
    "threshold_mean_not_median": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.mean([r["total_s"] for r in records]) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(sorted(ok), key=ok.get) if ok else None
""",
    ),
    "threshold_the_largest": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    return max(runs)
""",
    ),
    "threshold_ignores_invalid_paths": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.median([r["total_s"] for r in records]) for t, records in runs.items()
          if all(r["success"] for r in records)}
    return min(sorted(ok), key=ok.get) if ok else None
""",
    ),
    "threshold_ties_go_up": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.median([r["total_s"] for r in records]) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(sorted(ok, reverse=True), key=ok.get) if ok else None
""",
    ),
}

VARIANTS |= {
    # cae_loss, Q1: the contractive penalty
    "penalty_without_gradient": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    x = grids.reshape(len(grids), -1).detach().requires_grad_(True)
    z = cae.encode(x)
    rows = [torch.autograd.grad(z[:, k].sum(), x, retain_graph=True)[0] for k in range(z.shape[1])]  # constants
    return (torch.stack(rows, dim=1) ** 2).sum(dim=(1, 2)).mean()
""",
    ),
    "penalty_of_the_weights": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    return cae.encoder_weight_penalty()  # the paper's printed form: right for a linear encoder only
""",
    ),
    "penalty_summed_over_grids": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    x = grids.reshape(len(grids), -1).detach().requires_grad_(True)
    z = cae.encode(x)
    rows = [torch.autograd.grad(z[:, k].sum(), x, create_graph=True)[0] for k in range(z.shape[1])]
    return (torch.stack(rows, dim=1) ** 2).sum()  # a sum over the grids, not their mean
""",
    ),
    # cae_loss, Q2: the loss
    "loss_without_the_penalty": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean()
""",
    ),
    "loss_sign_error": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() - lam * contractive_penalty(cae, grids)
""",
    ),
    "loss_ignores_lambda": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() + contractive_penalty(cae, grids)
""",
    ),
    "loss_summed_over_cells": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    squared = (cae(grids) - grids) ** 2
    return squared.reshape(len(grids), -1).sum(dim=1).mean() + lam * contractive_penalty(cae, grids)
""",
    ),
    "loss_penalty_detached": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() + lam * contractive_penalty(cae, grids).detach()
""",
    ),
}
