"""The tutorials' figures draw what they are given: the mesh's triangles, its grid's occupied cells, passage counts."""

import io

import numpy as np
from matplotlib.colors import to_rgba
from matplotlib.patches import Rectangle
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from toolkit.geometry import meshes, robots
from toolkit.geometry.collision import exact_checker
from toolkit.geometry.workspace import Workspace, from_mesh
from toolkit.plots import tutorials
from toolkit.plots.palette import COLORS


def test_mesh_and_grid_draws_every_triangle_and_one_cube_per_occupied_cell():
    boxes = np.array([[[1.0, 1.0, 0.0], [3.0, 2.0, 1.0]], [[5.25, 5.25, 2.25], [5.75, 7.75, 2.75]]])  # 2 + 3 cells
    ws = from_mesh(meshes.mesh_of_boxes(boxes), lower=np.zeros(3), upper=np.full(3, 11.0))
    fig = tutorials.mesh_and_grid(ws, title="two boxes")
    fig.savefig(io.BytesIO())  # 3D collections project their polygons when drawn
    mesh_ax, grid_ax = fig.axes
    triangles = [c for c in mesh_ax.collections if isinstance(c, Poly3DCollection)]
    assert len(triangles) == 1 and len(triangles[0].get_paths()) == len(ws.faces) == 24
    cubes = [c for c in grid_ax.collections if isinstance(c, Poly3DCollection)]
    assert (ws.occupancy() > 0).sum() == 5
    assert len(cubes) == 5  # ax.voxels: one collection per occupied cell, holding its faces no neighbour hides
    assert sum(len(c.get_paths()) for c in cubes) == 10 + 14  # a 2-cell and a 3-cell row
    assert "24 triangles in 2 parts" in mesh_ax.get_title() and "5 of 1331 cells" in grid_ax.get_title()
    assert fig.get_suptitle() == "two boxes"


def test_samplers_in_a_passage_counts_the_samples_inside_it():
    ws = Workspace(np.zeros(2), np.full(2, 31.0), np.array([[[0.0, 14.0], [15.0, 17.0]], [[16.0, 14.0], [31.0, 17.0]]]))
    exact = exact_checker(ws, robots.point_robot())
    samples = {"A": np.array([[15.5, 15.0], [15.4, 16.9], [3.0, 3.0]]), "B": np.array([[3.0, 3.0]])}
    fig = tutorials.samplers_in_a_passage(exact, samples, ((15.0, 14.0), (16.0, 17.0)), attempts=10)
    assert len(fig.axes) == 2
    assert fig.axes[0].get_title().endswith("2 in the passage") and fig.axes[1].get_title().endswith("0 in the passage")
    assert "3 samples of 10 attempts" in fig.axes[0].get_title()
    outlined = [
        p
        for p in fig.axes[0].patches
        if isinstance(p, Rectangle) and p.get_edgecolor()[:3] == to_rgba(COLORS["highlight"])[:3]
    ]
    assert (
        len(outlined) == 1
        and outlined[0].get_xy() == (15.0, 14.0)
        and (outlined[0].get_width(), outlined[0].get_height()) == (1.0, 3.0)
    )
    assert fig.get_suptitle().startswith("2 samplers")
