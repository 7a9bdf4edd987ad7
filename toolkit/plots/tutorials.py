"""Figures of the tutorials (``tutorials/``): a mesh workspace and its grid, samplers in a narrow passage.

The tutorials reuse the notebooks' figures where they fit (``robot_drawing.robot_figure``,
``classifier.metrics_bars``, ``scenes.path_frame``, ``cae.training_curves``); the two
here are what only the tutorials show. Every function returns a matplotlib ``Figure``
and never calls ``show()``.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Rectangle
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from toolkit.geometry.collision import CollisionChecker
from toolkit.geometry.workspace import MeshWorkspace
from toolkit.plots import planning
from toolkit.plots.alt import Part, describe, parts_of
from toolkit.plots.cspace import frame_region
from toolkit.plots.palette import COLORS, halo

MESH_COLOR, VOXEL_COLOR = COLORS["mesh"], COLORS["voxel"]


def mesh_and_grid(workspace: MeshWorkspace, title: str = "") -> Figure:
    """Left: the workspace's triangles. Right: its occupancy grid, one cube per occupied cell (what the networks
    read)."""
    fig = Figure(figsize=(10, 4.8))
    mesh_ax = fig.add_subplot(1, 2, 1, projection="3d")
    mesh_ax.add_collection3d(
        Poly3DCollection(
            workspace.vertices[workspace.faces],
            facecolors=MESH_COLOR,
            edgecolors=COLORS["occupied"],
            linewidths=0.2,
            alpha=0.6,
        )
    )
    mesh_ax.set_title(f"the mesh: {len(workspace.faces)} triangles in {len(workspace.boxes)} parts", fontsize=10)
    grid_ax = fig.add_subplot(1, 2, 2, projection="3d")
    occupied = workspace.occupancy() > 0
    edges = [workspace.lower[d] + np.arange(n + 1) for d, n in enumerate(workspace.grid_shape)]
    x, y, z = np.meshgrid(*edges, indexing="ij")  # cell corners
    grid_ax.voxels(
        x, y, z, occupied, facecolors=VOXEL_COLOR, edgecolors=COLORS["occupied"], linewidth=0.2, alpha=0.5, shade=False
    )
    grid_ax.set_title(f"its occupancy grid: {occupied.sum()} of {occupied.size} cells occupied", fontsize=10)
    for ax in (mesh_ax, grid_ax):
        frame_region(ax, workspace)
        ax.set_box_aspect(workspace.upper - workspace.lower)
        ax.view_init(elev=25, azim=-60)
        ax.locator_params(nbins=4)
        ax.tick_params(labelsize=8)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    text = f"{title + ': ' if title else ''}left, a mesh workspace of {len(workspace.faces)} triangles in "
    text += f"{len(workspace.boxes)} parts, in 3D; right, its occupancy grid, {occupied.sum()} of {occupied.size} "
    text += f"cells occupied ({occupied.mean():.1%}), one cube per occupied cell."
    layers = Part(
        "the occupancy grid by z layer",
        "how many cells of each layer are occupied, bottom first",
        ("layer z", "occupied cells", "of"),
        tuple(
            (f"{workspace.lower[2] + z + 0.5:g}", str(int(occupied[:, :, z].sum())), str(occupied[:, :, z].size))
            for z in range(occupied.shape[2])
        ),
    )
    return describe(fig, text, [layers])


def samplers_in_a_passage(
    exact: CollisionChecker, samples: dict[str, np.ndarray], passage: tuple, *, attempts: int | None = None
) -> Figure:
    """One panel per sampler, its samples ``(M, 2)`` over the point robot's C-obstacles, the ``passage``
    ``((x0, y0), (x1, y1))`` outlined (dashed), with how many samples fell inside it in each panel's title."""
    fig = planning.samplers(exact, samples, attempts, nearness=False)  # one dashed outline: the passage
    (x0, y0), (x1, y1) = passage
    said = []
    for ax, (name, Q) in zip(fig.axes, samples.items()):
        outlined = Rectangle(
            (x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor=COLORS["highlight"], linewidth=1.2, linestyle="--"
        )
        outlined.set_path_effects(halo(1.2))
        ax.add_patch(outlined)
        inside = int(np.sum(np.all(((x0, y0) <= Q) & ((x1, y1) >= Q), axis=1)))
        ax.set_title(f"{ax.get_title()}\n{inside} in the passage", fontsize=9)
        said.append(f"{name} {len(Q)} samples, {inside} in the passage")
    fig.suptitle(f"{len(samples)} samplers, the same attempts each (dashed: the narrow passage)", fontsize=10)
    text = f"Samples of {len(samples)} samplers over the point robot's C-obstacles, the narrow passage from "
    text += f"({x0:g}, {y0:g}) to ({x1:g}, {y1:g}) outlined: "
    text += "; ".join(said) + (f", of {attempts} attempts each." if attempts else ".")
    return describe(fig, text, parts_of(fig))
