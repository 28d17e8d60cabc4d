"""The orientation of a camera's optical frame that looks from one point at another.

An optical frame (ROS's convention, and what a rendered picture is taken along) has z
forward, x to the right of the picture and y down it; a camera looking at a point keeps
the picture upright, x level with the floor.
"""

from __future__ import annotations

import numpy as np

from robocram.tf.errors import PoseValueError
from robocram.tf.pose import Pose, Vector3
from robocram.tf.quaternion import Quaternion


def optical_look_at(eye: Vector3, target: Vector3) -> Quaternion:
    """The optical-frame orientation at ``eye`` facing ``target`` (both [m], one frame).

    Raises:
        PoseValueError: ``target`` is at ``eye``: no direction to look in.
    """
    z = np.subtract(target, eye).astype(float)
    if np.linalg.norm(z) < 1e-6:
        raise PoseValueError(f"look target {target} is at the camera {eye}; look somewhere else")
    z /= np.linalg.norm(z)
    x = np.cross((0.0, 0.0, -1.0), z)
    if np.linalg.norm(x) < 1e-6:  # looking straight up or down: any level x will do
        x = np.array((0.0, -1.0, 0.0))
    x /= np.linalg.norm(x)
    y = np.cross(z, x)
    m = np.eye(4)
    m[:3, :3] = np.column_stack((x, y, z))
    return Pose.from_matrix(m).orientation
