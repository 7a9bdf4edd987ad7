"""Forward kinematics of the box chain, compiled (numba): link frames from a configuration (§II-B, §IV-A).

The compiled checkers (:mod:`toolkit.geometry.kernels`, :mod:`toolkit.geometry.mesh_kernels`) pose a robot's
links as :meth:`toolkit.geometry.robots.BoxRobot.link_frames` does in numpy: the base frame from the
configuration's position and angles, then, joint by joint, a shift by the joint's origin and a turn about its
axis; each link box's centre sits at its offset in its frame. Two forms:

- :func:`link_frames`: one configuration (the clearance bounds and the mesh checker use it);
- :func:`block_frames`: a block of configurations at once, every step a loop over them that the compiler turns
  into vector instructions (8 numbers at once), the sines and cosines included
  (:func:`toolkit.geometry.trig.sin_cos`).

The robot arrives as arrays (:class:`toolkit.geometry.compiled.Robot`): ``base`` the kind's number
(:data:`toolkit.geometry.robots.BASE_KINDS`): :data:`POINT2D` for the 2D point, :data:`PLANAR` for a planar base
(x, y, yaw on the floor), :data:`FREE` for a free one (x, y, z, then Z-Y-X Euler angles).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from toolkit.geometry.robots import BASE_KINDS
from toolkit.geometry.trig import SIN_COS_LIMIT, any_sin_cos, sin_cos

POINT2D, PLANAR, FREE = (BASE_KINDS[kind] for kind in ("point2d", "planar", "free"))  # constants to numba


@njit(cache=True, inline="always")
def _turn(rotation, axis, s, c):
    """``rotation (3, 3) @ (rotation about world axis ``axis`` by the angle of sine ``s``, cosine ``c``)``, in place."""
    j, k = (axis + 1) % 3, (axis + 2) % 3  # the plane it turns, in right-handed order
    for row in range(3):
        a, b = rotation[row, j], rotation[row, k]
        rotation[row, j] = a * c + b * s
        rotation[row, k] = b * c - a * s


@njit(cache=True, inline="always")
def first_angle(robot):
    """The column of a configuration's first angle; the rest follow it (the base's, then the joints')."""
    return 3 if robot.base == FREE else 2


@njit(cache=True, inline="always")
def base_angles(robot):
    """How many angles the base has (the joints' follow them): free 3 (Z-Y-X), planar 1 (yaw), the 2D point 0."""
    return 3 if robot.base == FREE else (1 if robot.base == PLANAR else 0)


@njit(cache=True, inline="always")
def pose_base(q, robot, sines, cosines, position, rotation):
    """Fill the base frame ``position (3,)``, ``rotation (3, 3)`` for configuration ``q``, the sines and cosines of
    its angles given (``sines, cosines``: indexable from :func:`first_angle`'s column on, as ``q``)."""
    rotation[:] = 0.0
    for i in range(3):
        rotation[i, i] = 1.0
    if robot.base == POINT2D:
        position[0], position[1], position[2] = q[0], q[1], 0.0
    elif robot.base == PLANAR:  # x, y, yaw on the floor
        position[0], position[1], position[2] = q[0], q[1], robot.base_height
        _turn(rotation, 2, sines[0], cosines[0])
    else:  # free: x, y, z, then Z-Y-X Euler angles
        position[0], position[1], position[2] = q[0], q[1], q[2]
        _turn(rotation, 2, sines[0], cosines[0])
        _turn(rotation, 1, sines[1], cosines[1])
        _turn(rotation, 0, sines[2], cosines[2])


@njit(cache=True, inline="always")
def next_link(robot, link, sines, cosines, position, rotation, center):
    """Move the frame ``position, rotation`` from link ``link - 1``'s to link ``link``'s (none for link 0) and fill
    the link box's ``center (3,)``; ``sines, cosines`` as in :func:`pose_base`."""
    if link > 0:  # joint link - 1 carries this link
        joint = link - 1
        for i in range(3):
            for j in range(3):
                position[i] += rotation[i, j] * robot.joint_origins[joint, j]
        angle = base_angles(robot) + joint
        _turn(rotation, robot.joint_axes[joint], sines[angle], cosines[angle])
    for i in range(3):
        center[i] = position[i]
        for j in range(3):
            center[i] += rotation[i, j] * robot.link_offsets[link, j]


@njit(cache=True, inline="always")
def link_frames(q, robot, frame, centers, rotations, n_links):
    """Fill ``centers (L, 3)`` and ``rotations (L, 3, 3)`` (columns: the link's axes) of the first ``n_links`` links
    for configuration ``q`` (:meth:`toolkit.geometry.robots.BoxRobot.link_boxes`); ``frame (4, 3)``: the frame being
    posed (:func:`new_frame`): position, rotation, then the sines and cosines of ``q``'s angles."""
    position, rotation, sines, cosines = frame[0, :3], frame[1:4, :3], frame[4], frame[5]
    start = first_angle(robot)
    for m in range(len(q) - start):
        sines[m], cosines[m] = any_sin_cos(q[start + m])
    pose_base(q, robot, sines, cosines, position, rotation)
    for link in range(n_links):
        next_link(robot, link, sines, cosines, position, rotation, centers[link])
        rotations[link] = rotation


