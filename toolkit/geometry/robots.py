"""The paper's four robots as serial chains of boxes, with vectorized kinematics (paper §IV-A).

Every robot is a :class:`BoxRobot`: a moving base followed by revolute joints, each
link a box. Forward kinematics maps configurations ``Q (N, dof)`` to oriented link
boxes in one pass of numpy over the whole batch (a Python loop over the few joints,
never over ``N``):

- ``point2d``: the 2D point robot, a 0.5x0.5 square, DoF {x, y};
- ``youbot``: a youBot-like mobile manipulator, DoF {x, y, yaw} of the base and 5
  arm joints (8 DoF; 1.5x1x1 overall with the arm upright, the paper's size);
- ``chain7``: box chain, DoF {x, y, z, alpha, beta, gamma} and 1 joint, a small
  0.1^3 link and a big 0.4x0.1x0.1 link;
- ``chain9``: box chain, 6 base DoF and 3 joints, small-big-small-big links.

Angles of the base (yaw, Euler angles) wrap around; arm joints have limits and do
not. Self-collision is not modelled (nor is it in the paper).

A robot of your own is a :class:`BoxRobot` as well: pick a base kind, list the link
boxes and the joints between them, and bound the base position inside the workspace
region; :func:`toolkit.scenarios.register` then makes it a scenario that trains,
plans and loads checkpoints by name (``tutorials/add_a_robot.ipynb``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class Link:
    """A box rigidly attached to a link frame: centre ``offset`` (3,), ``half_extents`` (3,)."""

    half_extents: tuple[float, ...]
    offset: tuple[float, ...] = (0.0, 0.0, 0.0)


@dataclass(frozen=True)
class Joint:
    """A revolute joint at ``origin`` in its parent link's frame, turning the next link about ``axis``."""

    origin: tuple[float, float, float]
    axis: str
    limits: tuple[float, float]


# The base's degrees of freedom, by kind: names and whether each one is an angle.
BASES = {
    "point2d": (("x", "y"), (False, False)),
    "planar": (("x", "y", "yaw"), (False, False, True)),
    "free": (("x", "y", "z", "alpha", "beta", "gamma"), (False, False, False, True, True, True)),
}
BASE_KINDS = {kind: number for number, kind in enumerate(BASES)}  # each kind's number in the compiled kernels


