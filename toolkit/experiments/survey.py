"""Chapter 01's tables: its closing one, our workspaces and robots measured against the paper's §IV-A beside what
the paper does not give, the free share of uniform configurations (:func:`paper_comparison`), and section 3's
table of checker speeds with the line under it (:func:`speed_summary`).
"""

from __future__ import annotations

import numpy as np

from toolkit import scenarios
from toolkit.experiments import bench
from toolkit.geometry.collision import exact_checker

PAPER = {  # §IV-A, as printed; the paper reports no free share and no collision-check speed
    "2ds": {"blocks": "around 3–5", "size": "0.5 × 0.5"},
    "3do": {"blocks": "25–30", "size": "1.5 × 1 × 1"},
    "3dc7": {"blocks": "110–125", "size": "links 0.1³, 0.4×0.1×0.1"},
    "3dc9": {"blocks": "110–125", "size": "links 0.1³, 0.4×0.1×0.1"},
}
SHAPE_HEADER = "| scenario | blocks: **ours** / paper | occupied | robot size at q = 0: **ours** / paper | free |"


def paper_comparison(*, n_workspaces: int, n_checked: int, n_samples: int, seed: int = 0) -> str:
    """A Markdown table, one row per scenario of :data:`PAPER`: block counts and occupied share over
    ``n_workspaces`` workspaces (drawn from ``default_rng(seed)``) and the robot's size at the zero configuration
    (its links' bounding box), ours beside the paper's, then what the paper does not give, the free share of
    ``n_samples`` uniform configurations, averaged over the first ``n_checked`` of those workspaces. Checker speeds
    stay in section 3's table, timed in turns (review r30a: a second set timed alone disagreed with it, and the
    chapter needs one ratio, not three speed columns)."""
    shapes = [SHAPE_HEADER, "| --- | --- | --- | --- | ---: |"]
    for name in PAPER:
        s = scenarios.get(name)
        rng = np.random.default_rng(seed)
        spaces = [s.make_workspace(rng) for _ in range(n_workspaces)]
        free = [
            exact_checker(ws, s.robot).are_valid(s.robot.sample(rng, n_samples)).mean() for ws in spaces[:n_checked]
        ]
        shapes.append(f"{_shape_row(name, spaces)} {np.mean(free):.0%} |")
    return "\n".join(shapes)


def speed_summary(speeds: dict[str, dict[str, float]], names: dict[str, str]) -> str:
    """Section 3's table of checks a second (``speeds``: scenario: {checker class name: rate}; ``names``: checker
    class name: its column's name, FCL's first) and the line under it: in 3D FCL's time per check as a multiple of
    the compiled checker's (the 3D rows' range: review r36a read "about 59x" beside a row of 53x), in 2D as a
    multiple of the fastest check's, named."""
    in_3d = [speeds[n]["CompiledChecker"] / speeds[n]["FCLChecker"] for n in speeds if n != "2ds"]
    fastest = max(speeds["2ds"], key=lambda k: speeds["2ds"][k])  # the 2D check that took least time
    in_2d = speeds["2ds"][fastest] / speeds["2ds"]["FCLChecker"]
    return (
        bench.rate_table(speeds, names, ratio=("FCLChecker", "CompiledChecker"))
        + f"\n\nSame answers, but in 3D FCL took **{min(in_3d):.0f}–{max(in_3d):.0f}x** the compiled checker's time "
        f"per check in this run, and in 2D **{in_2d:.0f}x** the {names[fastest]} check's, the fastest there."
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