@njit(cache=True, inline="always")
def new_frame(dof):
    """Scratch for :func:`link_frames` for configurations of ``dof`` numbers."""
    return np.zeros((6, max(3, dof)))


@njit(cache=True, inline="always")
def _turn_block(rotations, source, target, axis, trig, at, block):
    """:func:`_turn` for a block: ``rotations[target] (3, 3, B)`` becomes ``rotations[source]`` (the last axis the
    configurations; ``target`` may be ``source``) turned about its axis ``axis`` by the angles whose sines and cosines
    are ``trig[1, at:at + block]``, ``trig[2, at:at + block]``: per row one loop over the block (vectorized)."""
    j, k = (axis + 1) % 3, (axis + 2) % 3
    for row in range(3):
        for n in range(block):
            a, b, s, c = rotations[source, row, j, n], rotations[source, row, k, n], trig[1, at + n], trig[2, at + n]
            rotations[target, row, j, n] = a * c + b * s
            rotations[target, row, k, n] = b * c - a * s
            rotations[target, row, axis, n] = rotations[source, row, axis, n]


@njit(cache=True, inline="always")
def block_frames(Q, first, block, robot, trig, position, centers, rotations):
    """:func:`link_frames` of the ``block`` configurations ``Q[first:first + block]`` at once, every loop over
    them, so that the compiler turns each into vector instructions: fills ``centers (L, 3, B)`` and
    ``rotations[:L]`` of ``rotations (L + 1, 3, 3, B)`` (``B``: ``block`` or more), whose last, and first for a
    base that does not turn, hold the identity, never written (nine loops a block fewer); ``trig (3, A * B)``
    (angles, sines, cosines), ``position (3, B)``: scratch. The angles lie packed, angle ``k`` of configuration
    ``n`` at ``k * block + n``, so that one loop of ``A * block`` steps takes every sine and cosine of the block,
    however short it is.

    A loop costs a few nanoseconds to enter whatever its length, and a planner's calls are short, so each link's
    frame is turned from the last link's straight into its own (no copy), a link's centre and the shift to the next
    joint are one loop, and the arrays are indexed whole rather than sliced into a view per loop."""
    start, count = first_angle(robot), (Q.shape[1] - first_angle(robot)) * block
    for k in range(Q.shape[1] - start):
        for n in range(block):
            trig[0, k * block + n] = Q[first + n, start + k]
    for t in range(count):
        trig[1, t], trig[2, t] = sin_cos(trig[0, t])
    for t in range(count):
        if abs(trig[0, t]) > SIN_COS_LIMIT:
            trig[1, t], trig[2, t] = any_sin_cos(trig[0, t])
    for n in range(block):
        position[0, n], position[1, n] = Q[first + n, 0], Q[first + n, 1]
    if robot.base == FREE:
        for n in range(block):
            position[2, n] = Q[first + n, 2]
    else:
        height = robot.base_height if robot.base == PLANAR else 0.0
        for n in range(block):
            position[2, n] = height
    identity = len(centers)  # rotations[identity]: the identity, and rotations[0] too where no angle turns the base
    if robot.base == PLANAR:  # yaw
        _turn_block(rotations, identity, 0, 2, trig, 0, block)
    elif robot.base == FREE:  # Z-Y-X Euler angles
        _turn_block(rotations, identity, 0, 2, trig, 0, block)
        _turn_block(rotations, 0, 0, 1, trig, block, block)
        _turn_block(rotations, 0, 0, 0, trig, 2 * block, block)
    origins, offsets, n_links = robot.joint_origins, robot.link_offsets, len(centers)
    for link in range(n_links):
        if link > 0:  # joint link - 1 carries this link
            joint = link - 1
            angle = base_angles(robot) + joint
            _turn_block(rotations, joint, link, robot.joint_axes[joint], trig, angle * block, block)
        f0, f1, f2 = offsets[link, 0], offsets[link, 1], offsets[link, 2]
        o0 = o1 = o2 = 0.0  # the origin of joint ``link`` (which carries the next link) in this link's frame
        if link + 1 < n_links:
            o0, o1, o2 = origins[link, 0], origins[link, 1], origins[link, 2]
        for i in range(3):  # the box's centre, then the frame moved to the next joint: one loop, not two
            for n in range(block):
                r0, r1, r2, p = (
                    rotations[link, i, 0, n],
                    rotations[link, i, 1, n],
                    rotations[link, i, 2, n],
                    position[i, n],
                )
                centers[link, i, n] = p + r0 * f0 + r1 * f1 + r2 * f2
                position[i, n] = p + (r0 * o0 + r1 * o1 + r2 * o2)
