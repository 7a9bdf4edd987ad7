"""What chapter 05 (3D scenes) prints about its own runs: §1's valid shares, §2's office collisions, §5's truth vs
prediction, §6's counts of a planned query and §7's view of the lazy PRM's edge screening, each a Markdown table
built from the arrays a cell has just computed (the record's tables are :mod:`toolkit.teaching.chapter05`'s).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from toolkit.plots.dof_panels import wrap_frames
from toolkit.teaching import chapter05, recorded
from toolkit.teaching.chapter05 import SCENARIO
from toolkit.teaching.chapter05_accuracy import percent


def plan_tables(result) -> str:
    """§6's counts of a planned query (a ``PlanResult``): the path and the roadmap, then who answered how often (reader
    r44e, item 5: the ratio's column says what it counts, no "x" mark beside a number)."""
    stats = result.stats
    exactly = stats["exact_checks"] + stats["exact_clearances"]  # point checks and clearance bounds
    return (
        "| path found | configurations on the path | rounds | samples drawn | roadmap: nodes / edges |\n"
        "| --- | ---: | ---: | ---: | ---: |\n"
        f"| {'yes' if result.success else 'no'} | {len(result.path)} | {stats['rounds']} | {stats['node_checks']} "
        f"| {stats['nodes']} / {stats['edges']} |\n\n"
        "| model's answers | exact: checks + bounds | model answers per exact call | repairs "
        "| removed: nodes / edges |\n"
        "| ---: | ---: | ---: | ---: | ---: |\n"
        f"| {stats['predicted_checks']} | {stats['exact_checks']} + {stats['exact_clearances']} "
        f"| {stats['predicted_checks'] / max(exactly, 1):.0f} | {stats['repairs']} "
        f"| {stats['removed_nodes']} / {stats['removed_edges']} |\n\n" + _removed(stats) + " " + answers_cost(stats)
    )


def answers_cost(stats) -> str:
    """§6's counts tied to the chapter's question (reader r58e, 05 lift 2): the model's answers priced in compiled
    exact checks at the timed run's measured cost per answer (``docs/results.md``): cost, not accuracy."""
    rates = recorded.table(chapter05.COMPILED, "Checker throughput")[SCENARIO]  # docs/results.md, the timed run's
    cost = recorded.ours(rates["exact cfg/s"]) / recorded.ours(rates["learned cfg/s"])  # checks in one answer's time
    answers, exact = stats["predicted_checks"], stats["exact_checks"] + stats["exact_clearances"]
    return (
        f"What this costs: the model answered {answers} times, the exact checker {exact} times. One network answer "
        f"takes as long as {cost:.1f} compiled exact checks (the timed run's rates), so the {answers} answers took as "
        f"long as about {round(answers * cost, -2):.0f} compiled checks; checking the same configurations exactly "
        f"would have cost {answers} checks. That is the answer's \"cost, not accuracy\", in this query's own counts."
    )


def _removed(stats) -> str:
    """What §6's removed nodes and edges were (reader r49e, 05 item 2: beside §7's "no edge" line): places on a
    candidate path that the model had let in and the exact check found colliding, dangerous mistakes caught."""
    nodes, edges = stats["removed_nodes"], stats["removed_edges"]
    if not nodes + edges:
        return "No candidate path failed the exact check, so nothing was removed."
    counted = " and ".join(f"{n} {kind}{'' if n == 1 else 's'}" for n, kind in ((nodes, "node"), (edges, "edge")) if n)
    one = nodes + edges == 1
    hit = "a collision" if one else "collisions"
    return (
        f"The {counted} removed lay on {'a candidate path' if one else 'candidate paths'}: the model had let "
        f"{'it' if one else 'them'} into the roadmap, and the exact check found {hit} "
        f"there. {'That is a' if one else 'Each is a'} dangerous mistake caught before the path was returned. A "
        "conservative mistake removes nothing: it only keeps a node or an edge out."
    )


ROBOTS = {"3do": "youBot-like", "3dc7": "box chain", "3dc9": "box chain"}  # §1's robots, in two words


