"""Workspaces: axis-aligned box worlds and their occupancy grids (paper §IV-A).

A workspace is a rectangular region ``[lower, upper]`` holding ``K`` axis-aligned
obstacle boxes, stored as one array ``boxes`` of shape ``(K, 2, D)`` (min and max
corners). The paper's three families are generated from a seed:

- ``2ds``: a 31x31 region with 3-5 rectangular blocks of different shapes and sizes;
- ``3do``: a 41x41x6 office with 25-30 blocks of pre-defined furniture types;
- ``3dc``: an 11x11x11 clutter of 110-125 identical unit blocks.

Block corners lie on integer coordinates, so the occupancy grid (one point at the
centre of every unit cell, paper §IV-A: +1 occupied, -1 free) describes the
workspace exactly: nothing the CAE is asked to encode is lost by the grid.

Beyond the paper, :func:`from_mesh` makes a :class:`MeshWorkspace` from a triangle
mesh (a scanned or modelled scene): its grid marks the cells the mesh's solid meets,
and :func:`toolkit.geometry.collision.exact_checker` checks robots against the triangles
themselves (see :mod:`toolkit.geometry.meshes`).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import numpy as np

from toolkit.geometry import meshes
from toolkit.util import outputs

FREE, OCCUPIED = -1.0, 1.0


@dataclass(frozen=True, eq=False)
class Workspace:
    """A region ``[lower, upper]`` (``(D,)`` each) holding boxes ``(K, 2, D)``."""

    lower: np.ndarray  # (D,)
    upper: np.ndarray  # (D,)
    boxes: np.ndarray  # (K, 2, D) min / max corners
    family: str = ""
    labels: tuple[str, ...] = field(default=())  # optional name of each box's type

    def __post_init__(self):
        lower = _finite_array(self.lower, "lower", ndim=1)
        upper = _finite_array(self.upper, "upper", ndim=1)
        dim = lower.shape[0]
        if dim not in (2, 3) or upper.shape != lower.shape:
            raise ValueError(f"lower and upper must both have shape (2,) or (3,), got {lower.shape} and {upper.shape}")
        if np.any(upper <= lower):
            raise ValueError(f"upper {upper} must exceed lower {lower} in every axis")
        boxes = _finite_array(self.boxes, "boxes", ndim=None)
        if boxes.size == 0:
            boxes = boxes.reshape(0, 2, dim)
        if boxes.ndim != 3 or boxes.shape[1:] != (2, dim):
            raise ValueError(f"boxes must have shape (K, 2, {dim}), got {boxes.shape}")
        if np.any(boxes[:, 1] < boxes[:, 0]):
            raise ValueError("every box needs max corner >= min corner")
        if self.labels and len(self.labels) != len(boxes):
            raise ValueError(f"{len(self.labels)} labels for {len(boxes)} boxes")
        for name, value in (("lower", lower), ("upper", upper), ("boxes", boxes)):
            value.setflags(write=False)
            object.__setattr__(self, name, value)
        object.__setattr__(self, "labels", tuple(self.labels))

    @property
    def dim(self) -> int:
        return int(self.lower.shape[0])

    @property
    def grid_shape(self) -> tuple[int, ...]:
        """One grid point per unit cell: (31, 31), (41, 41, 6) or (11, 11, 11)."""
        return tuple(int(round(s)) for s in self.upper - self.lower)

    def _cell_centres(self) -> list[np.ndarray]:
        """Per axis, the centres of the unit cells along it, ``(n_d,)``."""
        return [self.lower[d] + 0.5 + np.arange(n) for d, n in enumerate(self.grid_shape)]

    def grid_points(self) -> np.ndarray:
        """Centres of the unit cells, shape ``grid_shape + (D,)``."""
        return np.stack(np.meshgrid(*self._cell_centres(), indexing="ij"), axis=-1)

    def occupancy(self) -> np.ndarray:
        """Occupancy grid, shape ``grid_shape``: +1 where a cell centre lies in a box, else -1."""
        grid = np.full(self.grid_shape, FREE, dtype=np.float32)
        # per axis, the cells whose centre lies in [lo, hi]: from the first centre >= lo to the last <= hi
        centres = self._cell_centres()
        first = [np.searchsorted(c, self.boxes[:, 0, d], side="left") for d, c in enumerate(centres)]  # D x (K,)
        stop = [np.searchsorted(c, self.boxes[:, 1, d], side="right") for d, c in enumerate(centres)]
        for box_first, box_stop in zip(np.transpose(first), np.transpose(stop)):  # (D,) each
            grid[tuple(map(slice, box_first, box_stop))] = OCCUPIED
        return grid

    def contains_points(self, points: np.ndarray) -> np.ndarray:
        """Whether each point ``(..., D)`` lies inside an obstacle (closed boxes)."""
        p = np.asarray(points, dtype=float)[..., None, :]  # (..., 1, D)
        return np.any(np.all((p >= self.boxes[:, 0]) & (p <= self.boxes[:, 1]), axis=-1), axis=-1)

    # -- equality and files ---------------------------------------------------
    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Workspace):
            return NotImplemented
        return (
            self.family == other.family
            and self.labels == other.labels
            and np.array_equal(self.lower, other.lower)
            and np.array_equal(self.upper, other.upper)
            and np.array_equal(self.boxes, other.boxes)
        )

    # A class that defines __eq__ without __hash__ gets __hash__ = None: arrays inside, so not hashable.

    def to_dict(self) -> dict:
        return {
            "family": self.family,
            "lower": self.lower.tolist(),
            "upper": self.upper.tolist(),
            "boxes": self.boxes.tolist(),
            "labels": list(self.labels),
        }

    @classmethod
    def from_dict(cls, data: dict) -> Workspace:
        """The workspace of :meth:`to_dict`'s data (a :class:`MeshWorkspace` when it holds a ``mesh``)."""
        missing = {"lower", "upper", "boxes"} - set(data)
        if missing:
            raise ValueError(f"workspace data is missing keys {sorted(missing)}")
        mesh = {"vertices": data["mesh"]["vertices"], "faces": data["mesh"]["faces"]} if "mesh" in data else {}
        return (MeshWorkspace if mesh else Workspace)(
            data["lower"],
            data["upper"],
            data["boxes"],
            family=data.get("family", ""),
            labels=tuple(data.get("labels", ())),
            **mesh,
        )

    def save(self, path: str | Path) -> None:
        """Write the workspace as JSON (atomically: a temporary file, then a rename)."""
        path = Path(path)
        text = json.dumps(self.to_dict())
        outputs.write_atomically(path, lambda tmp: tmp.write_text(text))

    @classmethod
    def load(cls, path: str | Path) -> Workspace:
        path = Path(path)
        try:
            data = json.loads(path.read_text())
        except (json.JSONDecodeError, UnicodeDecodeError) as err:
            raise ValueError(f"{path} is not a valid workspace file (corrupted or truncated JSON): {err}") from err
        if not isinstance(data, dict):
            raise ValueError(f"{path} is not a valid workspace file: expected a JSON object")
        return cls.from_dict(data)


