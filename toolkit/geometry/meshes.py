"""Triangle-mesh obstacles: loading, inside tests, fcl models, voxel grids, and a demo room.

The paper's workspaces are axis-aligned blocks (§IV-A); a real scene comes as a
mesh (STL, OBJ, GLB). Three questions decide how a mesh becomes a workspace
(:func:`toolkit.geometry.workspace.from_mesh`) and how it is checked exactly
(:class:`toolkit.geometry.collision.MeshChecker`):

- *does a robot link touch the surface?* python-fcl's ``BVHModel`` (a bounding-volume
  hierarchy over the triangles) answers it for a box against thousands of triangles;
- *does a link lie wholly inside a solid?* Then it touches no triangle, and fcl says
  "no contact". The generalized winding number (Jacobson et al., SIGGRAPH 2013) of one
  of its points answers it: the solid angle the surface subtends there, over 4 pi —
  1 inside a closed surface, 0 outside, and each inside of overlapping closed parts
  counts once more (a mesh of overlapping boxes needs no boolean union);
- *which grid cells are occupied?* A cell is occupied when the solid meets its open
  interior: the surface crosses the cell, or its centre lies inside. For blocks on the
  integer grid this is exactly the block workspaces' rule (a cell centre inside a
  block, :meth:`toolkit.geometry.workspace.Workspace.occupancy`), and a board thinner than a
  cell still marks the cells it crosses. trimesh's own voxelizer (``mesh.voxelized``)
  rounds points of the surface to the nearest cell centre, so a face lying on a cell
  boundary — every face of a block workspace — marks the cell on one side or the
  other by numpy's round-half-to-even, growing a unit block to as many as 27 cells;
  away from cell boundaries the two grids agree (``tests/test_mesh_workspace.py``).

``python -m toolkit.geometry.meshes PATH`` writes the demo room (:func:`room`) to ``PATH``
(any format trimesh exports by suffix: ``.stl``, ``.obj``, ``.glb``).
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path
from typing import cast

import fcl
import numpy as np
import trimesh
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

ROOM_REGION = (11.0, 11.0, 11.0)  # the 3D clutter scenarios' region: their robots and models fit the room


def load(mesh) -> trimesh.Trimesh:
    """A single ``trimesh.Trimesh`` from a mesh, or a path to a file trimesh reads (a scene's parts are joined)."""
    if isinstance(mesh, trimesh.Trimesh):
        return mesh
    if isinstance(mesh, (str, Path)):
        loaded = trimesh.load(mesh, force="mesh")
        if not isinstance(loaded, trimesh.Trimesh):
            raise ValueError(f"{mesh} holds no triangle mesh: trimesh read a {type(loaded).__name__}")
        return loaded
    raise TypeError(f"expected a trimesh.Trimesh or a path to a mesh file, got {type(mesh).__name__}")


class Solid:
    """A triangle mesh as obstacles: its connected parts and their bounds, an fcl ``BVHModel``, inside tests.

    ``vertices (V, 3)``, ``faces (F, 3)`` (vertex indices, counter-clockwise seen from
    outside). Parts are sets of faces joined by shared edges; ``bounds (K, 2, 3)``
    are their min / max corners, boxes that cover the mesh.
    """

    def __init__(self, vertices: np.ndarray, faces: np.ndarray):
        self.vertices = np.asarray(vertices, dtype=float).reshape(-1, 3)
        self.faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
        self.triangles = self.vertices[self.faces]  # (F, 3, 3)
        part_of_face = _parts(self.faces)  # (F,)
        self.parts = [
            np.flatnonzero(part_of_face == k) for k in range(part_of_face.max() + 1 if len(part_of_face) else 0)
        ]
        self.bounds = np.array(
            [[self.triangles[f].min(axis=(0, 1)), self.triangles[f].max(axis=(0, 1))] for f in self.parts]
        ).reshape(-1, 2, 3)  # (K, 2, 3)
        self.object = _bvh(self.vertices, self.faces) if len(self.faces) else None

    def inside(self, points: np.ndarray) -> np.ndarray:
        """``(M,)`` whether each point ``(M, 3)`` lies inside the solid: its winding number exceeds one half.

        A closed part's winding number is 0 outside its bounds, so each part is summed
        only over the points within them.
        """
        points = np.asarray(points, dtype=float).reshape(-1, 3)
        winding = np.zeros(len(points))
        for faces, (lo, hi) in zip(self.parts, self.bounds):
            near = np.flatnonzero(np.all((points >= lo) & (points <= hi), axis=1))
            if len(near):
                winding[near] += winding_numbers(points[near], self.triangles[faces])
        return winding > 0.5

    def touches(self, center: np.ndarray, size: np.ndarray, rotation: np.ndarray | None = None) -> bool:
        """Whether a box (centre ``(3,)``, side lengths ``(3,)``, turned by ``rotation (3, 3)``) touches the surface."""
        if self.object is None:
            return False
        box = fcl.CollisionObject(fcl.Box(*size), fcl.Transform(np.eye(3) if rotation is None else rotation, center))
        return fcl.collide(box, self.object, fcl.CollisionRequest(), fcl.CollisionResult()) > 0

    def voxel_grid(self, lower, upper) -> np.ndarray:
        """Occupancy of the unit cells from ``lower`` to ``upper``: +1 where the solid meets a cell's
        open interior, else -1.

        Only cells that meet a part's bounds are tested: the centre inside, or else the
        cell touching the surface, tested as a box a millionth smaller than the cell (a
        face on its boundary does not count).
        """
        lower = np.asarray(lower, dtype=float)
        shape = tuple(int(round(s)) for s in np.asarray(upper, dtype=float) - lower)
        centres = lower + 0.5 + np.stack(np.meshgrid(*map(np.arange, shape), indexing="ij"), axis=-1).reshape(-1, 3)
        near = np.zeros(len(centres), dtype=bool)  # (C,) the cell meets some part's bounds
        for lo, hi in self.bounds:
            near |= np.all((centres + 0.5 > lo) & (centres - 0.5 < hi), axis=1)
        occupied = np.zeros(len(centres), dtype=bool)
        occupied[near] = self.inside(centres[near])
        cell = np.full(3, 1.0 - 1e-6)
        for i in np.flatnonzero(near & ~occupied):
            occupied[i] = self.touches(centres[i], cell)
        return np.where(occupied, 1.0, -1.0).astype(np.float32).reshape(shape)


def winding_numbers(points: np.ndarray, triangles: np.ndarray, chunk: int = 1024) -> np.ndarray:
    """``(M,)`` generalized winding numbers of ``points (M, 3)`` w.r.t. ``triangles (T, 3, 3)`` (outward-facing).

    The solid angle of each triangle seen from a point (Van Oosterom and Strackee 1983),
    summed and divided by 4 pi.
    """
    points = np.asarray(points, dtype=float).reshape(-1, 3)
    total = np.zeros(len(points))
    for start in range(0, len(points), chunk):
        rel = triangles[None] - points[start : start + chunk, None, None]  # (m, T, 3 corners, 3)
        a, b, c = rel[:, :, 0], rel[:, :, 1], rel[:, :, 2]  # (m, T, 3) each
        la, lb, lc = (np.linalg.norm(v, axis=-1) for v in (a, b, c))  # (m, T) each
        det = np.einsum("mtd,mtd->mt", a, np.cross(b, c))
        dots = (
            np.einsum("mtd,mtd->mt", a, b) * lc
            + np.einsum("mtd,mtd->mt", b, c) * la
            + np.einsum("mtd,mtd->mt", c, a) * lb
        )
        total[start : start + chunk] = 2 * np.arctan2(det, la * lb * lc + dots).sum(axis=1)
    return total / (4 * np.pi)


def _parts(faces: np.ndarray) -> np.ndarray:
    """``(F,)`` the connected part of each face: faces sharing an edge are connected (boxes that only touch at a
    corner, such as a shelf's boards and panels read back from an STL file, stay apart)."""
    if len(faces) == 0:
        return np.zeros(0, dtype=np.int64)
    pairs = trimesh.graph.face_adjacency(faces=faces)  # (A, 2) faces sharing an edge
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(faces), len(faces)))
    return connected_components(graph, directed=False)[1]