def valid_shares(samples: int, seed: int) -> str:
    """§1's table: in each 3D scenario's workspace of ``seed``, the share of ``samples`` uniform configurations
    (drawn from ``seed`` too) that the exact checker finds valid, with the robot's links and DoFs and the blocks."""
    from toolkit import scenarios
    from toolkit.geometry.collision import exact_checker

    rows = []
    for name, robot_words in ROBOTS.items():
        scenario = scenarios.get(name)
        workspace = scenario.make_workspace(np.random.default_rng(seed))
        Q = scenario.robot.sample(np.random.default_rng(seed), samples)  # (N, dof) uniform
        share = exact_checker(workspace, scenario.robot).are_valid(Q).mean()
        robot = scenario.robot
        rows.append(
            f"| {name} | {robot_words} | {robot.n_links} / {robot.dof} | {len(workspace.boxes)} | {share:.1%} |"
        )
    return (
        f"The share of {samples} uniform samples that is valid, in the workspace of seed {seed}:\n\n"
        "| scenario | robot | links / DoF | blocks | valid share |\n"
        "| --- | --- | ---: | ---: | ---: |\n" + "\n".join(rows)
    )


def office_collisions(samples: np.ndarray, seed: int) -> str:
    """§2's table: of the 3DO configurations ``samples (N, 8)`` in the office of ``seed``, how many collide, and of
    those how many poke out of the office (an office without furniture finds them too) and how many are in collision
    with furniture only, inside the office (reader r28e's header)."""
    from toolkit import scenarios
    from toolkit.geometry.collision import exact_checker
    from toolkit.geometry.workspace import Workspace

    office = scenarios.get("3do")
    workspace = office.make_workspace(np.random.default_rng(seed))  # the workspace the view draws
    colliding = ~exact_checker(workspace, office.robot).are_valid(samples)  # (N,)
    empty = Workspace(workspace.lower, workspace.upper, np.zeros((0, 2, 3)), family="3do")  # no furniture
    outside = ~exact_checker(empty, office.robot).are_valid(samples)  # (N,) out of the office
    return (
        "| uniform samples | in collision | of those: poking out of the office "
        "| in collision with furniture only (inside the office) |\n"
        "| ---: | ---: | ---: | ---: |\n"
        f"| {len(samples)} | {colliding.sum()} | {(colliding & outside).sum()} | {(colliding & ~outside).sum()} |"
    )


def wrap_starts(robot, Q: np.ndarray) -> str:
    """§7's frame picture: each angle that wraps round ±π right after the first frame (reader r58e, 05 lift 3: the
    alt said "beta 0.00", the line seemed to start at 1.0): its first point sits alone on one edge of its panel."""
    scaled = (Q - robot.lower) / (robot.upper - robot.lower)  # (T, dof) in [0, 1]
    said = [
        f"{name} starts at {scaled[0, k]:.2f} and wraps round ±π at once, so its line seems to start at "
        f"{scaled[1, k]:.2f}, its first point alone on the other edge"
        for k, name in enumerate(robot.dof_names)
        if len(scaled) > 1 and 0 in wrap_frames(scaled[:, k])
    ]
    return ("In the picture, " + "; ".join(said) + ".") if said else ""


def closest_above(probability: np.ndarray, threshold: float, tightest: int | None = None) -> str:
    """§7's line on the P(valid) panel's near misses (reader r29e: a dip to the dashed line read as a second frame
    below it): the lowest P(valid) of ``probability (F,)`` among the frames at or above ``threshold``, and where;
    given the frame of the least clearance bound, ``tightest``, how far from it (reader r31e: the dip sat just left
    of the slider's line, and the page never said so)."""
    above = np.flatnonzero(probability >= threshold)  # frames the model calls valid: no band
    if not len(above):
        return "Every frame lies below the threshold."
    frame = int(above[np.argmin(probability[above])])
    apart = "" if tightest is None else _frames_from(frame, tightest)
    return (
        f"The frame that comes nearest the threshold from above: frame {frame}, P(valid) {probability[frame]:.3f} "
        f"against {threshold:.3f}: called valid, so no band marks it.{apart}"
    )


def _frames_from(frame: int, tightest: int) -> str:
    """Where ``frame`` lies from the frame of the least clearance bound, the slider's first, as a sentence."""
    if frame == tightest:
        return " It is the frame of the least clearance bound, where the slider starts."
    n = abs(frame - tightest)
    side = "before" if frame < tightest else "after"
    return (
        f" It lies {n} frame{'s' * (n != 1)} {side} the least clearance bound (frame {tightest}, where the slider "
        "starts)."
    )


