"""Chapter 01's closing tables: our workspaces and robots measured against the paper's §IV-A, and what the paper
does not give, the free share of uniform configurations and the default exact checker's speed.

:func:`paper_comparison` builds both, as Markdown; :func:`speed_summary`, section 3's table of checker speeds and the
line under it. The speed table sets the default checker's rate timed alone
beside section 3's, timed in turns with FCL on one workspace (review r27a: the two disagreed and the page did not
say why), with a middle column that differs from the first in the timing only and from the last in the
workspaces and configurations only.
"""

from __future__ import annotations

import numpy as np

from toolkit import scenarios
from toolkit.experiments import bench
from toolkit.geometry.collision import exact_checker

PAPER = {  # §IV-A, as printed; the paper reports no free share and no collision-check speed
    "2ds": {"blocks": "3–5", "size": "0.5 × 0.5"},
    "3do": {"blocks": "25–30", "size": "1.5 × 1 × 1"},
    "3dc7": {"blocks": "110–125", "size": "links 0.1³, 0.4×0.1×0.1"},
    "3dc9": {"blocks": "110–125", "size": "links 0.1³, 0.4×0.1×0.1"},
}
SHAPE_HEADER = "| scenario | blocks: **ours** / paper | occupied | robot size at q = 0: **ours** / paper |"


def paper_comparison(
    section_3: dict[str, dict[str, float]],
    *,
    n_workspaces: int,
    n_checked: int,
    n_samples: int,
    rounds: int,
    seed: int = 0,
) -> tuple[str, str]:
    """Two Markdown tables, one row per scenario of :data:`PAPER`. The first: block counts and occupied share over
    ``n_workspaces`` workspaces (drawn from ``default_rng(seed)``), and the robot's size at the zero configuration
    (its links' bounding box), ours beside the paper's. The second: the free share of ``n_samples`` uniform
    configurations, averaged over the first ``n_checked`` of those workspaces, and the default exact checker's
    checks a second in this thread's CPU time (:func:`bench.cpu_clock`), three ways: section 3's rate
    (``section_3``: scenario: {checker class name: rate}, timed in turns with FCL), the same checker timed alone on
    section 3's workspace and configurations (``seed``, ``seed + 1``, as chapter 01 draws them), and alone on the
    first ``n_checked`` workspaces, other configurations (the median; the first of them is section 3's)."""
    shapes = [SHAPE_HEADER, "| --- | --- | --- | --- |"]
    checks = [
        "| scenario | free | checks / s: section 3,<br>in turns with FCL | section 3's workspace,<br>alone "
        f"| first {n_checked} workspaces,<br>alone (median) |",
        "| --- | ---: | ---: | ---: | ---: |",
    ]
    for name in PAPER:
        s = scenarios.get(name)
        rng = np.random.default_rng(seed)
        spaces = [s.make_workspace(rng) for _ in range(n_workspaces)]
        shapes.append(_shape_row(name, spaces))
        free, rates = [], []
        for ws in spaces[:n_checked]:
            Q = s.robot.sample(rng, n_samples)  # (n, dof)
            checker = exact_checker(ws, s.robot)
            free.append(checker.are_valid(Q).mean())
            rates.append(_alone(checker, Q, rounds))
        own = exact_checker(s.make_workspace(np.random.default_rng(seed)), s.robot)
        there = section_3[name][type(own).__name__]
        here = _alone(own, s.robot.sample(np.random.default_rng(seed + 1), n_samples), rounds)
        checks.append(f"| {name} | {np.mean(free):.0%} | {there:,.0f} | {here:,.0f} | {np.median(rates):,.0f} |")
    return "\n".join(shapes), "\n".join(checks)


def speed_summary(speeds: dict[str, dict[str, float]], names: dict[str, str]) -> str:
    """Section 3's table of checks a second (``speeds``: scenario: {checker class name: rate}; ``names``: checker
    class name: its column's name, FCL's first) and the line under it: in 3D FCL's time per check as a multiple of
    the compiled checker's (the median over the 3D rows, and their range), in 2D as a multiple of the fastest
    check's, named."""
    in_3d = [speeds[n]["CompiledChecker"] / speeds[n]["FCLChecker"] for n in speeds if n != "2ds"]
    fastest = max(speeds["2ds"], key=lambda k: speeds["2ds"][k])  # the 2D check that took least time
    in_2d = speeds["2ds"][fastest] / speeds["2ds"]["FCLChecker"]
    return (
        bench.rate_table(speeds, names, ratio=("FCLChecker", "CompiledChecker"))
        + f"\n\nSame answers, but in 3D FCL took about **{np.median(in_3d):.0f}x** the compiled checker's time per "
        f"check ({min(in_3d):.0f}–{max(in_3d):.0f}x in this run), and in 2D **{in_2d:.0f}x** the "
        f"{names[fastest]} check's, the fastest there."
    )


def _shape_row(name: str, spaces: list) -> str:
    """One row of the first table: the block counts' range and the mean occupied share of ``spaces``, the robot's
    size at q = 0, each beside the paper's."""
    robot = scenarios.get(name).robot
    counts = [len(ws.boxes) for ws in spaces]
    occupied = np.mean([(ws.occupancy() > 0).mean() for ws in spaces])
    bounds = robot.link_aabbs(np.zeros(robot.dof))[0]  # (L, 2, D)
    size = "×".join(f"{e:.2g}" for e in bounds[:, 1].max(axis=0) - bounds[:, 0].min(axis=0))
    paper = PAPER[name]
    blocks = f"**{min(counts)}–{max(counts)}** / {paper['blocks']}"
    return f"| {name} | {blocks} | {occupied:.1%} | **{size}** / {paper['size']} |"


def _alone(checker, Q: np.ndarray, rounds: int) -> float:
    """``checker``'s checks a second on ``Q``, timed alone in CPU time (after an untimed call: a new workspace's
    checker sets itself up on its first), the median of ``rounds``."""
    with bench.cpu_clock():
        return bench.in_turns({"": (lambda: checker.are_valid(Q), len(Q))}, rounds)[""]