class BoxRobot:
    """A base plus a serial chain of revolute joints, every link a box.

    ``base`` is ``"point2d"`` (2D translation; its joints, if any, turn about z, in
    the plane), ``"planar"`` (x, y, yaw on the floor at height ``base_height``) or
    ``"free"`` (x, y, z and Z-Y-X Euler angles). ``position_bounds`` is ``(lower,
    upper)`` of the base position, ``(D,)`` each. Configurations are ordered base
    positions, base angles, joints (``dof_names``).
    """

    def __init__(
        self,
        name: str,
        base: str,
        links: list[Link],
        joints: list[Joint],
        *,
        position_bounds: tuple,
        base_height: float = 0.0,
    ):
        if base not in BASES:
            raise ValueError(f"unknown base kind {base!r}; choose one of {sorted(BASES)}")
        if len(joints) != len(links) - 1:
            raise ValueError("a serial chain has one joint fewer than links")
        if base == "point2d" and any(joint.axis != "z" for joint in joints):
            raise ValueError("a 2D robot's joints turn about z: any other axis would lift its links out of the plane")
        if any(not joint.limits[0] < joint.limits[1] for joint in joints):
            raise ValueError(
                f"every joint needs limits (lower, upper) with lower < upper, got {[j.limits for j in joints]}"
            )
        self.name, self.base, self.base_height = name, base, float(base_height)
        self.links, self.joints = tuple(links), tuple(joints)
        self.dim = 2 if base == "point2d" else 3
        base_names, base_angular = BASES[base]
        self.dof_names = base_names + tuple(f"joint{i + 1}" for i in range(len(joints)))
        self.dof = len(self.dof_names)
        pos_lo, pos_hi = (np.asarray(b, dtype=float) for b in position_bounds)
        n_rot = sum(base_angular)  # base angles follow the base positions
        self.lower = np.concatenate(
            [pos_lo[: len(base_names) - n_rot], np.full(n_rot, -np.pi), [j.limits[0] for j in joints]]
        )
        self.upper = np.concatenate(
            [pos_hi[: len(base_names) - n_rot], np.full(n_rot, np.pi), [j.limits[1] for j in joints]]
        )
        self.wraps = np.array(base_angular + (False,) * len(joints))  # (dof,) angles that wrap around
        n_pos = len(base_names) - n_rot
        self.n_positions = n_pos  # configurations are [base positions, base angles (wrap), joints (limited)]
        self._angles = slice(n_pos, n_pos + n_rot)  # the columns where wraps is True: base angles follow the positions
        self.half_extents = np.array([l.half_extents[: self.dim] for l in links], dtype=float)  # (L, D)
        self._offsets = np.array([l.offset for l in links], dtype=float)  # (L, 3)
        self.motion_weights = self._motion_weights()  # (dof,)
        # links whose height never changes: on a planar base, the base and the links after it turned about vertical axes
        self.level_links = (
            1 + next((i for i, j in enumerate(joints) if j.axis != "z"), len(joints)) if base == "planar" else 0
        )
        for array in (self.lower, self.upper, self.wraps, self.half_extents, self.motion_weights):
            array.setflags(write=False)

    def __repr__(self) -> str:
        return f"BoxRobot({self.name!r}, dof={self.dof}, links={len(self.links)})"

    @property
    def n_links(self) -> int:
        return len(self.links)

    # -- configurations ---------------------------------------------------------
    def check_configs(self, Q, name: str = "Q") -> np.ndarray:
        """``Q`` as a float array ``(N, dof)``; a clear error for a wrong shape or NaN/inf."""
        Q = self._finite_configs(Q, name)
        return Q[None] if Q.ndim == 1 else Q

    def _finite_configs(self, Q, name: str, max_ndim: int | None = 2) -> np.ndarray:
        """``Q`` as a float array ``(dof,)`` or ``(N, dof)`` (any leading axes if ``max_ndim`` is None);
        a clear error for a wrong shape or NaN/inf."""
        Q = np.asarray(Q, dtype=float)
        if Q.ndim < 1 or Q.ndim > (max_ndim or Q.ndim) or Q.shape[-1] != self.dof:
            shape = f"(N, {self.dof}) or ({self.dof},)" if max_ndim else f"(..., {self.dof})"
            raise ValueError(f"{name} must have shape {shape} for robot {self.name!r}, got {Q.shape}")
        if not np.all(np.isfinite(Q)):
            raise ValueError(f"{name} contains NaN or infinite values")
        return Q

    def in_bounds(self, Q: np.ndarray) -> np.ndarray:
        """(N,) whether each configuration lies within ``[lower, upper]``."""
        return np.all((self.lower <= Q) & (self.upper >= Q), axis=1)

    def sample(self, rng: np.random.Generator, n: int) -> np.ndarray:
        """``(n, dof)`` configurations drawn uniformly from the bounds."""
        return rng.uniform(self.lower, self.upper, size=(int(n), self.dof))

    def difference(self, Q0, Q1) -> np.ndarray:
        """``Q1 - Q0`` with angles taken the short way round, ``(N, dof)`` (leading axes broadcast)."""
        delta = self._finite_configs(Q1, "Q1", max_ndim=None) - self._finite_configs(Q0, "Q0", max_ndim=None)
        return self.wrap(delta)

    def wrap(self, Q: np.ndarray) -> np.ndarray:
        """``Q (..., dof)``, a float array, with its angles mapped to [-pi, pi) in place; returns it."""
        angles = Q[..., self._angles]  # a view
        angles[...] = np.mod(angles + np.pi, 2 * np.pi) - np.pi  # on a contiguous copy: twice as fast as in the view
        return Q

    def distance(self, Q0, Q1) -> np.ndarray:
        """Euclidean distance in configuration space, respecting angle wrap-around, ``(N,)``."""
        return np.linalg.norm(self.difference(Q0, Q1), axis=-1)

    def interpolate(self, q0, q1, t) -> np.ndarray:
        """``(T, dof)`` configurations at fractions ``t`` (T,) of the straight segment q0 -> q1."""
        q0 = self._finite_configs(q0, "q0")
        t = np.asarray(t, dtype=float).reshape(-1, 1)  # (T, 1)
        if not np.all(np.isfinite(t)):
            raise ValueError("t contains NaN or infinite values")
        return self.wrap(q0 + t * self.difference(q0, q1))

    def motion_bound(self, Q0, Q1) -> np.ndarray:
        """Upper bound on how far any point of the robot moves along each segment, ``(N,)``.

        Each DoF contributes ``weight * |dq|``: 1 for translations, and for a rotation
        the largest distance from its axis to any point of the links it turns.
        """
        return np.abs(self.difference(Q0, Q1)) @ self.motion_weights

    def _motion_weights(self) -> np.ndarray:
        # reach[i]: largest distance from link i's frame origin to any point of links i, i+1, ...
        reach = np.zeros(self.n_links)
        for i in reversed(range(self.n_links)):
            own = np.linalg.norm(self._offsets[i]) + np.linalg.norm(self.links[i].half_extents)
            further = np.linalg.norm(self.joints[i].origin) + reach[i + 1] if i + 1 < self.n_links else 0.0
            reach[i] = max(own, further)
        n_base = len(BASES[self.base][0])
        weights = np.where(self.wraps[:n_base], reach[0], 1.0)
        return np.concatenate([weights, reach[1:]])

    # -- kinematics ---------------------------------------------------------------
    def link_frames(self, Q) -> tuple[np.ndarray, np.ndarray]:
        """Frames of all links: positions ``(N, L, 3)`` and rotations ``(N, L, 3, 3)`` (3D always)."""
        Q = self.check_configs(Q)
        n = len(Q)
        position = np.zeros((n, 3))
        if self.base == "point2d":
            position[:, :2] = Q[:, :2]
            rotation = np.broadcast_to(np.eye(3), (n, 3, 3)).copy()
            first_joint = 2
        elif self.base == "planar":
            position[:, :2], position[:, 2] = Q[:, :2], self.base_height
            rotation = _rotation("z", Q[:, 2])
            first_joint = 3
        else:
            position[:] = Q[:, :3]
            rotation = _rotation("z", Q[:, 3]) @ _rotation("y", Q[:, 4]) @ _rotation("x", Q[:, 5])
            first_joint = 6
        positions, rotations = [position], [rotation]
        for j, joint in enumerate(self.joints):
            position = position + rotation @ np.asarray(joint.origin)  # (N, 3)
            rotation = rotation @ _rotation(joint.axis, Q[:, first_joint + j])  # (N, 3, 3)
            positions.append(position)
            rotations.append(rotation)
        return np.stack(positions, axis=1), np.stack(rotations, axis=1)

    def link_boxes(self, Q) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Oriented link boxes: centres ``(N, L, D)``, rotations ``(N, L, D, D)``, half extents ``(L, D)``."""
        positions, rotations = self.link_frames(Q)
        centers = positions + np.einsum("nlij,lj->nli", rotations, self._offsets)  # (N, L, 3)
        d = self.dim
        return centers[..., :d], rotations[..., :d, :d], self.half_extents

    def link_aabbs(self, Q) -> np.ndarray:
        """Axis-aligned bounds of every link box, ``(N, L, 2, D)`` (min and max corners)."""
        centers, rotations, half = self.link_boxes(Q)
        reach = np.einsum("nlij,lj->nli", np.abs(rotations), half)  # (N, L, D)
        return np.stack([centers - reach, centers + reach], axis=2)


def _rotation(axis: str, angle: np.ndarray) -> np.ndarray:
    """Rotations about a coordinate axis, ``(N, 3, 3)``."""
    c, s = np.cos(angle), np.sin(angle)
    i = AXES[axis]
    j, k = (i + 1) % 3, (i + 2) % 3  # the plane it turns, in right-handed order
    R = np.zeros(np.shape(angle) + (3, 3))
    R[..., i, i] = 1.0
    R[..., j, j], R[..., j, k] = c, -s
    R[..., k, j], R[..., k, k] = s, c
    return R


# -- the paper's robots ------------------------------------------------------------
SMALL = Link(half_extents=(0.05, 0.05, 0.05), offset=(0.05, 0.0, 0.0))  # 0.1^3, starting at its joint
BIG = Link(half_extents=(0.2, 0.05, 0.05), offset=(0.2, 0.0, 0.0))  # 0.4x0.1x0.1 along its x axis
CHAIN_JOINT_LIMITS = (-2.0, 2.0)


def point_robot(region=(31.0, 31.0)) -> BoxRobot:
    """2D point robot: a 0.5x0.5 square whose centre stays inside the region."""
    region = np.asarray(region, dtype=float)
    return BoxRobot(
        "point2d",
        "point2d",
        [Link(half_extents=(0.25, 0.25, 0.0))],
        [],
        position_bounds=(np.full(2, 0.25), region - 0.25),
    )


def youbot(region=(41.0, 41.0, 6.0)) -> BoxRobot:
    """youBot-like mobile manipulator: base (x, y, yaw) and 5 arm joints (yaw, 3 pitches, roll).

    Joint limits follow the KUKA youBot arm's; the arm stands upright at zero.
    """
    deg = np.pi / 180
    links = [
        Link((0.75, 0.5, 0.1), (0.0, 0.0, 0.12)),  # base platform, 1.5 x 1.0 x 0.2, 2 cm above the floor
        Link((0.07, 0.07, 0.06), (0.0, 0.0, 0.06)),  # turret
        Link((0.04, 0.04, 0.13), (0.0, 0.0, 0.13)),  # upper arm
        Link((0.035, 0.035, 0.11), (0.0, 0.0, 0.11)),  # forearm
        Link((0.03, 0.03, 0.045), (0.0, 0.0, 0.045)),  # wrist
        Link((0.04, 0.08, 0.045), (0.0, 0.0, 0.045)),  # gripper, its top 1.0 above the floor
    ]
    joints = [
        Joint((0.45, 0.0, 0.22), "z", (-169 * deg, 169 * deg)),
        Joint((0.0, 0.0, 0.12), "y", (-65 * deg, 90 * deg)),
        Joint((0.0, 0.0, 0.26), "y", (-150 * deg, 146 * deg)),
        Joint((0.0, 0.0, 0.22), "y", (-102 * deg, 102 * deg)),
        Joint((0.0, 0.0, 0.09), "z", (-167 * deg, 167 * deg)),
    ]
    region = np.asarray(region, dtype=float)
    return BoxRobot("youbot", "planar", links, joints, position_bounds=(np.zeros(3), region))


def box_chain(n_joints: int, region=(11.0, 11.0, 11.0)) -> BoxRobot:
    """Box chain with 6 base DoF: 1 joint (small, big links; 7 DoF) or 3 joints (small, big, small, big; 9 DoF)."""
    if n_joints == 1:
        links, axes = [SMALL, BIG], ["z"]
    elif n_joints == 3:
        links, axes = [SMALL, BIG, SMALL, BIG], ["z", "y", "z"]
    else:
        raise ValueError(f"the paper's box chains have 1 or 3 joints, not {n_joints}")
    joints = [Joint((2 * link.half_extents[0], 0.0, 0.0), axis, CHAIN_JOINT_LIMITS) for link, axis in zip(links, axes)]
    region = np.asarray(region, dtype=float)
    return BoxRobot(f"chain{6 + n_joints}", "free", links, joints, position_bounds=(np.zeros(3), region))
