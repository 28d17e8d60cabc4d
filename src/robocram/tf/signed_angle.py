"""The signed angle turning one vector onto another about an axis.

Aiming a pan or tilt joint (in projection and over ROS alike) needs the turn about that
joint's axis, with both vectors first projected onto the plane normal to it.
"""

from __future__ import annotations

import math

import numpy as np


def signed_angle(a: np.ndarray, b: np.ndarray, axis: np.ndarray) -> float:
    """Angle [rad] turning ``a`` onto ``b`` about the unit ``axis``; 0 if either is parallel.

    >>> import numpy as np
    >>> round(signed_angle(np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([0, 0, 1.0])), 6)
    1.570796
    """
    ax, ay, az = (float(c) for c in axis)
    a0, a1, a2 = (float(c) for c in a)
    b0, b1, b2 = (float(c) for c in b)
    along_a = a0 * ax + a1 * ay + a2 * az
    along_b = b0 * ax + b1 * ay + b2 * az
    pa = (a0 - ax * along_a, a1 - ay * along_a, a2 - az * along_a)  # on the plane normal to it
    pb = (b0 - ax * along_b, b1 - ay * along_b, b2 - az * along_b)
    if math.hypot(*pa) < 1e-9 or math.hypot(*pb) < 1e-9:
        return 0.0
    cross = (
        pa[1] * pb[2] - pa[2] * pb[1],
        pa[2] * pb[0] - pa[0] * pb[2],
        pa[0] * pb[1] - pa[1] * pb[0],
    )
    sine = cross[0] * ax + cross[1] * ay + cross[2] * az
    cosine = pa[0] * pb[0] + pa[1] * pb[1] + pa[2] * pb[2]
    return math.atan2(sine, cosine)
