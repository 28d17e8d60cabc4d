"""Pan and tilt angles that point a robot's camera at a point, from forward kinematics.

For heads driven by a pan/tilt trajectory controller (the HSR) the angles are computed on
the plan side: each joint turns by the angle between the camera's optical axis (z) and
the direction to the target, both projected onto the plane normal to the joint's axis;
a few rounds absorb the camera's offset from the axes. Limits are not applied here: the
controller rejects or clamps, and the process module reports that as the typed failure.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from robocram.kinematics import forward_kinematics
from robocram.robots import RobotDescription
from robocram.ros.errors import RosConfigError
from robocram.tf import Pose, Vector3
from robocram.tf.signed_angle import signed_angle

ROUNDS = 6
TOLERANCE = 1e-4  # [rad] a round changing the angles less than this ends the aiming


def pan_tilt_towards(
    desc: RobotDescription,
    joints: Mapping[str, float],
    base_in_map: Pose,
    target_in_map: Vector3,
) -> dict[str, float]:
    """Pan and tilt joint values [rad] aiming ``desc``'s first camera at ``target_in_map``."""
    pt = desc.pan_tilt
    if pt is None or not desc.cameras or desc.model is None:
        raise RosConfigError(
            f"{desc.name} has no pan-tilt head with a camera; its head needs a "
            "control_msgs/PointHead server in its ros_action facts"
        )
    values = dict(joints)
    target = np.asarray(target_in_map, float)
    camera_frame = desc.cameras[0].frame
    for _ in range(ROUNDS):
        change = 0.0
        for joint, link in pt.axes():
            link_pose = (base_in_map * forward_kinematics(desc, values, link)).matrix()
            axis = link_pose[:3, :3] @ np.asarray(desc.model.joints[joint].axis, float)
            camera = (base_in_map * forward_kinematics(desc, values, camera_frame)).matrix()
            turn = signed_angle(camera[:3, 2], target - camera[:3, 3], axis / np.linalg.norm(axis))
            values[joint] = values.get(joint, 0.0) + turn
            change = max(change, abs(turn))
        if change < TOLERANCE:
            break
    return {pt.pan_joint: values[pt.pan_joint], pt.tilt_joint: values[pt.tilt_joint]}
