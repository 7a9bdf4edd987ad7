"""Answers to the course assignments, each one a test of its grader (tests/test_assignments.py).

A variant is the code a student might write for one function of an assignment; it replaces the
solution cell that defines the same function in the master's solved notebook. A **wrong** variant
breaks one sentence of the function's specification (``breaks``: "q1 sentence 4", as the notebook
numbers it, or "library" for a call to the toolkit's own answer); graded like a submission, it must
score below full marks on every question in ``loses`` and full marks on the others. Every sentence
of every specification has at least one wrong variant. A **correct** variant (``loses`` empty) is
the function written differently from the master, and must score full marks. To plant another
answer, add one entry to :data:`VARIANTS`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass


@dataclass(frozen=True)
class Variant:
    assignment: str
    loses: frozenset[str]  # the questions it must lose points on; every other question scores full marks
    code: str  # one function definition, replacing the solution cell that defines the same name
    breaks: str  # the specification's sentence it breaks ("q1 sentence 4", "library"); "" for a correct variant

    @property
    def function(self) -> str:
        """The name of the function the variant defines."""
        found = re.search(r"^def (\w+)\(", self.code, re.MULTILINE)
        assert found, f"a variant defines a function: {self.code[:80]!r}"
        return found[1]


def _variant(assignment: str, loses: str, code: str, breaks: str) -> Variant:
    return Variant(assignment, frozenset(loses.split()), code.strip() + "\n", breaks)


def _correct(assignment: str, code: str) -> Variant:
    return Variant(assignment, frozenset(), code.strip() + "\n", "")


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
        "q1 sentence 3",
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
        "q1 sentence 5",
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
        "q1 sentence 5",
    ),
    "bridge_returns_nothing": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    empty = np.zeros((0, checker.robot.dof))
    return empty, empty, empty
""",
        "q1 sentence 6",
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
        "q1 sentence 6",
    ),
    "bridge_calls_the_library": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    middles = sampling.BridgeTestSampler(checker, sigma).sample(n_attempts, rng)
    return middles, middles - sigma / 2, middles + sigma / 2  # made-up ends
""",
        "library",
    ),
    # bridge_test, Q2: the share in the passage
    "passage_half_hard_coded": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    return 0.5
""",
        "q2 sentence 1",
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
        "q2 sentence 1",
    ),
    "passage_empty_is_nan": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    return float(np.all((Q >= passage[0]) & (Q <= passage[1]), axis=1).mean())
""",
        "q2 sentence 3",
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
        "q1 sentence 4",
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
        "q1 sentence 3",
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
        "q1 sentence 2",
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
        "q1 sentence 3",
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
        "q1 sentence 3",
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
        "q1 sentence 3",
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
        "library",
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
        "q1 sentence 1",
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
        "q1 sentence 4",
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
        "q2 sentence 2",
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
        "q2 sentence 2",
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
        "q2 sentence 2",
    ),
    "threshold_the_largest": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    return max(runs)
""",
        "q2 sentence 2",
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
        "q2 sentence 1",
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
        "q2 sentence 3",
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
        "q1 sentence 3",
    ),
    "penalty_of_the_weights": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    return cae.encoder_weight_penalty()  # the paper's printed form: right for a linear encoder only
""",
        "library",
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
        "q1 sentence 2",
    ),
    # cae_loss, Q2: the loss
    "loss_without_the_penalty": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean()
""",
        "q2 sentence 2",
    ),
    "loss_sign_error": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() - lam * contractive_penalty(cae, grids)
""",
        "q2 sentence 2",
    ),
    "loss_ignores_lambda": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() + contractive_penalty(cae, grids)
""",
        "q2 sentence 2",
    ),
    "loss_summed_over_cells": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    squared = (cae(grids) - grids) ** 2
    return squared.reshape(len(grids), -1).sum(dim=1).mean() + lam * contractive_penalty(cae, grids)
""",
        "q2 sentence 1",
    ),
    "loss_penalty_detached": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() + lam * contractive_penalty(cae, grids).detach()
""",
        "q2 sentence 3",
    ),
}

