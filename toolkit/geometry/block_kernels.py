"""The compiled exact check of a box world, a block of configurations at a time (numba).

Numpy checks a batch one step at a time: kinematics for every configuration, then bounds for
every link, then the pairs that may touch. Each step writes arrays the next one reads, so
the cost is memory traffic, and FCL adds a Python call per pair. Here one loop (compiled by
numba to machine code) takes a block of 128 configurations through every step:

1. forward kinematics of the box chain (:meth:`toolkit.geometry.robots.BoxRobot.link_frames`) for the whole
   block (:func:`toolkit.geometry.frame_kernels.block_frames`), each step a loop over its configurations that the
   compiler turns into vector instructions, the sines and cosines included (:mod:`toolkit.geometry.trig`);
2. then, still a loop over the block's configurations per step (:func:`_block_needs`): bounds,
   ``lower <= q <= upper``; and per link one bit, looked up in the cell of a fine grid that holds the link's centre
   (:class:`toolkit.geometry.compiled.Far`): whether a ball round the link, centred anywhere in that cell, lies in
   the region and misses every obstacle. Most links are done here (the idea of the mesh checker,
   :mod:`toolkit.geometry.mesh_kernels`); the rest are marked, one bit a link, with the broadphase cell of their
   centre;
3. then each configuration alone, its marked links in order, stopping at the first that touches
   (:func:`_link_touches`): its axis-aligned bounds must lie inside the region, and the obstacle boxes listed in
   its cell (:class:`toolkit.geometry.box_world.BoxGrid`'s cell lists, the boxes grown by the largest link ball's
   radius: all a link centred there can touch) are tested: a ball round the link that misses the box, or one
   inside the link that meets it, settles most pairs; the rest go to the separating axes
   (:func:`toolkit.geometry.kernels.boxes_touch`).

A loop that the compiler turns into vector instructions cannot stop early, so steps 1 and 2 do the work of
every configuration of the block; step 3, where a configuration's answer can come at its first link, is the
only loop that branches. It reads the block's arrays in place, numbers only, never a view of them (in a loop
this hot a view costs more than the tests).

The robot and the workspace arrive as arrays, in one object (:class:`Arrays`, from the arrays
:class:`toolkit.geometry.compiled.CompiledChecker` builds), never as constants, so one compiled version serves
every robot and workspace; ``cache=True`` keeps it on disk (see :mod:`toolkit.geometry.kernels`). numba dates that
copy by this file alone: a change to what the loop inlines from another module (:mod:`~toolkit.geometry.frame_kernels`,
:mod:`~toolkit.geometry.kernels`, :mod:`~toolkit.geometry.trig`) needs a change here too, or a cached copy runs the
old code.
"""

from __future__ import annotations

import numpy as np
from numba import njit, types
from numba.core import cgutils
from numba.core.datamodel import models
from numba.experimental import structref
from numba.extending import intrinsic, register_model

from toolkit.geometry.frame_kernels import block_frames, first_angle
from toolkit.geometry.kernels import boxes_touch

BLOCK = 128  # configurations posed together (64 and 512 measured slower, 256 no faster)


@structref.register
class ArraysType(types.StructRef):
    """numba's type of :class:`Arrays`."""


class Arrays(structref.StructRefProxy):
    """What :func:`validity` reads besides the configurations, in one object (made by :func:`arrays`): the robot
    (:class:`toolkit.geometry.compiled.Robot`), the world (:class:`~toolkit.geometry.compiled.World`), numbers
    derived from them once rather than at every call (``walls (6,)``, ``corner (3,)``, ``balls (2, L)``, as
    :func:`_link_touches` reads them), and the loop's scratch for a block: ``trig (3, A * BLOCK)`` (angles, sines,
    cosines), ``position (3, BLOCK)``, ``centers (L, 3, BLOCK)``, ``rotations (L + 1, 3, 3, BLOCK)`` as
    :func:`~toolkit.geometry.frame_kernels.block_frames` fills them, ``cells (L + 2, BLOCK)`` as :func:`_block_needs`
    fills them, ``box (27,)`` as :func:`_link_touches` uses it. Those fields hold views that count no references
    (:func:`_borrowed`), to be read by the loop only; ``owners`` holds the arrays themselves, alive as long as this.

    It is about a call's fixed cost, which a planner's calls of tens of configurations pay again and again: numba
    unpacks every argument of a call, about 35 ns an array, and a robot and a world are 17 arrays in named tuples
    (0.6 us, as long as checking 8 configurations); this object is one pointer (0.09 us: numba looks it up by
    attribute name and counts a reference), and its address, an integer, with its type (:func:`validity_at`) a few
    nanoseconds. Allocating the scratch anew cost a call of 16 configurations about 0.15 us more. A checker's
    scratch is its own, and no two calls use it at once: the loop holds Python's interpreter lock (numba's ``nogil``
    is off). Made by one function from arrays laid out alike, it always has the same numba type: one compiled version
    serves all."""