def _screened(result, model) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
    """How the lazy PRM's learned edge screening saw the edges of ``result``'s path (a ``PlanResult``): per edge, the
    points it asked ``model`` about, how many the model called colliding and their share; and the share above which
    screening drops an edge (``LazyParams.screen_reject``)."""
    from toolkit import scenarios
    from toolkit.experiments.problems import make_planner, scenario_resolution
    from toolkit.planning.local_planner import invalid_fractions, step_counts

    scenario = scenarios.get(SCENARIO)
    params = make_planner(scenario).params  # the planner clutter.plan ran: the default, with the scenario's |S|
    spacing = scenario_resolution(scenario) * params.screen_spacing
    Q0, Q1 = result.path[:-1], result.path[1:]  # (E, dof) each: the path's edges, roadmap edges
    fraction, _ = invalid_fractions(model, Q0, Q1, spacing)  # (E,) share of each edge's screened points
    points = np.maximum(step_counts(model.robot, Q0, Q1, spacing) - 1, 0)  # (E,) screened points per edge
    called = np.rint(fraction * points).astype(int)  # (E,) of those, called colliding by the model
    return points, called, fraction, params.screen_reject


def screening(result, model) -> str:
    """§7's reading of a kept edge (:func:`_screened`), in a table and a line (r39e)."""
    points, called, fraction, reject = _screened(result, model)
    return (
        "| path edges | points screening asked the model about | called colliding | most on one edge |\n"
        "| ---: | ---: | ---: | ---: |\n"
        f"| {len(points)} | {points.sum()} | {called.sum()} | {fraction.max(initial=0.0):.0%} |\n\n"
        f"An edge is dropped when more than {reject:.0%} of its points are called colliding."
    )


def path_mistakes(result, model, below: np.ndarray) -> str:
    """§7's plain answer to §6's question (reader r47e, 05 item 3): did the model call the valid robot colliding on
    ``result``'s path, at its frames (``below (F,)``: P(valid) under the threshold) or at the points screening asked
    it about, and could that have cost the path an edge."""
    points, called, fraction, reject = _screened(result, model)
    frames = int(np.sum(below))
    said = (
        f"{frames or 'None'} of the {len(below)} frames {'falls' if frames <= 1 else 'fall'} below the "
        f"threshold, and screening called {called.sum()} of the path's {points.sum()} screened points colliding"
    )
    if not frames and not called.sum():
        return said + ": no conservative mistake at any of them, so the model cost this path no edge."
    kept = fraction.max(initial=0.0) <= reject  # a returned path's edges always are: screening kept them
    return said + (
        f": conservative mistakes, where the robot is valid. {'They cost' if kept else 'They would cost'} "
        f"{'no' if kept else 'an'} edge of this path: screening drops an edge only where more than {reject:.0%} of "
        "its points are called colliding."
    )


def dips_unscreened(result, model, along: np.ndarray, below: np.ndarray) -> str:
    """§7's open line (reader r36e, item 2): whether the frames ``along (F, dof)`` that the model calls colliding,
    ``below (F,)``, are among the points the lazy PRM's edge screening asked it about on ``result``'s path (they lie
    a fixed step apart on each edge; the frames are evenly spaced along the whole path); empty where none is below."""
    from toolkit import scenarios
    from toolkit.experiments.problems import make_planner, scenario_resolution
    from toolkit.planning.local_planner import segment_points, step_counts

    frames = np.flatnonzero(below)
    if not len(frames):
        return ""
    scenario = scenarios.get(SCENARIO)
    spacing = scenario_resolution(scenario) * make_planner(scenario).params.screen_spacing
    Q0, Q1 = result.path[:-1], result.path[1:]  # (E, dof) each
    n = step_counts(model.robot, Q0, Q1, spacing)  # (E,) steps; n - 1 interior points each
    points = np.concatenate(
        [segment_points(model.robot, Q0[[e]], Q1[[e]], np.arange(1, k) / k) for e, k in enumerate(n) if k > 1]
        or [np.zeros((0, Q0.shape[1]))]
    )  # (P, dof)
    screened = [bool(len(points)) and bool(np.any(np.all(np.isclose(points, along[f]), axis=1))) for f in frames]
    where = ", ".join(f"{100 * f / (len(along) - 1):.0f} %" for f in frames)  # as the animation caption writes it
    many = len(frames) > 1
    if not any(screened):
        return (
            f"The frame{'s' * many} below the threshold ({where} along the path) {'are' if many else 'is'} not "
            f"{'among' if many else 'one of'} the {len(points)} points screening asked the model about, so "
            f"{'they' if many else 'it'} could not cost the path an edge."
        )
    return (
        f"{sum(screened)} of the {len(frames)} frame{'s' * many} below the threshold ({where} along the path) "
        f"{'is' if sum(screened) == 1 else 'are'} among the {len(points)} points screening asked the model about."
    )


