"""``toolkit.collision``: the checker interface and the exact checkers, kept at this name for code
written against it; the code is in :mod:`toolkit.geometry.collision`."""

from toolkit.geometry.collision import (
    CollisionChecker,
    CompiledChecker,
    ExactChecker,
    FCLChecker,
    MeshChecker,
    PointRobotChecker,
    SeparatingAxisChecker,
    exact_checker,
)

__all__ = [
    "CollisionChecker",
    "CompiledChecker",
    "ExactChecker",
    "FCLChecker",
    "MeshChecker",
    "PointRobotChecker",
    "SeparatingAxisChecker",
    "exact_checker",
]