FIELDS = ["owners", "robot", "world", "walls", "corner", "balls"]  # the arrays themselves, then views of them
FIELDS += ["trig", "position", "centers", "rotations", "cells", "box"]  # the scratch
structref.define_constructor(Arrays, ArraysType, FIELDS)
structref.define_boxing(ArraysType, Arrays)


class BorrowedArray(types.Array):
    """numba's type of an array that counts no references: numba calls nothing when it is copied or dropped, where
    for an array it calls the runtime's ``NRT_incref``/``NRT_decref`` at every copy, even of an array whose count is
    not kept (a call of 16 configurations made 277 such calls). Whoever holds one keeps its array alive
    (:attr:`Arrays.owners`). A view taken of it is an ordinary array again."""

    def __init__(self, dtype, ndim, layout, readonly=False, aligned=True):
        name = f"borrowed array({dtype}, {ndim}d, {layout})"
        super().__init__(dtype, ndim, layout, readonly=readonly, name=name, aligned=aligned)

    def __repr__(self):  # not an Array's: a compiled version's name, made from it, tells the two apart
        return f"Borrowed{super().__repr__()}"


@register_model(BorrowedArray)
class BorrowedArrayModel(models.ArrayModel):
    """An array's data, laid out as an array's; it lists no members, so numba finds no reference count in it."""

    def traverse(self, builder):
        return []


def _borrowed_type(typ):
    """``typ`` with every array in it (in tuples too) a :class:`BorrowedArray`."""
    if isinstance(typ, types.Array):
        return BorrowedArray(typ.dtype, typ.ndim, typ.layout, readonly=not typ.mutable, aligned=typ.aligned)
    if isinstance(typ, types.BaseNamedTuple):
        return types.NamedTuple([_borrowed_type(t) for t in typ], typ.instance_class)
    if isinstance(typ, types.BaseTuple):
        return types.Tuple([_borrowed_type(t) for t in typ])
    return typ


def _borrow_value(context, builder, typ, value):
    """``value`` of numba type ``typ`` as :func:`_borrowed_type`'s: every array in it with no reference count."""
    if isinstance(typ, types.Array):
        view = cgutils.create_struct_proxy(typ)(context, builder, value=value)
        view.meminfo = cgutils.get_null_value(view.meminfo.type)
        view.parent = cgutils.get_null_value(view.parent.type)
        return view._getvalue()
    if isinstance(typ, types.BaseTuple):
        items = [_borrow_value(context, builder, t, builder.extract_value(value, i)) for i, t in enumerate(typ)]
        return context.make_tuple(builder, _borrowed_type(typ), items)
    return value


@intrinsic
def _borrowed(typingctx, value):
    """``value`` (an array, or a tuple holding arrays) with its arrays as :class:`BorrowedArray`: the loop takes
    them, and reads them, with no call to count references. Whoever holds them keeps the arrays themselves alive
    (:attr:`Arrays.owners`)."""

    def codegen(context, builder, signature, args):
        return _borrow_value(context, builder, signature.args[0], args[0])

    return _borrowed_type(value)(value), codegen