VARIANTS |= {  # bridge_test, written after the specification: one or more a sentence, and correct ones
    "bridge_asks_the_notebooks_checker": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    blocked = np.flatnonzero(~free(exact, Q1))  # the notebook's checker, not the one given
    blocked = blocked[~free(exact, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(exact, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 1",
    ),
    "bridge_draws_from_np_random": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = np.random.normal(Q1, sigma)  # the global generator
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 2",
    ),
    "bridge_seeds_its_own_generator": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    rng = np.random.default_rng(0)  # the rng given is ignored
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 2",
    ),
    "bridge_uniform_partner": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + rng.uniform(-sigma, sigma, Q1.shape)  # a box of side 2 sigma, not a normal distribution
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 3",
    ),
    "bridge_clips_the_partner": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    robot = checker.robot
    Q1 = robot.sample(rng, n_attempts)
    Q2 = np.clip(rng.normal(Q1, sigma), robot.lower, robot.upper)  # into the bounds: they no longer act as walls
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 4",
    ),
    "bridge_outside_counts_as_free": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    robot = checker.robot
    Q1 = robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    blocked = np.flatnonzero(~free(checker, Q1))
    inside = robot.in_bounds(Q2[blocked])
    blocked = blocked[inside][~free(checker, Q2[blocked][inside])]  # a partner outside the bounds is dropped
    middles = segment_points(robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 4",
    ),
    "bridge_checks_every_partner": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    both = ~free(checker, Q1) & ~free(checker, Q2)  # every q2 checked, also where q1 is free
    middles = segment_points(checker.robot, Q1[both], Q2[both], np.full(int(both.sum()), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[both][keep], Q2[both][keep]
""",
        "q1 sentence 7",
    ),
    "bridge_checks_in_many_batches": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    chunks = np.array_split(np.arange(n_attempts), 4)  # four calls for the first ends alone
    blocked = np.concatenate([c[~free(checker, Q1[c])] for c in chunks]).astype(int)
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 7",
    ),
    "bridge_nothing_is_flat": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    if not keep.any():
        return np.array([]), np.array([]), np.array([])  # shape (0,), not (0, dof)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 8",
    ),
    "passage_of_the_notebooks_gap": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    Q = np.asarray(Q, float).reshape(-1, 2)
    inside = ((Q >= PASSAGE[0]) & (Q <= PASSAGE[1])).all(axis=1)  # the notebook's box, not the one given
    return float(inside.mean()) if len(Q) else 0.0
""",
        "q2 sentence 2",
    ),
    "passage_returns_an_array": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    Q = np.asarray(Q, float).reshape(-1, 2)
    return ((Q >= passage[0]) & (Q <= passage[1])).all(axis=1).mean(keepdims=True) if len(Q) else 0.0  # (1,)
""",
        "q2 sentence 3",
    ),
    "bridge_one_mask_per_round": _correct(
        "bridge_test",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    robot = checker.robot
    q1 = rng.uniform(robot.lower, robot.upper, size=(n_attempts, robot.dof))
    q2 = q1 + rng.normal(0.0, sigma, size=q1.shape)
    first = ~free(checker, q1)
    second = np.zeros(n_attempts, dtype=bool)
    second[first] = ~free(checker, q2[first])
    middle = (q1 + q2) / 2
    keep = np.zeros(n_attempts, dtype=bool)
    keep[second] = free(checker, middle[second])
    return middle[keep], q1[keep], q2[keep]
""",
    ),
    "bridge_a_loop_over_the_ends": _correct(
        "bridge_test",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    ends_a = checker.robot.sample(rng, n_attempts)
    ends_b = ends_a + sigma * rng.standard_normal(ends_a.shape)
    alive = np.arange(n_attempts)
    for ends in (ends_a, ends_b):  # an attempt survives while its ends collide
        alive = alive[~free(checker, ends[alive])]
    middles = 0.5 * (ends_a[alive] + ends_b[alive])
    holds = free(checker, middles)
    return middles[holds], ends_a[alive[holds]], ends_b[alive[holds]]
""",
    ),
    "passage_a_python_loop": _correct(
        "bridge_test",
        """
def passage_fraction(Q, passage):
    lower, upper = (list(map(float, corner)) for corner in passage)
    rows = [list(map(float, q)) for q in Q]
    inside = [all(lo <= x <= hi for x, lo, hi in zip(q, lower, upper)) for q in rows]
    return sum(inside) / len(rows) if rows else 0.0
""",
    ),
    "passage_count_nonzero": _correct(
        "bridge_test",
        """
def passage_fraction(Q, passage):
    Q = np.atleast_2d(np.asarray(Q, dtype=float))
    n = Q.shape[0] if Q.size else 0
    lower, upper = np.asarray(passage[0]), np.asarray(passage[1])
    return np.count_nonzero(np.logical_and(Q >= lower, Q <= upper).all(axis=1)) / n if n else 0.0
""",
    ),
}

VARIANTS |= {  # verify_and_repair, written after the specification
    "repair_at_the_notebooks_resolution": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while (path := roadmap.shortest_path(start, goal)) is not None:
        node_ok = exact.are_valid(roadmap.nodes[path])
        if not node_ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~node_ok]).any(axis=1))
            continue
        step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], RESOLUTION)  # not the argument
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~step_ok])
    return None
""",
        "q1 sentence 1",
    ),
    "repair_asks_the_notebooks_checker": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    checker = globals()["exact"]  # the notebook's exact checker, not the argument
    while (path := roadmap.shortest_path(start, goal)) is not None:
        node_ok = checker.are_valid(roadmap.nodes[path])
        if not node_ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~node_ok]).any(axis=1))
            continue
        step_ok = check_edges(checker, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~step_ok])
    return None
