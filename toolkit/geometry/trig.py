"""Sines and cosines that a compiled loop vectorizes (numba): Cephes' polynomials in place of a C library call.

Forward kinematics (:mod:`toolkit.geometry.frame_kernels`) turns every link frame by the sine and cosine of a
joint angle; the paper's robots (§IV-A) take one to nine such angles. A call to the C library's ``sin`` per angle
cost more than the rest of the kinematics, and it keeps the compiler from turning a loop over configurations
into vector instructions. :func:`sin_cos` is Cephes' (S. Moshier, ``sin.c``), written without a branch: pi/4 in
three parts (subtracting multiples of it exactly up to ``|x| ~ 1e9``), then polynomials on ``[-pi/4, pi/4]``;
within an ulp or two of the C library's, and a loop over many angles of it compiles to vector instructions.
:func:`any_sin_cos` takes any angle, handing those beyond ``SIN_COS_LIMIT`` to the C library.
"""

from __future__ import annotations

import numpy as np
from numba import njit

# Cephes' constants (sin.c): pi/4 in three parts, then the coefficients of the sine's and the cosine's polynomials
_PI4 = (7.85398125648498535156e-1, 3.77489470793079817668e-8, 2.69515142907905952645e-15)
_SIN = (1.58962301576546568060e-10, -2.50507477628578072866e-8, 2.75573136213857245213e-6,
        -1.98412698295895385996e-4, 8.33333333332211858878e-3, -1.66666666666666307295e-1)  # fmt: skip
_COS = (-1.13585365213876817300e-11, 2.08757008419747316778e-9, -2.75573141792967388112e-7,
        2.48015872888517045348e-5, -1.38888888888730564116e-3, 4.16666666666665929218e-2)  # fmt: skip
SIN_COS_LIMIT = 1e8  # beyond this |angle|, the C library's


@njit(cache=True, inline="always")
def sin_cos(x):
    """``(sin(x), cos(x))`` for ``|x| <= SIN_COS_LIMIT``, without a branch."""
    a = abs(x)
    octant = np.int64(a * (4 / np.pi))
    octant += octant & 1  # even: the nearest multiple of pi/2 below or above
    y = np.float64(octant)
    z = ((a - y * _PI4[0]) - y * _PI4[1]) - y * _PI4[2]  # in [-pi/4, pi/4]
    zz = z * z
    p = _SIN[0]
    for coefficient in _SIN[1:]:
        p = p * zz + coefficient
    q = _COS[0]
    for coefficient in _COS[1:]:
        q = q * zz + coefficient
    sin_z, cos_z = z + z * zz * p, 1.0 - 0.5 * zz + zz * zz * q
    quadrant = (octant >> 1) & 3  # sin a: sin_z, cos_z, -sin_z, -cos_z; cos a: cos_z, -sin_z, -cos_z, sin_z
    sin_a = cos_z if quadrant & 1 else sin_z
    cos_a = sin_z if quadrant & 1 else cos_z
    sin_a = -sin_a if quadrant & 2 else sin_a
    cos_a = -cos_a if (quadrant + 1) & 2 else cos_a
    return (-sin_a if x < 0 else sin_a), cos_a


@njit(cache=True, inline="always")
def any_sin_cos(x):
    """:func:`sin_cos` of any angle (beyond ``SIN_COS_LIMIT``, the C library's)."""
    return sin_cos(x) if abs(x) <= SIN_COS_LIMIT else (np.sin(x), np.cos(x))