@njit(cache=True)
def arrays(robot, world) -> Arrays:
    """The :class:`Arrays` of ``robot`` and ``world`` (with its far bits): they, the loop's scratch and, computed once
    rather than at every call, the region's walls padded to 3D with infinities, its grid's corner (0 where padded)
    and per link the squared radii of a ball holding its box and of one it holds, a billionth inside the truth.

    The fields the loop reads hold arrays that count no references (:func:`_borrowed`: a call of 16 configurations
    made 277 calls to count them, 21 now); ``owners`` holds the arrays themselves."""
    half, n_links, dim = robot.half_extents, len(robot.half_extents), len(world.lower)
    walls, corner, balls = np.empty(6), np.empty(3), np.empty((2, n_links))
    for i in range(3):
        walls[i], walls[3 + i] = (world.lower[i], world.upper[i]) if i < dim else (-np.inf, np.inf)
        corner[i] = world.lower[i] if i < dim else 0.0
    for link in range(n_links):
        balls[0, link] = (half[link, 0] ** 2 + half[link, 1] ** 2 + half[link, 2] ** 2) * (1 + 1e-9)
        balls[1, link] = min(half[link, 0], half[link, 1], half[link, 2] if dim == 3 else np.inf) ** 2 * (1 - 1e-9)
    # zeros, not np.empty: a short block's vector loops also read lanes it did not write (_grid_cells runs over a
    # multiple of 32), and memory never written may hold subnormal numbers or NaN, on which the processor takes a
    # slow path an operation: a checker whose first calls were small paid that at every small call (3DC-9, 4 to 10
    # checkers in 60 made afresh: calls of 16 at 2.8x the cost of the others')
    trig = np.zeros((3, (len(robot.lower) - first_angle(robot)) * BLOCK))
    position, centers = np.zeros((3, BLOCK)), np.zeros((n_links, 3, BLOCK))
    rotations = np.zeros((n_links + 1, 3, 3, BLOCK))
    for i in range(3):  # the identity, where block_frames takes it from
        rotations[:, i, i] = 1.0
    cells = np.zeros((n_links + 2, BLOCK), np.int64)
    owners = (robot, world, walls, corner, balls, trig, position, centers, rotations, cells, np.zeros(27))
    return Arrays(owners, *_borrowed(owners))  # type: ignore[call-arg]  # numba passes the typing context


@njit(cache=True, inline="always")
def _cell(x, lower, inverse, last):
    """The layer of cells (``lower``, ``1 / inverse`` wide, ``0 .. last``) that holds coordinate ``x``, clipped.

    Multiplying by the inverse width rather than dividing may put a point within about 1e-15 of a border into the
    next cell; the far bits keep a margin of 1e-9 of the region and the cell lists one of 1e-9 of a link's reach,
    both far above it."""
    return min(max(int(np.floor((x - lower) * inverse)), 0), last)


@njit(cache=True, inline="always")
def _grid_cells(centers, link, lower, cell, shape, cells, row, block):
    """Fill ``cells[row, :block]`` with the cell of a grid (corner ``lower (3,)``, cubes ``cell`` wide, ``shape (3,)``)
    that holds each centre of link ``link`` (``centers (L, 3, B)``), clipped to the grid. The grid arrives as
    numbers: a loop that reads arrays while it writes another is not turned into vector instructions."""
    x0, y0, z0, inverse = lower[0], lower[1], lower[2], 1.0 / cell
    last_x, last_y, last_z, ny, nz = shape[0] - 1, shape[1] - 1, shape[2] - 1, shape[1], shape[2]
    for n in range(block):
        a, b = _cell(centers[link, 0, n], x0, inverse, last_x), _cell(centers[link, 1, n], y0, inverse, last_y)
        cells[row, n] = (a * ny + b) * nz + _cell(centers[link, 2, n], z0, inverse, last_z)


