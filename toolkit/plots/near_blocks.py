"""Configurations worth drawing in chapter 01: a valid one near a block, its colliding twin, and widgets that
sweep slices of configuration space through it (paper §II-A: a C-obstacle seen one slice at a time).

A random valid configuration is usually far from every block, and its slices are all free;
:func:`configuration_near_blocks` picks one whose slices cross C-obstacles, :func:`nudged_into_a_block` moves it
until a block makes it invalid (the figure of one check), :func:`slice_hits` names the blocks a slice's links
reach, and :func:`slice_explorer` draws :func:`toolkit.plots.cspace.cspace_slice` through it under sliders.
"""

from __future__ import annotations

import itertools
from collections import Counter
from functools import lru_cache

import numpy as np

from toolkit.geometry.collision import CollisionChecker, exact_checker
from toolkit.plots.contact import touching
from toolkit.plots.cspace import checker_workspace, cspace_slice
from toolkit.plots.slices import slice_configs


def configuration_near_blocks(checker: CollisionChecker, rng: np.random.Generator, n: int = 2000) -> np.ndarray:
    """A valid configuration ``(dof,)`` close to a block: a slice through it is likely to cross C-obstacles.

    Of ``n`` uniform samples, the valid one whose link boxes' axis-aligned bounds come
    nearest a block (a random valid configuration is usually far from every block, and
    its slices through arm joints are all free).
    """
    robot, boxes = checker.robot, checker_workspace(checker).boxes  # boxes (K, 2, D)
    Q = robot.sample(rng, n)
    Q = Q[checker.are_valid(Q)]  # (M, dof)
    if len(Q) == 0:
        raise ValueError(f"none of {n} samples is valid: draw more")
    if len(boxes) == 0:
        return Q[0]
    aabbs = robot.link_aabbs(Q)[:, :, None]  # (M, L, 1, 2, D)
    gap = np.maximum(np.maximum(boxes[:, 0] - aabbs[..., 1, :], aabbs[..., 0, :] - boxes[:, 1]), 0)  # (M, L, K, D)
    return Q[np.argmin(np.linalg.norm(gap, axis=-1).min(axis=(1, 2)))]


def nudged_into_a_block(checker: CollisionChecker, q, dofs: tuple[int, ...] = (0, 1), step: float = 0.05):
    """The configuration nearest ``q (dof,)`` that a block makes invalid, moving one of ``dofs`` at a time up or down
    in steps of ``step`` (within the robot's bounds): the same robot, a little further, touching (a figure's
    colliding twin of a valid :func:`configuration_near_blocks`). ``None`` if none is within the bounds."""
    robot, workspace = checker.robot, checker_workspace(checker)
    q = robot.check_configs(q)[0]
    for k in range(1, int(np.ceil(np.max(robot.upper - robot.lower) / step)) + 1):
        for dof, sign in itertools.product(dofs, (1, -1)):
            moved = q.copy()
            moved[dof] += sign * k * step
            if robot.in_bounds(moved[None])[0] and not checker.is_valid(moved) and touching(robot, workspace, moved):
                return moved
    return None


def slice_hits(checker: CollisionChecker, q, joints: tuple[int, int], resolution: int) -> tuple[Counter, int]:
    """Over the in-collision pixels of :func:`toolkit.plots.cspace.cspace_slice`'s slice through ``q`` sweeping
    ``joints``: how many pixels each (link, block) pair touches in, and how many no block touches in (a link out of
    the region). Reader r51a: the text named no block for the links to sweep into."""
    robot, workspace = checker.robot, checker_workspace(checker)
    Q = slice_configs(robot, q, joints, resolution=resolution)[2].reshape(-1, robot.dof)  # (n * n, dof)
    hits: Counter = Counter()
    elsewhere = 0
    for moved in Q[~checker.are_valid(Q)]:
        pairs = touching(robot, workspace, moved)
        hits.update(pairs)
        elsewhere += not pairs
    return hits, elsewhere