def mistake_counts(
    valid: np.ndarray, predicted: np.ndarray, pose: tuple[bool, bool] | None = None, step: int | None = None
) -> str:
    """The line under §5's view (reader r49e, 05 item 3): the overview draws every dangerous mistake but only some
    of the conservative ones, so the true proportion, from ``valid``, ``predicted (N,)``, is said in words. ``pose``:
    the close-up robot's (exact, model) verdicts; where the model is wrong on it, the line says so first (r52e, 05
    item 3: the first close-up shows a mistake). ``step``: the overview draws 1 sample in ``step``
    (``toolkit.plots.scenes.overview_step``) and every dangerous one; given, the line says how many of each kind it
    draws (reader r54e, 05 figure: the eye read 15 stars of 17 as "mostly dangerous")."""
    dangerous, conservative = int(np.sum(~valid & predicted)), int(np.sum(valid & ~predicted))
    more = "more" if conservative > dangerous else "fewer" if conservative < dangerous else "as many"
    kind, count = ("conservative", conservative) if pose and pose[0] else ("dangerous", dangerous)
    wrong = (
        f"The robot's own pose in the close-up is a {kind} mistake, the kind {count} of the {len(valid)} samples are: "
        "a picture of one wrong answer, not of the model's accuracy. "
        if pose and pose[0] != pose[1]
        else ""
    )
    drawn = "overview draws every dangerous one but only some of the conservative ones."
    return wrong + (
        f"Count the mistakes, not the stars: of the {len(valid)} samples, {conservative} are conservative mistakes "
        f"and {dangerous} dangerous ones ({more} conservative than dangerous, {conservative} to {dangerous}). The "
        + (drawn if step is None else _drawn(valid & ~predicted, dangerous, step))
    )


def _drawn(conservative: np.ndarray, dangerous: int, step: int) -> str:
    """How many mistakes of each kind the overview draws: every dangerous one, of the ``conservative (N,)`` ones
    those among every ``step``-th sample."""
    shown, total = int(np.sum(conservative[::step])), int(np.sum(conservative))
    most = "so most of its stars are dangerous although most mistakes are not" if shown < dangerous < total else ""
    return (
        "overview draws every sample, each mistake among them."
        if step <= 1
        else (
            f"overview draws all {dangerous} dangerous mistakes but only {shown} of the {total} conservative ones "
            f"(1 sample in {step}){', ' + most if most else ''}."
        )
    )


KINDS = {  # §5's four kinds of sample: (the truth, the model's answer) -> the mark and its meaning
    (True, True): "circle: valid, predicted valid",
    (False, False): "diamond: in collision, predicted in collision",
    (False, True): "diamond + sparkle: in collision, predicted valid (dangerous)",
    (True, False): "circle + sparkle: valid, predicted in collision (conservative)",
}


def truth_vs_prediction(
    valid: np.ndarray,
    predicted: np.ndarray,
    scores: Mapping[str, float],
    threshold: float,
    room: np.ndarray,
    freed: np.ndarray,
    nudge: float,
) -> str:
    """§5's counts: the four kinds of sample, the model's scores against answering "valid" to all, where the mistakes
    lie (``room (N,)``: clearance bounds, ``freed (N,)``: free after a move of the base by ``nudge``), and a line that
    reads it. ``valid``, ``predicted (N,)``: the truth and the model's answer."""

    def median_room(mask):
        return f"{np.median(room[mask]):.2f}" if mask.any() else "none"

    def share_freed(mask):
        return f"{freed[mask].mean():.0%} of {mask.sum()}" if mask.any() else "none"

    masks = {kind: (valid == truth) & (predicted == answer) for (truth, answer), kind in KINDS.items()}
    circles, diamonds = valid & predicted, ~valid & ~predicted  # the model right
    dangerous, conservative = ~valid & predicted, valid & ~predicted  # the model wrong
    read = []
    if circles.any() and conservative.any():
        nearer = np.median(room[conservative]) < np.median(room[circles])
        read.append(
            f"the conservative mistakes lie {'nearer' if nearer else 'no nearer'} to the blocks than the circles it "
            "gets right"
        )
    if diamonds.any() and dangerous.any():
        shallower = freed[dangerous].mean() > freed[diamonds].mean()
        read.append(
            f"a nudge frees {'more' if shallower else 'no more'} of the dangerous mistakes than of the diamonds it "
            "gets right"
        )
    return (
        "| samples | count | share |\n| --- | ---: | ---: |\n"
        + "\n".join(f"| {kind} | {mask.sum()} | {percent(mask.mean())} |" for kind, mask in masks.items())
        + f"\n\naccuracy **{percent(scores['acc'])}**, TPR {percent(scores['tpr'])}, TNR {percent(scores['tnr'])} "
        f'(threshold {threshold:.2f}); answering "valid" to all {len(valid)} of these samples: {percent(valid.mean())}'
        "\n\n"
        "| where the samples lie | the model right | the model wrong |\n| --- | ---: | ---: |\n"
        f"| valid: median clearance bound (workspace units) | {median_room(circles)} (circles) "
        f"| {median_room(conservative)} (conservative) |\n"
        f"| in collision: freed by moving the base {nudge} along one axis | {share_freed(diamonds)} (diamonds) "
        f"| {share_freed(dangerous)} (dangerous) |\n\n"
        + (("Read: " + ", and ".join(read) + ".") if read else "Read: the model made no mistake here.")
    )