@dataclass(frozen=True, eq=False)
class MeshWorkspace(Workspace):
    """A workspace whose obstacles are a triangle mesh: ``vertices (V, 3)``, ``faces (F, 3)`` (see :func:`from_mesh`).

    ``boxes`` are the bounds of the mesh's connected parts: they cover the obstacles
    (what a box-only consumer, such as the viewer, draws; the checker's prefilter and
    clearance bounds stay conservative with them), but the obstacles are the triangles.
    ``occupancy()`` marks the unit cells the mesh's solid meets (:meth:`toolkit.geometry.meshes.Solid.voxel_grid`).
    """

    # keyword-only, as they follow fields with defaults; faces are vertex indices, counter-clockwise seen from outside
    vertices: np.ndarray = field(kw_only=True)  # (V, 3)
    faces: np.ndarray = field(kw_only=True, default_factory=lambda: np.zeros((0, 3), dtype=np.int64))  # (F, 3)

    def __post_init__(self):
        super().__post_init__()
        if self.dim != 3:
            raise ValueError("a mesh workspace is 3D: lower and upper need shape (3,)")
        vertices = _finite_array(self.vertices, "vertices", ndim=2)
        faces = np.asarray(self.faces, dtype=np.int64).reshape(-1, 3)
        if vertices.size == 0:
            vertices = vertices.reshape(0, 3)
        if vertices.shape[1] != 3 or (len(faces) and (faces.min() < 0 or faces.max() >= len(vertices))):
            raise ValueError(
                f"need vertices (V, 3) and faces (F, 3) indexing them, got {vertices.shape} and {faces.shape}"
            )
        for name, value in (("vertices", vertices), ("faces", faces)):
            value.setflags(write=False)
            object.__setattr__(self, name, value)

    @property
    def mesh(self):
        """The obstacles as a ``trimesh.Trimesh``."""
        import trimesh

        return trimesh.Trimesh(self.vertices, self.faces, process=False)

    @cached_property
    def solid(self) -> meshes.Solid:
        """The mesh as obstacles: parts, fcl model, inside tests (built once)."""
        return meshes.Solid(self.vertices, self.faces)

    @cached_property
    def _grid(self) -> np.ndarray:
        grid = self.solid.voxel_grid(self.lower, self.upper)
        grid.setflags(write=False)
        return grid

    def occupancy(self) -> np.ndarray:
        """Occupancy grid, shape ``grid_shape``: +1 where the mesh's solid meets a cell's interior, else -1."""
        return self._grid.copy()

    def contains_points(self, points: np.ndarray) -> np.ndarray:
        """Whether each point ``(..., 3)`` lies inside the mesh's solid (winding number above one half)."""
        points = np.asarray(points, dtype=float)
        return self.solid.inside(points.reshape(-1, 3)).reshape(points.shape[:-1])

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, MeshWorkspace):
            return NotImplemented if not isinstance(other, Workspace) else False
        return (
            super().__eq__(other)
            and np.array_equal(self.vertices, other.vertices)
            and np.array_equal(self.faces, other.faces)
        )

    def to_dict(self) -> dict:
        return dict(super().to_dict(), mesh={"vertices": self.vertices.tolist(), "faces": self.faces.tolist()})