def _bvh(vertices: np.ndarray, faces: np.ndarray) -> fcl.CollisionObject:
    """The triangles as one fcl collision object: a ``BVHModel`` (OBB-RSS hierarchy), identity pose."""
    model = fcl.BVHModel()
    model.beginModel(len(vertices), len(faces))
    model.addSubModel(vertices, faces)
    model.endModel()
    return fcl.CollisionObject(model, fcl.Transform())


# -- a demo room ---------------------------------------------------------------------


def _table(width: float, depth: float, height: float, leg: float = 0.3, top: float = 0.3) -> list:
    """A table's boxes (min, max corners) from the origin: a top on four legs."""
    boxes = [((0.0, 0.0, height - top), (width, depth, height))]
    for x in (0.0, width - leg):
        for y in (0.0, depth - leg):
            boxes.append(((x, y, 0.0), (x + leg, y + leg, height - top)))
    return boxes


def _shelf(width: float, depth: float, height: float, boards: int, side: float = 0.2, board: float = 0.15) -> list:
    """A shelf's boxes from the origin: two side panels, a back panel and ``boards`` boards, open at the front (+y)."""
    boxes = [
        ((0.0, 0.0, 0.0), (side, depth, height)),
        ((width - side, 0.0, 0.0), (width, depth, height)),
        ((side, 0.0, 0.0), (width - side, side, height)),
    ]
    for z in np.linspace(0.0, height - board, boards):
        boxes.append(((side, side, z), (width - side, depth, z + board)))
    return boxes


