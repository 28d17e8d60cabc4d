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
    pa = a - axis * float(a @ axis)
    pb = b - axis * float(b @ axis)
    if np.linalg.norm(pa) < 1e-9 or np.linalg.norm(pb) < 1e-9:
        return 0.0
    return math.atan2(float(np.cross(pa, pb) @ axis), float(pa @ pb))
