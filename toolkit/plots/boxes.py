"""Drawing a box: its corners, its faces in 3D and its shadow on a coordinate plane (paper §IV-A).

Every body of the toolkit is a box: a workspace's blocks are axis-aligned boxes
``[lo, hi]`` and a robot's links are oriented boxes (a centre, a rotation and half
extents, ``robot.link_boxes``). A box is drawn from its ``2^D`` corners: in 3D as its
six faces (:func:`add_box_3d`), on a plane as the convex hull of its projected
corners (:func:`outline`), which is the box's shadow on that plane.

Corner ``k`` of a box has bit ``D-1-a`` of ``k`` set where it lies on the + side of axis
``a`` (:func:`corner_signs`); :data:`FACES` lists the corners of each face of a 3D box
in that numbering.
"""

from __future__ import annotations

import itertools

import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from scipy.spatial import ConvexHull


def corner_signs(dim: int) -> np.ndarray:
    """``(2^D, D)`` the corners of a box as ±1 per axis; corner ``k`` has bit ``D-1-a`` set where axis ``a`` is +."""
    return np.array(list(itertools.product((-1.0, 1.0), repeat=dim)))


def _face_indices() -> np.ndarray:
    """``(6, 4)`` corners of each face of a 3D box (numbered as :func:`corner_signs`), in order around it."""
    faces = []
    for axis, side in itertools.product(range(3), (0, 1)):
        u, v = (a for a in range(3) if a != axis)
        face = []
        for bit_u, bit_v in ((0, 0), (0, 1), (1, 1), (1, 0)):
            bits = np.zeros(3, dtype=int)
            bits[[axis, u, v]] = side, bit_u, bit_v
            face.append(int(bits @ (4, 2, 1)))
        faces.append(face)
    return np.array(faces)


FACES = _face_indices()  # (6, 4)


def box_corners(center: np.ndarray, rotation: np.ndarray, half: np.ndarray) -> np.ndarray:
    """``(2^D, D)`` corners of an oriented box: ``center (D,)``, ``rotation (D, D)``, ``half (D,)``."""
    return center + (corner_signs(len(center)) * half) @ rotation.T


def aabb_corners(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """``(2^D, D)`` corners of an axis-aligned box."""
    return box_corners((lo + hi) / 2, np.eye(len(lo)), (hi - lo) / 2)


def outline(corners: np.ndarray, axes: tuple[int, int]) -> np.ndarray:
    """The box's shadow on the plane of ``axes``: its projected corners' convex hull, ``(V, 2)`` in order."""
    points = corners[:, list(axes)]
    return points[ConvexHull(points).vertices]


def add_box_3d(ax, corners: np.ndarray, **style) -> Poly3DCollection:
    """Draw a 3D box from its ``corners (8, 3)`` on an mplot3d axes as its six faces; returns the faces."""
    faces = Poly3DCollection(corners[FACES], **style)
    ax.add_collection3d(faces)
    return faces