""",
        "q1 sentence 1",
    ),
    "repair_removes_the_whole_path": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while (path := roadmap.shortest_path(start, goal)) is not None:
        node_ok = exact.are_valid(roadmap.nodes[path])
        if not node_ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~node_ok]).any(axis=1))
            continue
        step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path))  # the good edges too
    return None
""",
        "q1 sentence 3",
    ),
    "repair_gives_up_after_one_round": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    path = roadmap.shortest_path(start, goal)
    if path is None:
        return None
    node_ok = exact.are_valid(roadmap.nodes[path])
    step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
    return path if node_ok.all() and step_ok.all() else None  # no second candidate
""",
        "q1 sentence 4",
    ),
    "repair_removes_nodes": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while (path := roadmap.shortest_path(start, goal)) is not None:
        node_ok = exact.are_valid(roadmap.nodes[path])
        if not node_ok.all():
            roadmap.remove_nodes(path[~node_ok])  # shifts the indices of later nodes
            continue
        step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~step_ok])
    return None
""",
        "q1 sentence 5",
    ),
    "repair_checks_the_whole_roadmap": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    node_ok = exact.are_valid(roadmap.nodes)  # every node and edge, not the candidate paths
    roadmap.remove_edges(~node_ok[roadmap.edges].all(axis=1))
    edge_ok = check_edges(exact, roadmap.nodes[roadmap.edges[:, 0]], roadmap.nodes[roadmap.edges[:, 1]], resolution)
    roadmap.remove_edges(~edge_ok)
    return roadmap.shortest_path(start, goal)
""",
        "q1 sentence 6",
    ),
    "repair_trusts_start_and_goal": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    while (path := roadmap.shortest_path(start, goal)) is not None:
        inner = path[1:-1]  # start and goal taken as valid
        node_ok = exact.are_valid(roadmap.nodes[inner])
        if not node_ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, inner[~node_ok]).any(axis=1))
            continue
        step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~step_ok])
    return None
""",
        "q1 sentence 7",
    ),
    "repair_by_recursion": _correct(
        "verify_and_repair",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    path = roadmap.shortest_path(start, goal)
    if path is None:
        return None
    bad = path[~exact.are_valid(roadmap.nodes[path])]
    if len(bad):
        roadmap.remove_edges((roadmap.edges[:, :, None] == bad).any(axis=(1, 2)))
        return verify_and_repair(roadmap, exact, start, goal, resolution)
    ok = check_edges(exact, roadmap.nodes[path][:-1], roadmap.nodes[path][1:], resolution)
    if not ok.all():
        roadmap.remove_edges(roadmap.edge_index(path)[~ok])
        return verify_and_repair(roadmap, exact, start, goal, resolution)
    return path
""",
    ),
    "repair_with_python_sets": _correct(
        "verify_and_repair",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    for _ in range(len(roadmap.edges) + 1):  # each round removes at least one edge
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        nodes = roadmap.nodes[path]
        node_ok = exact.are_valid(nodes)
        if not node_ok.all():
            bad = set(path[~node_ok].tolist())
            roadmap.remove_edges(np.array([a in bad or b in bad for a, b in roadmap.edges.tolist()], dtype=bool))
            continue
        step_ok = check_edges(exact, nodes[:-1], nodes[1:], resolution)
        if step_ok.all():
            return path
        failed = set(roadmap.edge_index(path)[~step_ok].tolist())
        roadmap.remove_edges(np.array([i in failed for i in range(len(roadmap.edges))], dtype=bool))
    return None
""",
    ),
}