def from_mesh(mesh, *, lower, upper, family: str = "mesh") -> MeshWorkspace:
    """A :class:`MeshWorkspace` of the region ``[lower, upper]`` holding a mesh (a ``trimesh.Trimesh`` or a file path).

    The grid's cells are unit cubes from ``lower``, as in every scenario, so ``upper -
    lower`` must be whole numbers; to use a scenario's trained models, give the region
    of its workspaces (``lower`` at the origin, e.g. 11 x 11 x 11 for ``3dc7``) and scale
    your mesh into it first (``mesh.apply_scale``). A closed (watertight) mesh has an
    inside, which counts as obstacle; an open surface is an obstacle only where it is.
    """
    lower, upper = _finite_array(lower, "lower", ndim=1), _finite_array(upper, "upper", ndim=1)
    if lower.shape != (3,) or upper.shape != (3,):
        raise ValueError(
            f"a mesh workspace is 3D: lower and upper need shape (3,), got {lower.shape} and {upper.shape}"
        )
    if not np.allclose(upper - lower, np.round(upper - lower)):
        raise ValueError(f"the region's sides {upper - lower} must be whole numbers of unit cells")
    mesh = meshes.load(mesh)
    solid = meshes.Solid(mesh.vertices, mesh.faces)
    return MeshWorkspace(lower, upper, solid.bounds, family=family, vertices=solid.vertices, faces=solid.faces)