@njit(cache=True, inline="always")
def _block_needs(Q, first, block, robot, centers, far, world, corner, cells):
    """For the block ``Q[first:first + block]`` posed in ``centers (L, 3, B)``, fill ``cells (L + 2, B)``: row 0 -1
    for a configuration out of bounds, else one bit per link whose far bit is 0 (link ``l``: bit ``l``); row
    ``2 + l`` link ``l``'s cell of ``world``'s lists (``corner (3,)``: their grid's corner, 0 along a 2D world's third
    axis); row 1 scratch. Every loop runs over the block's configurations. Returns whether every number of the block
    is finite."""
    lower, upper = robot.lower, robot.upper
    for n in range(block):  # bit 0: out of bounds; bit 1: not finite (x - x is NaN for NaN and infinities)
        out = odd = 0
        for i in range(Q.shape[1]):  # a configuration's numbers lie side by side: one loop, not one per column
            x = Q[first + n, i]
            odd |= np.int64(x - x != 0.0)
            out |= np.int64((x < lower[i]) | (x > upper[i]))
        cells[0, n] = out | odd | (odd << 1)
    bits = far.bits
    lanes = min(-(-block // 32) * 32, BLOCK)
    for link in range(len(centers)):
        ball = far.link_ball[link]
        _grid_cells(centers, link, far.lower, far.cell, far.shape, cells, 1, lanes)
        for n in range(block):
            flat = cells[1, n]
            cells[0, n] |= np.int64(1 - ((bits[ball, flat >> 6] >> (flat & 63)) & 1)) << (link + 2)
        _grid_cells(centers, link, corner, world.cell, world.shape, cells, 2 + link, lanes)
    finite = True
    for n in range(block):
        finite &= not cells[0, n] & 2
        cells[0, n] = -1 if cells[0, n] & 3 else cells[0, n] >> 2
    return finite


@njit(cache=True, inline="always")
def _reach(rotations, link, i, b, half):
    """How far link ``link`` of configuration ``b`` reaches from its centre along world axis ``i``."""
    reach = 0.0
    for j in range(3):
        reach += abs(rotations[link, i, j, b]) * half[link, j]
    return reach


@njit(cache=True, inline="always")
def _link_touches(centers, rotations, link, b, half, walls, first, count, members, boxes, cell, balls, scratch):
    """Whether link ``link`` of configuration ``b`` of the block (``centers (L, 3, B)``, ``rotations (L, 3, 3, B)``,
    ``half (L, 3)``) leaves the region (``walls (6,)``: its lower then upper corner, padded to 3D with infinities)
    or touches an obstacle of ``boxes (K, 2, D)`` listed in its ``cell`` (``first, count, members``: a world's
    ``cell_first``, ``cell_count``, ``cell_boxes``). ``balls (2, L)``: the squared radii of a ball that holds the
    link box and of one it holds, a billionth inside the truth (far above rounding; nearer contact goes to the
    separating axes); ``scratch (27,)``: room for a link box and an obstacle box as :func:`boxes_touch` takes them.

    Every argument is a number or an array: a named tuple of arrays passed to it would cost a reference count
    per array per call."""
    c0, c1, c2 = centers[link, 0, b], centers[link, 1, b], centers[link, 2, b]
    e0, e1, e2 = (
        _reach(rotations, link, 0, b, half),
        _reach(rotations, link, 1, b, half),
        _reach(rotations, link, 2, b, half),
    )
    l0, l1, l2, h0, h1, h2 = c0 - e0, c1 - e1, c2 - e2, c0 + e0, c1 + e1, c2 + e2
    if not (
        walls[0] <= l0 and walls[1] <= l1 and walls[2] <= l2 and h0 <= walls[3] and h1 <= walls[4] and h2 <= walls[5]
    ):
        return True
    dim = boxes.shape[2]
    for m in range(first[cell], first[cell] + count[cell]):
        k = members[m]
        lo0, lo1, lo2 = boxes[k, 0, 0], boxes[k, 0, 1], boxes[k, 0, 2] if dim == 3 else -np.inf
        hi0, hi1, hi2 = boxes[k, 1, 0], boxes[k, 1, 1], boxes[k, 1, 2] if dim == 3 else np.inf
        if l0 > hi0 or h0 < lo0 or l1 > hi1 or h1 < lo1 or l2 > hi2 or h2 < lo2:
            continue  # a world axis separates them
        g0, g1, g2 = max(lo0 - c0, c0 - hi0, 0.0), max(lo1 - c1, c1 - hi1, 0.0), max(lo2 - c2, c2 - hi2, 0.0)
        squared = g0 * g0 + g1 * g1 + g2 * g2  # from the link's centre to the box
        if squared > balls[0, link]:
            continue
        if squared < balls[1, link]:
            return True
        center, R, link_half, low, high = (
            scratch[:3],
            scratch[3:12].reshape(3, 3),
            scratch[12:15],
            scratch[15:18],
            scratch[18:21],
        )
        box = scratch[21 : 21 + 2 * dim].reshape(2, dim)
        for i in range(3):
            center[i], link_half[i] = centers[link, i, b], half[link, i]
            for j in range(3):
                R[i, j] = rotations[link, i, j, b]
        low[0], low[1], low[2], high[0], high[1], high[2] = l0, l1, l2, h0, h1, h2
        box[:] = boxes[k]
        if boxes_touch(center, R, link_half, low, high, box, dim):
            return True
    return False


@intrinsic
def _address(typingctx, arrays):
    """Where ``arrays`` (an :class:`Arrays`) lies in memory: the address of its numba record (its meminfo)."""

    def codegen(context, builder, signature, args):
        ref = cgutils.create_struct_proxy(signature.args[0])(context, builder, value=args[0])
        return builder.ptrtoint(ref.meminfo, context.get_value_type(types.intp))

    return types.intp(arrays), codegen


@njit(cache=True)
def address(arrays) -> int:
    """The address of ``arrays``' record (:func:`validity_at` takes it): valid as long as ``arrays`` lives."""
    return _address(arrays)  # type: ignore[call-arg]  # numba supplies the typing context


@intrinsic
def _arrays_at(typingctx, address, kind):
    """The :class:`Arrays` of numba type ``kind`` (a type reference) whose record lies at ``address``
    (:func:`address`), with a reference of its own (numba drops it when done)."""
    arrays_type = kind.instance_type

    def codegen(context, builder, signature, args):
        ref = cgutils.create_struct_proxy(arrays_type)(context, builder)
        ref.meminfo = builder.inttoptr(args[0], ref.meminfo.type)
        value = ref._getvalue()
        context.nrt.incref(builder, arrays_type, value)
        return value

    return arrays_type(address, kind), codegen


@njit(cache=True)
def validity_at(Q, address, valid, kind):
    """:func:`validity` with the :class:`Arrays` given by the address of its record (:func:`address`) and its numba
    type ``kind``: numba takes an integer and a type from Python in a few nanoseconds, an :class:`Arrays` in about
    85 (it looks the record up by attribute name and counts a reference). The caller keeps the :class:`Arrays`
    alive."""
    return validity(Q, _arrays_at(address, kind), valid)


@njit(cache=True)
def validity(Q, arrays, valid):
    """Fill ``valid (N,)`` for configurations ``Q (N, dof)``: the steps in the module's docstring, each
    configuration stopping at its first failure; ``arrays``: the robot's and the world's (:class:`Arrays`).
    Returns whether ``Q`` has the robot's ``dof`` columns, lies in C order (its strides tested here: numba takes an
    array of another order as it is) and every number of it is finite (else ``valid`` means nothing)."""
    robot, world, walls, corner, balls = arrays.robot, arrays.world, arrays.walls, arrays.corner, arrays.balls
    n, dof = Q.shape
    if dof != len(robot.lower) or (n > 1 and Q.strides[0] != 8 * dof) or (dof > 1 and Q.strides[1] != 8):
        return False
    half, trig, position, cells = robot.half_extents, arrays.trig, arrays.position, arrays.cells  # scratch: Arrays
    centers, rotations, scratch = arrays.centers, arrays.rotations, arrays.box
    first_box, box_count, members = world.cell_first, world.cell_count, world.cell_boxes
    finite = True
    for first in range(0, len(Q), BLOCK):
        block = min(BLOCK, len(Q) - first)
        block_frames(Q, first, block, robot, trig, position, centers, rotations)
        finite &= _block_needs(Q, first, block, robot, centers, world.far, world, corner, cells)
        for b in range(block):
            need, link = cells[0, b], 0
            valid[first + b] = need >= 0
            while need > 0:  # the links whose far bit is 0, in order
                if need & 1 and _link_touches(
                    centers,
                    rotations,
                    link,
                    b,
                    half,
                    walls,
                    first_box,
                    box_count,
                    members,
                    world.boxes,
                    cells[2 + link, b],
                    balls,
                    scratch,
                ):
                    valid[first + b] = False
                    break
                need, link = need >> 1, link + 1
    return finite
