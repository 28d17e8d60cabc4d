"""Frames and poses: positions [m], quaternions (x, y, z, w), stamped poses and transforms."""

from robocram.tf.pose import Pose, PoseLike, Vector3
from robocram.tf.quaternion import Quaternion

__all__ = ["Pose", "PoseLike", "Quaternion", "Vector3"]