def paper_share() -> str:
    """The valid share the paper's Table 2 row implies, against that of uniform samples (the recipe's record)."""
    paper = chapter05.paper_numbers.MLP[SCENARIO]["unseen"]
    implied = (paper["acc"] - paper["tnr"]) / (paper["tpr"] - paper["tnr"])  # acc = TPR share + TNR (1 - share)
    _, uniform = chapter05.recorded_scores("paper")
    return (
        '<details><summary>Which "unseen" test did the paper score?</summary>\n\n'
        'Of its seen test, §IV-A says the samples are "approximately distributed 50/50 between valid and invalid". '
        'Of the unseen one it says only that it generates "2000 samples for each 3D office-like workspace, and 400 '
        'samples for each 3D clutter workspace" "regardless of their validity", and "This is evaluated as unseen '
        'scenarios". '
        "Section 1's fold reads those 400 as the planner's uniform samples; Table 2 may have scored another set, "
        "since its three numbers fix the valid share of its test set.\n\n"
        f"The paper's row: {paper['acc']:.0%} = {paper['tpr']:.0%} × share + {paper['tnr']:.0%} × (1 − share) gives a "
        f"valid share of about {implied:.0%}. On uniform samples in the recipe's unseen workspaces, "
        f"{uniform:.0%} valid, "
        f"the same TPR and TNR would give an accuracy of {paper['tpr'] * uniform + paper['tnr'] * (1 - uniform):.0%}, "
        f"not {paper['acc']:.0%}. That reads TPR as valid configurations called valid, our reading. "
        f"With collisions the positive class, TPR and TNR swap places, and the share is about {1 - implied:.0%} "
        f"valid: still not {uniform:.0%}. On either reading, one answer for every sample would score at most "
        f"{max(implied, 1 - implied):.0%} on that test, below the paper's {paper['acc']:.0%}: the paper's "
        f"{paper['acc']:.0%} is not a no-skill score.\n\n"  # reader r58e, 05 lift 3
        # reader r52e, 05 item 1: the uniform share is our workspaces', set by a block size the paper does not give
        f"This is a hint, not evidence. The {uniform:.0%} is the valid share of our workspaces, whose blocks are "
        "1 × 1 × 1 cubes. The paper gives no block size; with larger blocks its uniform samples could be about "
        f"{implied:.0%} valid, and Table 2 could then have scored the planner's 400.\n\n</details>"
    )


def trainings(threshold: float) -> str:
    """The chapter's map of its three trainings of `strong`, each with its threshold (``threshold``: the notebook's
    network's), under the answer (reader r54e, 05 lift 2; r50e, 05 lift 5); the answer's fold names them only (r51e)."""
    timed, mine, lazy, name, at = (
        chapter05.TIMED,
        chapter05.MINE,
        chapter05.LAZY,
        chapter05.run_name,
        chapter05.COMPILED,
    )
    threshold_of = chapter05.recorded_threshold
    return (
        "The three trainings of `strong` in this chapter, each with its own weights, threshold and label:\n\n"
        "| training | threshold | where the chapter uses it |\n| --- | ---: | --- |\n"
        f"| **{timed}** ({name(at).split(', threshold')[0]}) | {threshold_of(at):.2f} | the answer, its accuracy "
        "row at the end |\n"
        f"| **{mine}** (`trained_models`, cached) | {threshold:.2f} | §5's views, §6–7's lazy-PRM path, its accuracy "
        "row at the end |\n"
        f"| **{lazy}** ({name('strong').split(', threshold')[0]}, which calls it the *lazy-PRM network*) | "
        f"{threshold_of('strong'):.2f} | the closing fold: the lazy PRM timed |"
    )