def slice_hits_table(checker: CollisionChecker, q, joints: tuple[int, int], resolution: int) -> str:
    """:func:`slice_hits` as a Markdown table: each link, the block it reaches (its corners) and in how many of the
    slice's pixels."""
    hits, elsewhere = slice_hits(checker, q, joints, resolution)
    boxes, pixels = checker_workspace(checker).boxes, int(resolution) ** 2
    corner = lambda c: "(" + ", ".join(f"{v:g}" for v in c) + ")"
    rows = [
        f"| link {link} | block {block}, {corner(boxes[block][0])} to {corner(boxes[block][1])} | {n} of {pixels} |"
        for (link, block), n in sorted(hits.items())
    ]
    rows += [f"| a link | the region's boundary | {elsewhere} of {pixels} |"] if elsewhere else []
    return "| link | touches | pixels |\n| --- | --- | ---: |\n" + "\n".join(rows)


def slice_explorer(sweeps: dict[str, tuple[int, int]], start: str, seed: int = 0, resolution: int = 60):
    """Widgets to explore 2-DoF slices (chapter 01, section 5): a scenario (``sweeps``: name -> the two DoF it
    starts sweeping; ``start`` first), a workspace seed, the two DoF to sweep, the robot panel's view, and one slider
    per DoF at the values of a valid configuration near a block (:func:`configuration_near_blocks`). Each redraw is
    one :func:`cspace_slice` at ``resolution``; a workspace's checker and start are computed once per scenario and
    seed. Returns the ``HBox`` to display."""
    import ipywidgets as widgets
    from IPython.display import display

    scenario_w = widgets.Dropdown(options=list(sweeps), value=start, description="scenario")
    seed_w = widgets.IntSlider(seed, 0, 20, description="seed", continuous_update=False)
    view_w = widgets.Dropdown(options=["xy", "xz", "3d"], description="robot view")
    joint_i_w, joint_j_w = widgets.Dropdown(description="sweep i"), widgets.Dropdown(description="sweep j")
    fixed_box, out = widgets.VBox(), widgets.Output()
    redrawing = {"paused": False}  # resetting several widgets at once draws once, not per widget

    def redraw(_=None):
        if redrawing["paused"]:
            return
        checker, _ = _checker_and_start(scenario_w.value, seed_w.value)
        q = np.array([slider.value for slider in fixed_box.children])
        joints = (joint_i_w.value, joint_j_w.value)
        out.clear_output(wait=True)
        with out:
            if joints[0] == joints[1]:
                print("choose two different DoF to sweep")
            else:
                display(cspace_slice(checker, q, joints, resolution=resolution, view=view_w.value))

    def reset(_=None):
        checker, first = _checker_and_start(scenario_w.value, seed_w.value)
        robot = checker.robot
        redrawing["paused"] = True
        sliders = [
            widgets.FloatSlider(value=v, min=lo, max=hi, step=0.01, description=name, continuous_update=False)
            for v, lo, hi, name in zip(first, robot.lower, robot.upper, robot.dof_names)
        ]
        for slider in sliders:
            slider.observe(redraw, "value")
        fixed_box.children = sliders
        joint_i_w.options = joint_j_w.options = [(name, k) for k, name in enumerate(robot.dof_names)]
        joint_i_w.value, joint_j_w.value = sweeps[scenario_w.value]
        redrawing["paused"] = False
        redraw()

    for w in (scenario_w, seed_w):
        w.observe(reset, "value")
    for w in (view_w, joint_i_w, joint_j_w):
        w.observe(redraw, "value")
    reset()
    return widgets.HBox([widgets.VBox([scenario_w, seed_w, joint_i_w, joint_j_w, view_w, fixed_box]), out])


@lru_cache(maxsize=32)
def _checker_and_start(name: str, seed: int):
    """The exact checker of scenario ``name``'s workspace ``seed`` and a valid configuration near its blocks, built
    once per scenario and seed (the explorer redraws often)."""
    from toolkit import scenarios

    s = scenarios.get(name)
    checker = exact_checker(s.make_workspace(np.random.default_rng(seed)), s.robot)
    return checker, configuration_near_blocks(checker, np.random.default_rng(seed))