VARIANTS |= {  # evaluating_a_checker, written after the specification
    "rates_over_the_wrong_axis": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    with np.errstate(invalid="ignore"):
        return {  # one rate per configuration, over the workspaces
            "acc": (p == v).mean(axis=0),
            "tpr": (p & v).sum(axis=0) / v.sum(axis=0),
            "tnr": (~p & ~v).sum(axis=0) / (~v).sum(axis=0),
        }
""",
        "q1 sentence 1",
    ),
    "rates_accuracy_is_the_share_predicted_valid": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    with np.errstate(invalid="ignore"):
        return {
            "acc": p.mean(axis=1),  # not the share of right answers
            "tpr": (p & v).sum(axis=1) / np.where(v.any(axis=1), v.sum(axis=1), np.nan),
            "tnr": (~p & ~v).sum(axis=1) / np.where((~v).any(axis=1), (~v).sum(axis=1), np.nan),
        }
""",
        "q1 sentence 2",
    ),
    "rates_tpr_is_precision": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    with np.errstate(invalid="ignore", divide="ignore"):
        return {
            "acc": (p == v).mean(axis=1),
            "tpr": np.where(v.any(axis=1), (p & v).sum(axis=1) / p.sum(axis=1), np.nan),  # over the predicted valid
            "tnr": np.where((~v).any(axis=1), (~p & ~v).sum(axis=1) / (~p).sum(axis=1), np.nan),
        }
""",
        "q1 sentence 3",
    ),
    "rates_absent_class_is_one": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    with np.errstate(invalid="ignore"):
        tpr, tnr = (p & v).sum(axis=1) / v.sum(axis=1), (~p & ~v).sum(axis=1) / (~v).sum(axis=1)
    return {"acc": (p == v).mean(axis=1), "tpr": np.nan_to_num(tpr, nan=1.0), "tnr": np.nan_to_num(tnr, nan=1.0)}
""",
        "q1 sentence 4",
    ),
    "rates_from_the_confusion_counts": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    from toolkit.plots.answers import confusion_counts

    out = {"acc": [], "tpr": [], "tnr": []}
    for p, v in zip(predicted_valid, valid):
        kept, missed, rejected, wrong = confusion_counts(p, v).values()
        out["acc"].append((kept + rejected) / len(v))
        out["tpr"].append(kept / (kept + missed) if v.any() else np.nan)
        out["tnr"].append(rejected / (rejected + wrong) if (~v).any() else np.nan)
    return {k: np.array(x) for k, x in out.items()}
""",
        "library",
    ),
    "threshold_any_query_valid": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.median([r["total_s"] for r in records]) for t, records in runs.items()
          if any(r["success"] and r["path_valid"] for r in records)}  # one valid query is not every query
    return min(sorted(ok), key=ok.get) if ok else None
""",
        "q2 sentence 1",
    ),
    "threshold_forgets_zero": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    best, best_s = None, None
    for t in sorted(runs):
        if all(r["success"] and r["path_valid"] for r in runs[t]):
            median_s = np.median([r["total_s"] for r in runs[t]])
            if not best or median_s < best_s:  # a best threshold of 0.0 is forgotten
                best, best_s = t, median_s
    return best
""",
        "q2 sentence 3",
    ),
    "threshold_first_listed_wins_a_tie": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.median([r["total_s"] for r in records]) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(ok, key=ok.get) if ok else None  # in the order given: a tie goes to the first listed
""",
        "q2 sentence 3",
    ),
    "threshold_fails_on_nothing": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    ok = {t: np.median([r["total_s"] for r in records]) for t, records in runs.items()
          if all(r["success"] and r["path_valid"] for r in records)}
    return min(sorted(ok), key=ok.get)  # raises when nothing qualifies
