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

:func:`exact_checker` picks the fastest for a workspace and robot from one table, :data:`EXACT_CHECKERS`:
rows of (workspace kind, which robots, checker). A workspace kind of your own gets its checker by a row inserted
before the toolkit's (``EXACT_CHECKERS.insert(0, (MyWorkspace, any_robot, MyChecker))``).
"""

from __future__ import annotations

from collections.abc import Callable

from toolkit.geometry.box_world import (
    BoxWorldChecker,
    PointRobotChecker,
    PrefilteredChecker,
    SeparatingAxisChecker,
    is_point_robot,
)
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
    "PrefilteredChecker",
    "SeparatingAxisChecker",
    "exact_checker",
]

CheckerClass = Callable[..., CollisionChecker]  # (workspace, robot) -> a checker: its class, or a function


def any_robot(robot: BoxRobot) -> bool:
    """A row of :data:`EXACT_CHECKERS` for every robot."""
    return True


# The fastest exact checker, by kind of workspace and robot: the first row whose kind the workspace is and whose
# test the robot passes. Tried in order, so a narrower row comes before a wider one.
EXACT_CHECKERS: list[tuple[type[Workspace], Callable[[BoxRobot], bool], CheckerClass]] = [
    (MeshWorkspace, any_robot, CompiledMeshChecker),  # triangle-box separating axes and inside tests, compiled
    (Workspace, is_point_robot, PointRobotChecker),  # a lone 2D square: interval tests in numpy beat a compiled call
    (Workspace, any_robot, CompiledChecker),  # boxes: kinematics and separating axes, compiled
]


def exact_checker(workspace: Workspace, robot: BoxRobot) -> CollisionChecker:
    """The fastest exact checker for this workspace and robot: the first fitting row of :data:`EXACT_CHECKERS`."""
    for kind, fits, checker in EXACT_CHECKERS:
        if isinstance(workspace, kind) and fits(robot):
            return checker(workspace, robot)
    raise ValueError(f"no exact checker for a {type(workspace).__name__} and robot {robot.name!r}")