def _finite_array(value, name: str, ndim: int | None) -> np.ndarray:
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError) as err:  # strings, ragged nesting, None
        raise ValueError(f"{name} must be an array of numbers: {err}") from err
    if ndim is not None and array.ndim != ndim:
        raise ValueError(f"{name} must be a {ndim}-D array, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} contains NaN or infinite values")
    return array


# -- generators -----------------------------------------------------------------


def _place(rng: np.random.Generator, size: np.ndarray, region: np.ndarray, on_floor: bool = False) -> np.ndarray:
    """A box of integer ``size`` (D,) at a random integer position inside ``region`` (D,)."""
    corner = np.array([rng.integers(0, int(r - s) + 1) for r, s in zip(region, size)], dtype=float)
    if on_floor:
        corner[-1] = 0.0
    return np.stack([corner, corner + size])


def simple_2d(rng: np.random.Generator) -> Workspace:
    """2DS: 31x31 region, 3-5 rectangular blocks, sides 2-9 (paper §IV-A), placed independently: they may overlap."""
    region = np.array([31.0, 31.0])
    count = int(rng.integers(3, 6))
    boxes = [_place(rng, rng.integers(2, 10, size=2).astype(float), region) for _ in range(count)]
    return Workspace(np.zeros(2), region, np.array(boxes), family="2ds")


# Pre-defined office furniture (size x, y, z), placed on the floor; walls also rotated by 90 degrees.
OFFICE_TYPES: dict[str, tuple[float, float, float]] = {
    "desk": (3.0, 2.0, 1.0),
    "table": (4.0, 2.0, 1.0),
    "shelf": (1.0, 4.0, 3.0),
    "cabinet": (1.0, 1.0, 2.0),
    "chair": (1.0, 1.0, 1.0),
    "wall": (8.0, 1.0, 4.0),
}


def office_3d(rng: np.random.Generator) -> Workspace:
    """3DO: 41x41x6 office, 25-30 blocks whose type and place are random (paper §IV-A), placed independently: they
    may overlap."""
    region = np.array([41.0, 41.0, 6.0])
    names = list(OFFICE_TYPES)
    count = int(rng.integers(25, 31))
    boxes, labels = [], []
    for _ in range(count):
        name = names[int(rng.integers(len(names)))]
        size = np.array(OFFICE_TYPES[name])
        if rng.random() < 0.5:  # turn the block by 90 degrees about z
            size[[0, 1]] = size[[1, 0]]
        boxes.append(_place(rng, size, region, on_floor=True))
        labels.append(name)
    return Workspace(np.zeros(3), region, np.array(boxes), family="3do", labels=tuple(labels))


def clutter_3d(rng: np.random.Generator) -> Workspace:
    """3DC: 11x11x11 clutter, 110-125 identical unit blocks (paper §IV-A), each in a cell of its own: they never
    overlap."""
    region = np.array([11.0, 11.0, 11.0])
    count = int(rng.integers(110, 126))
    cells = rng.choice(11**3, size=count, replace=False)  # distinct cells: every block counts
    corners = np.stack(np.unravel_index(cells, (11, 11, 11)), axis=-1).astype(float)  # (K, 3)
    return Workspace(np.zeros(3), region, np.stack([corners, corners + 1.0], axis=1), family="3dc")


GENERATORS = {"2ds": simple_2d, "3do": office_3d, "3dc": clutter_3d}


def generate(family: str, rng: np.random.Generator) -> Workspace:
    """A workspace of ``family`` ('2ds', '3do' or '3dc') drawn with ``rng``."""
    if family not in GENERATORS:
        raise ValueError(f"unknown workspace family {family!r}; choose one of {sorted(GENERATORS)}")
    return GENERATORS[family](rng)
