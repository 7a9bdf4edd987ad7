"""Collision checking: one interface, exact implementations (paper §II-B's "black box").

Every checker answers ``are_valid(Q (N, dof)) -> (N,) bool`` (:class:`CollisionChecker`,
in :mod:`toolkit.geometry.checker`). A configuration is valid when it lies within the
robot's bounds, every link lies inside the workspace region, and no link box touches an
obstacle (closed sets: touching counts as collision, as in FCL). The exact checkers:

- :class:`CompiledChecker` (:mod:`toolkit.geometry.compiled`, :mod:`toolkit.geometry.kernels`):
  kinematics and separating axes compiled with numba, one loop over configurations; the
  default for box worlds.
- :class:`CompiledMeshChecker` (:mod:`toolkit.geometry.compiled_mesh`, :mod:`toolkit.geometry.mesh_kernels`):
  triangle-box separating axes and inside tests compiled with numba; the default for mesh workspaces.
- :class:`FCLChecker` (:mod:`toolkit.geometry.fcl_checker`):
  python-fcl, the reference the tests hold the others to. :class:`MeshChecker`: python-fcl
  against a triangle mesh and numpy winding numbers, the mesh reference.
- :class:`PointRobotChecker` and :class:`SeparatingAxisChecker` (:mod:`toolkit.geometry.box_world`):
  interval tests for the 2D point robot, and the separating-axis reference, in numpy.

:func:`exact_checker` picks the fastest for a workspace and robot.
"""

from __future__ import annotations

from toolkit.geometry.box_world import BoxWorldChecker, PointRobotChecker, SeparatingAxisChecker
from toolkit.geometry.checker import CollisionChecker
from toolkit.geometry.compiled import CompiledChecker
from toolkit.geometry.compiled_mesh import CompiledMeshChecker
from toolkit.geometry.fcl_checker import FCLChecker, MeshChecker
from toolkit.geometry.robots import BoxRobot
from toolkit.geometry.workspace import MeshWorkspace, Workspace

__all__ = [
    "BoxWorldChecker",
    "CollisionChecker",
    "CompiledChecker",
    "CompiledMeshChecker",
    "FCLChecker",
    "MeshChecker",
    "PointRobotChecker",
    "SeparatingAxisChecker",
    "exact_checker",
]


def exact_checker(workspace: Workspace, robot: BoxRobot) -> CollisionChecker:
    """The fastest exact checker for this workspace and robot: the compiled mesh checker against the triangles of a
    mesh workspace; otherwise interval tests in numpy for the lone 2D square (the point robot), the compiled checker
    for the rest."""
    if isinstance(workspace, MeshWorkspace):
        return CompiledMeshChecker(workspace, robot)
    if robot.base == "point2d" and robot.dof == 2:
        return PointRobotChecker(workspace, robot)
    return CompiledChecker(workspace, robot)