""",
        "q2 sentence 4",
    ),
    "rates_a_loop_over_workspaces": _correct(
        "evaluating_a_checker",
        """
def rates(predicted_valid, valid):
    out = {"acc": [], "tpr": [], "tnr": []}
    for p, v in zip(np.asarray(predicted_valid, bool), np.asarray(valid, bool)):
        out["acc"].append(np.mean(p == v))
        out["tpr"].append(p[v].mean() if v.any() else np.nan)
        out["tnr"].append((~p[~v]).mean() if (~v).any() else np.nan)
    return {key: np.array(values, dtype=float) for key, values in out.items()}
""",
    ),
    "rates_divide_where": _correct(
        "evaluating_a_checker",
        """
def rates(predicted_valid, valid):
    p, v = np.asarray(predicted_valid, bool), np.asarray(valid, bool)
    def share(hits, of):
        n = of.sum(axis=1)
        return np.divide((hits & of).sum(axis=1), n, out=np.full(len(n), np.nan), where=n > 0)
    return {"acc": share(p == v, np.ones_like(v)), "tpr": share(p, v), "tnr": share(~p, ~v)}
""",
    ),
    "threshold_statistics_median": _correct(
        "evaluating_a_checker",
        """
def fastest_valid_threshold(runs):
    import statistics

    best = None
    for t in sorted(runs):
        records = runs[t]
        if records and not all(r["success"] and r["path_valid"] for r in records):
            continue
        median_s = statistics.median(r["total_s"] for r in records)
        if best is None or median_s < best[1]:
            best = (t, median_s)
    return None if best is None else best[0]
""",
    ),
    "threshold_sort_by_pairs": _correct(
        "evaluating_a_checker",
        """
def fastest_valid_threshold(runs):
    candidates = sorted(
        (float(np.median([r["total_s"] for r in records])), t)
        for t, records in runs.items()
        if all(r["success"] and r["path_valid"] for r in records)
    )
    return candidates[0][1] if candidates else None
""",
    ),
}

VARIANTS |= {  # cae_loss, written after the specification
    "penalty_mean_over_entries": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    x = grids.reshape(len(grids), -1).detach().requires_grad_(True)
    z = cae.encode(x)
    rows = [torch.autograd.grad(z[:, k].sum(), x, create_graph=True)[0] for k in range(z.shape[1])]
    return (torch.stack(rows, dim=1) ** 2).mean()  # a mean over the Jacobian's entries, not their sum
""",
        "q1 sentence 1",
    ),
    "penalty_one_backward_pass": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    x = grids.reshape(len(grids), -1).detach().requires_grad_(True)
    (summed,) = torch.autograd.grad(cae.encode(x).sum(), x, create_graph=True)  # the rows summed before squaring
    return (summed**2).sum(dim=1).mean()
""",
        "q1 sentence 4",
    ),
    "penalty_detached": _variant(
        "cae_loss",
        "q1",
        """
def contractive_penalty(cae, grids):
    x = grids.reshape(len(grids), -1).detach().requires_grad_(True)
    z = cae.encode(x)
    rows = [torch.autograd.grad(z[:, k].sum(), x, create_graph=True)[0] for k in range(z.shape[1])]
    return (torch.stack(rows, dim=1) ** 2).sum(dim=(1, 2)).mean().detach()
""",
        "q1 sentence 3",
    ),
    "loss_absolute_error": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return (cae(grids) - grids).abs().mean() + lam * contractive_penalty(cae, grids)
""",
        "q2 sentence 1",
    ),
    "loss_lambda_squared": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids) - grids) ** 2).mean() + lam**2 * contractive_penalty(cae, grids)
""",
        "q2 sentence 2",
    ),
    "loss_reconstruction_detached": _variant(
        "cae_loss",
        "q2",
        """
def cae_loss(cae, grids, lam):
    return ((cae(grids).detach() - grids) ** 2).mean() + lam * contractive_penalty(cae, grids)
""",
        "q2 sentence 3",
    ),
    "penalty_by_jacrev": _correct(
        "cae_loss",
        """
