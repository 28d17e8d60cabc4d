"""Frames and poses: positions [m], quaternions (x, y, z, w), stamped poses and transforms."""

from robocram.tf.errors import (
    PoseValueError,
    RosMessageError,
    TfArgumentError,
    TfError,
    TfUsageError,
    TransformError,
)
from robocram.tf.pose import Pose, PoseLike, Vector3
from robocram.tf.quaternion import Quaternion
from robocram.tf.ros_messages import (
    pose_from_ros,
    pose_stamped_from_ros,
    pose_stamped_to_ros,
    pose_to_ros,
    transform_stamped_from_ros,
    transform_stamped_to_ros,
)
from robocram.tf.stamped import PoseStamped, TransformStamped
from robocram.tf.transform_context import (
    current_transform_tree,
    transform_pose,
    using_transform_tree,
)
from robocram.tf.transform_tree import TransformSource, TransformTree

__all__ = [
    "Pose",
    "PoseLike",
    "PoseStamped",
    "PoseValueError",
    "Quaternion",
    "RosMessageError",
    "TfArgumentError",
    "TfError",
    "TfUsageError",
    "TransformError",
    "TransformSource",
    "TransformStamped",
    "TransformTree",
    "Vector3",
    "current_transform_tree",
    "pose_from_ros",
    "pose_stamped_from_ros",
    "pose_stamped_to_ros",
    "pose_to_ros",
    "transform_pose",
    "transform_stamped_from_ros",
    "transform_stamped_to_ros",
    "using_transform_tree",
]