# Furniture of the room: name -> boxes from the origin (inside an 11 x 11 x 11 region).
FURNITURE: dict[str, list] = {
    "table": _table(4.2, 2.6, 3.4),
    "shelf": _shelf(3.4, 1.4, 7.3, boards=5),
    "cabinet": [((0.0, 0.0, 0.0), (1.7, 1.3, 2.6))],
    "lamp": [((0.85, 0.85, 0.0), (1.15, 1.15, 5.6)), ((0.3, 0.3, 5.6), (1.7, 1.7, 6.6))],
}
DEMO_LAYOUT = (  # (name, corner (x, y), quarter turns about z): shelves stand against walls, open to the room
    ("table", (3.3, 4.1), 0),
    ("shelf", (0.4, 9.4), 2),
    ("shelf", (9.4, 1.1), 1),
    ("cabinet", (7.4, 9.1), 0),
    ("lamp", (0.6, 0.7), 0),
)


def furniture_boxes(name: str, corner, turns: int = 0) -> np.ndarray:
    """``(B, 2, 3)`` the boxes of a piece of ``FURNITURE``, turned by ``turns`` quarter turns about z (anticlockwise),
    placed with its bounds' min corner at ``corner (x, y)``."""
    boxes = np.array(FURNITURE[name], dtype=float)  # (B, 2, 3)
    for _ in range(
        turns % 4
    ):  # a quarter turn: (x, y) -> (-y, x), so x spans [-y_max, -y_min] and y spans [x_min, x_max]
        boxes = np.stack(
            [
                np.stack([-boxes[:, 1, 1], boxes[:, 0, 0], boxes[:, 0, 2]], -1),
                np.stack([-boxes[:, 0, 1], boxes[:, 1, 0], boxes[:, 1, 2]], -1),
            ],
            axis=1,
        )
    boxes -= boxes[:, 0].min(axis=0) * np.array([1.0, 1.0, 0.0])
    return boxes + np.array([corner[0], corner[1], 0.0])


def mesh_of_boxes(boxes: np.ndarray) -> trimesh.Trimesh:
    """One mesh of closed boxes ``(K, 2, 3)`` (min / max corners), each box its own part (no boolean union)."""
    if len(boxes) == 0:
        return trimesh.Trimesh()
    parts = [trimesh.creation.box(bounds=box) for box in np.asarray(boxes, dtype=float)]
    return cast(trimesh.Trimesh, trimesh.util.concatenate(parts))  # typed Geometry; meshes join into a Trimesh


def room(rng: np.random.Generator | None = None) -> trimesh.Trimesh:
    """A room of ``ROOM_REGION`` with a table, two shelves, a cabinet and a lamp, as one mesh of boxes.

    Without ``rng``: the demo layout (``DEMO_LAYOUT``). With ``rng``: each piece at a random
    place on the floor, turned by a random number of quarter turns (pieces may overlap, as the paper's blocks do).
    """
    layout: Sequence[tuple[str, tuple[float, float] | np.ndarray, int]]
    if rng is None:
        layout = DEMO_LAYOUT
    else:
        layout = []
        for name, _, _ in DEMO_LAYOUT:
            turns = int(rng.integers(4))
            size = np.ptp(furniture_boxes(name, (0.0, 0.0), turns).reshape(-1, 3), axis=0)  # (3,)
            layout.append((name, rng.uniform(0.0, np.array(ROOM_REGION[:2]) - size[:2]), turns))
    return mesh_of_boxes(np.concatenate([furniture_boxes(name, corner, turns) for name, corner, turns in layout]))


def main(argv: list[str] | None = None) -> int:
    """Write the demo room to the path given (its suffix picks the format)."""
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m toolkit.geometry.meshes PATH  (e.g. tutorials/data/room.stl)", file=sys.stderr)
        return 2
    room().export(args[0])
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