def contractive_penalty(cae, grids):
    from torch.func import jacrev

    flat = grids.reshape(len(grids), -1)  # (W, n)
    jacobians = torch.stack([jacrev(cae.encoder)(x[None])[0, :, 0] for x in flat])  # (W, m, n)
    return jacobians.pow(2).sum(dim=(1, 2)).mean()
""",
    ),
    "penalty_grid_by_grid": _correct(
        "cae_loss",
        """
def contractive_penalty(cae, grids):
    norms = []
    for grid in grids:
        J = torch.autograd.functional.jacobian(lambda x: cae.encode(x.unsqueeze(0)).squeeze(0), grid, create_graph=True)
        norms.append((J * J).sum())
    return sum(norms) / len(norms)
""",
    ),
    "loss_with_mse_loss": _correct(
        "cae_loss",
        """
def cae_loss(cae, grids, lam):
    return torch.nn.functional.mse_loss(cae(grids), grids, reduction="mean") + lam * contractive_penalty(cae, grids)
""",
    ),
    "loss_sum_over_numel": _correct(
        "cae_loss",
        """
def cae_loss(cae, grids, lam):
    error = (grids - cae(grids)).square().sum() / grids.numel()
    return error + contractive_penalty(cae, grids) * lam
""",
    ),
}

VARIANTS |= {  # round 3: the families fresh submissions found unheld (any robot, inputs kept, rng only, limits, ties)
    "bridge_noise_in_two_columns": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + sigma * rng.standard_normal((n_attempts, 2))  # two coordinates: the point robot's
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 9",
    ),
    "bridge_ends_swapped": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = rng.normal(Q1, sigma)
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q2[blocked][keep], Q1[blocked][keep]  # q2 first
""",
        "q1 sentence 10",
    ),
    "bridge_ends_b_from_numpy_random": _variant(
        "bridge_test",
        "q1",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    Q1 = checker.robot.sample(rng, n_attempts)
    Q2 = Q1 + np.random.normal(0.0, sigma, Q1.shape)  # the global generator, not rng
    blocked = np.flatnonzero(~free(checker, Q1))
    blocked = blocked[~free(checker, Q2[blocked])]
    middles = segment_points(checker.robot, Q1[blocked], Q2[blocked], np.full(len(blocked), 0.5))
    keep = free(checker, middles)
    return middles[keep], Q1[blocked][keep], Q2[blocked][keep]
""",
        "q1 sentence 2",
    ),
    "bridge_any_dof_from_the_bounds": _correct(
        "bridge_test",
        """
def bridge_test(checker, n_attempts, sigma, rng):
    robot = checker.robot
    empty = np.empty((0, robot.dof))
    if n_attempts == 0:
        return empty, empty, empty
    first = rng.uniform(robot.lower, robot.upper, size=(n_attempts, robot.dof))
    second = first + rng.normal(size=first.shape) * sigma
    hit = ~free(checker, first)
    hit[hit] = ~free(checker, second[hit])
    a, b = first[hit], second[hit]
    middle = segment_points(robot, a, b, np.full(len(a), 0.5))
    ok = free(checker, middle)
    return middle[ok], a[ok], b[ok]
""",
    ),
    "passage_shifts_the_callers_array": _variant(
        "bridge_test",
        "q2",
        """
def passage_fraction(Q, passage):
    Q = np.asarray(Q, dtype=float).reshape(-1, 2)
    Q -= passage[0]  # in place: the caller's array moves
    inside = ((Q >= 0) & (Q <= passage[1] - passage[0])).all(axis=1)
    return float(inside.mean()) if len(Q) else 0.0
""",
        "q2 sentence 4",
    ),
    "passage_shifts_a_copy": _correct(
        "bridge_test",
        """
def passage_fraction(Q, passage):
    offsets = np.array(Q, dtype=float).reshape(-1, 2)  # a copy
    offsets -= passage[0]
    inside = ((offsets >= 0) & (offsets <= np.subtract(passage[1], passage[0]))).all(axis=1)
    return float(np.mean(inside)) if len(offsets) else 0.0
""",
    ),
    "repair_gives_up_after_50_rounds": _variant(
        "verify_and_repair",
        "q1",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    for _ in range(50):  # surely enough
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        node_ok = exact.are_valid(roadmap.nodes[path])
        if not node_ok.all():
            roadmap.remove_edges(np.isin(roadmap.edges, path[~node_ok]).any(axis=1))
            continue
        step_ok = check_edges(exact, roadmap.nodes[path[:-1]], roadmap.nodes[path[1:]], resolution)
        if step_ok.all():
            return path
        roadmap.remove_edges(roadmap.edge_index(path)[~step_ok])
    return None
""",
        "q1 sentence 8",
    ),
    "repair_with_sets_and_a_flag": _correct(
        "verify_and_repair",
        """
def verify_and_repair(roadmap, exact, start, goal, resolution):
    done = False
    path = None
    while not done:
        path = roadmap.shortest_path(start, goal)
        if path is None:
            return None
        path = np.asarray(path)
        bad_nodes = set(path[~exact.are_valid(roadmap.nodes[path])].tolist())
        if bad_nodes:
            touching = [a in bad_nodes or b in bad_nodes for a, b in roadmap.edges.tolist()]
            roadmap.remove_edges(np.array(touching, dtype=bool))
            continue
        ok = check_edges(exact, roadmap.nodes[path][:-1], roadmap.nodes[path][1:], resolution)
        if ok.all():
            done = True
        else:
            roadmap.remove_edges(roadmap.edge_index(path)[np.flatnonzero(~ok)])
    return path
""",
    ),
    "rates_flips_the_callers_predictions": _variant(
        "evaluating_a_checker",
        "q1",
        """
def rates(predicted_valid, valid):
    hits = np.asarray(predicted_valid, bool)
    valid = np.asarray(valid, bool)
    hits ^= ~valid  # in place: the caller's predictions become the hits
    n_valid = np.where(valid.any(axis=1), valid.sum(axis=1), np.nan)
    n_invalid = np.where((~valid).any(axis=1), (~valid).sum(axis=1), np.nan)
    tpr, tnr = (hits & valid).sum(axis=1) / n_valid, (hits & ~valid).sum(axis=1) / n_invalid
    return {"acc": hits.mean(axis=1), "tpr": tpr, "tnr": tnr}
""",
        "q1 sentence 5",
    ),
    "rates_loops_over_workspaces": _correct(
        "evaluating_a_checker",
        """
def rates(predicted_valid, valid):
    out = {"acc": [], "tpr": [], "tnr": []}
    for guess, truth in zip(np.asarray(predicted_valid, bool).tolist(), np.asarray(valid, bool).tolist()):
        right = [g == t for g, t in zip(guess, truth)]
        positives = [r for r, t in zip(right, truth) if t]
        negatives = [r for r, t in zip(right, truth) if not t]
        out["acc"].append(sum(right) / len(right))
        out["tpr"].append(sum(positives) / len(positives) if positives else float("nan"))
        out["tnr"].append(sum(negatives) / len(negatives) if negatives else float("nan"))
    return {key: np.array(values, dtype=float) for key, values in out.items()}
""",
    ),
    "threshold_rounds_the_medians": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    qualified = sorted(t for t, records in runs.items() if all(r["success"] and r["path_valid"] for r in records))
    if not qualified:
        return None
    return min(qualified, key=lambda t: round(float(np.median([r["total_s"] for r in runs[t]])), 3))  # to the ms
""",
        "q2 sentence 3",
    ),
    "threshold_sorts_the_records_in_place": _variant(
        "evaluating_a_checker",
        "q2",
        """
def fastest_valid_threshold(runs):
    best = None
    for t in sorted(runs):
        records = runs[t]
        if not all(r["success"] and r["path_valid"] for r in records):
            continue
        records.sort(key=lambda r: r["total_s"])  # in place: the caller's records are reordered
        n = len(records)
        median = (records[(n - 1) // 2]["total_s"] + records[n // 2]["total_s"]) / 2
        if best is None or median < best[0]:
            best = (median, t)
    return None if best is None else best[1]
""",
        "q2 sentence 5",
    ),
    "threshold_min_over_pairs": _correct(
        "evaluating_a_checker",
        """
def fastest_valid_threshold(runs):
    import statistics

    candidates = [
        (statistics.median(r["total_s"] for r in records), threshold)
        for threshold, records in runs.items()
        if all(r["success"] for r in records) and all(r["path_valid"] for r in records)
    ]
    return min(candidates)[1] if candidates else None
""",
    ),
}
