"""The python-fcl checkers: the reference for box worlds, and the checker for triangle meshes.

- :class:`FCLChecker`: obstacles in FCL's ``DynamicAABBTreeCollisionManager``; kinematics and
  the shared prefilter (:class:`~toolkit.geometry.box_world.PrefilteredChecker`) run batched in
  numpy, and only links whose bounds meet an obstacle's are handed to FCL, one call per link.
  It is the reference the tests hold every other checker to; for box worlds
  :func:`toolkit.geometry.collision.exact_checker` returns the compiled checker, which gives the
  same answers many times faster.
- :class:`MeshChecker`: the same against a triangle mesh (a
  :class:`~toolkit.geometry.workspace.MeshWorkspace`): FCL's ``BVHModel`` for links that touch
  the surface, winding numbers for links wholly inside a solid (:class:`toolkit.geometry.meshes.Solid`).
"""

from __future__ import annotations

import fcl
import numpy as np

from toolkit.geometry.box_world import PrefilteredChecker, refuse_mesh
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import MeshWorkspace, Workspace


class FCLChecker(PrefilteredChecker):
    """The reference exact checker, python-fcl: obstacles in a ``DynamicAABBTreeCollisionManager``.

    It is the ground truth the tests hold the other checkers to;
    :func:`toolkit.geometry.collision.exact_checker` returns the faster compiled checker
    (:class:`toolkit.geometry.compiled.CompiledChecker`) for box worlds.
    """

    def __init__(self, workspace: Workspace, robot: BoxRobot):
        refuse_mesh(workspace)
        super().__init__(workspace, robot)
        self._world = fcl.DynamicAABBTreeCollisionManager()
        self._world.registerObjects([_fcl_box(lo, hi) for lo, hi in workspace.boxes])
        self._world.setup()
        self._links = _fcl_links(robot)

    def _links_collide(self, Q, aabbs, candidates):
        if not candidates.any():
            return np.zeros(len(Q), dtype=bool)
        some = np.flatnonzero(candidates.any(axis=1))  # kinematics only where FCL will be asked
        hit = np.zeros(len(Q), dtype=bool)
        centers, rotations, _ = self.robot.link_boxes(Q[some])
        if self.robot.dim == 2:  # lift to 3D: obstacles become slabs z in [-1, 1]
            centers = np.concatenate([centers, np.zeros(centers.shape[:2] + (1,))], axis=-1)
            eye = np.broadcast_to(np.eye(3), rotations.shape[:2] + (3, 3)).copy()
            eye[..., :2, :2] = rotations
            rotations = eye
        request = fcl.CollisionRequest()
        for i, l in zip(*np.nonzero(candidates[some])):
            if hit[some[i]]:
                continue
            link = self._links[l]
            link.setTransform(fcl.Transform(rotations[i, l], centers[i, l]))
            data = fcl.CollisionData(request=request)
            self._world.collide(link, data, _first_contact)
            hit[some[i]] = data.result.is_collision
        return hit


class MeshChecker(PrefilteredChecker):
    """Ground truth against a triangle mesh: a :class:`~toolkit.geometry.workspace.MeshWorkspace`'s triangles.

    The prefilter and the clearance bounds use the bounds of the mesh's parts (they
    cover it, so both stay conservative). A link box that passes them is valid when it
    touches no triangle (FCL, box against the mesh's ``BVHModel``) and its centre lies
    outside every closed part (:meth:`toolkit.geometry.meshes.Solid.inside`): a box that touches no
    triangle lies wholly inside or wholly outside, and FCL alone would miss the first.
    """

    def __init__(self, workspace: MeshWorkspace, robot: BoxRobot):
        if not isinstance(workspace, MeshWorkspace):
            raise ValueError(
                "MeshChecker needs a MeshWorkspace (toolkit.geometry.workspace.from_mesh), "
                f"got {type(workspace).__name__}"
            )
        super().__init__(workspace, robot)
        self._solid = workspace.solid
        self._links = _fcl_links(robot)

    def _links_collide(self, Q, aabbs, candidates):
        hit = np.zeros(len(Q), dtype=bool)
        some = np.flatnonzero(candidates.any(axis=1))
        if not len(some):
            return hit
        centers, rotations, _ = self.robot.link_boxes(Q[some])  # (n, L, 3), (n, L, 3, 3)
        request = fcl.CollisionRequest()
        pairs = np.transpose(np.nonzero(candidates[some]))  # (P, 2): (configuration, link)
        clear = []  # candidate pairs whose link touches no triangle
        for p, (i, l) in enumerate(pairs):
            if hit[some[i]]:
                continue
            link = self._links[l]
            link.setTransform(fcl.Transform(rotations[i, l], centers[i, l]))
            if fcl.collide(link, self._solid.object, request, fcl.CollisionResult()):
                hit[some[i]] = True
            else:
                clear.append(p)
        i, l = pairs[clear].T if clear else (np.zeros(0, int), np.zeros(0, int))
        np.logical_or.at(hit, some[i], self._solid.inside(centers[i, l]))
        return hit


def _fcl_links(robot: BoxRobot) -> list:
    """One FCL box per link, posed later; a 2D robot's squares become unit-thick slabs (FCL is 3D)."""
    half3 = np.array([link.half_extents for link in robot.links], dtype=float)  # (L, 3)
    if robot.dim == 2:
        half3[:, 2] = 0.5
    return [fcl.CollisionObject(fcl.Box(*(2 * h))) for h in half3]


def _first_contact(o1, o2, data) -> bool:
    """Broadphase callback: test one candidate pair, and stop the search at the first contact.

    (FCL's default callback never sets ``done`` for a default request, so it would test
    every overlapping pair after a hit.)
    """
    if not data.done:
        data.done = fcl.collide(o1, o2, data.request, data.result) > 0
    return data.done


def _fcl_box(lo: np.ndarray, hi: np.ndarray) -> fcl.CollisionObject:
    lo3, hi3 = np.zeros(3) - 1.0, np.zeros(3) + 1.0  # 2D boxes: slabs z in [-1, 1]
    lo3[: len(lo)], hi3[: len(hi)] = lo, hi
    return fcl.CollisionObject(fcl.Box(*(hi3 - lo3)), fcl.Transform((lo3 + hi3) / 2))
