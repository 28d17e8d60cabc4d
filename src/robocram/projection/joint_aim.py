"""Aiming a camera joint by joint: the values that turn its optical axis onto a target.

Each joint turns by the angle between the optical axis and the direction to the target,
both projected onto the plane normal to the joint's axis; a few rounds absorb the
camera's offset from the axes. A pan-tilt head aims with its two joints, a head that only
pans with its one (the tilt it cannot change is accepted). The links are placed by the
robot's kinematic model from its base pose in the world: a round costs microseconds, where
setting the joints in the world and reading its links back cost a millisecond a look.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf.signed_angle import signed_angle
from robocram.world import JointLimits

AIM_ROUNDS = 6
AIM_TOLERANCE = 1e-4  # [rad] a round changing the joints less than this ends the aiming


def nearest_in_limits(value: float, limits: JointLimits) -> float:
    """``value`` or a 2*pi turn of it that lies within ``limits``, else ``value``."""
    for candidate in (value, value - 2 * math.pi, value + 2 * math.pi):
        if limits.lower <= candidate <= limits.upper:
            return candidate
    return value


def aimed_joints(
    robot: ProjectedRobot, axes: Sequence[tuple[str, str]], target: np.ndarray
) -> dict[str, float]:
    """The values of ``axes`` (``(joint, link)`` pairs, outermost first) that point the
    first camera at ``target`` (map), unclamped.

    The rounds turn each joint in turn with the others held where the last turn (clamped
    to its limits, as setting it would) left them.
    """
    world, desc = robot.world, robot.description
    kin = robot_kinematics(desc.model)
    frames = [kin.frame_id(link) for _, link in axes] + [kin.frame_id(desc.cameras[0].frame)]
    local_axes = [np.asarray(desc.model.joints[joint].axis, float) for joint, _ in axes]
    limits = [world.bodies.joint_limits(robot.name, joint) for joint, _ in axes]
    state = world.joint_states(robot.name)
    q = kin.configuration({j: v for j, v in state.items() if desc.model.joints[j].mimic is None})
    root = world.pose(robot.name).matrix()
    values = [state[joint] for joint, _ in axes]
    wanted: dict[str, float] = {}
    for _ in range(AIM_ROUNDS):
        before = list(values)
        for k, (joint, _) in enumerate(axes):
            placed = kin.frame_matrices(q, (frames[k], frames[-1]))
            link, view = root @ placed[0], root @ placed[1]
            axis = link[:3, :3] @ local_axes[k]
            axis /= np.linalg.norm(axis)
            turn = signed_angle(view[:3, 2], target - view[:3, 3], axis)
            wanted[joint] = nearest_in_limits(values[k] + turn, limits[k])
            values[k] = limits[k].clamp(wanted[joint])
            kin.put(q, joint, values[k])
        if max(abs(a - b) for a, b in zip(values, before, strict=True)) < AIM_TOLERANCE:
            break
    return wanted
