"""Link poses of a model at given joint values, from the URDF alone (no kinematics backend).

The draft measures a URDF before any description exists: where the hands point, how high
a camera sits at the torso's limits. Poses are in the model's root link.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from robocram.robots.mimic import mimic_followers
from robocram.robots.robot_model import RobotModel
from robocram.tf import Pose
from robocram.tf import quaternion as quat


def joint_motion(axis: tuple[float, float, float], kind: str, value: float) -> Pose:
    """The joint's own motion by ``value`` [rad | m] about or along its unit ``axis``."""
    unit = np.asarray(axis, float)
    unit /= np.linalg.norm(unit)
    if kind == "prismatic":
        return Pose(tuple(float(v) for v in unit * value))  # type: ignore[arg-type]
    return Pose(orientation=quat.from_axis_angle((unit[0], unit[1], unit[2]), value))


def link_poses(model: RobotModel, values: Mapping[str, float] | None = None) -> dict[str, Pose]:
    """Every link's pose in the root link; joints not given stay at 0 (or their followers)."""
    states = mimic_followers(model, dict(values or {}))
    poses = {model.root_link: Pose()}
    pending = list(model.joints.values())
    while pending:
        waiting = []
        for joint in pending:
            if joint.parent not in poses:
                waiting.append(joint)
                continue
            pose = poses[joint.parent] * joint.origin
            value = states.get(joint.name, 0.0)
            if joint.movable and value != 0.0:
                pose = pose * joint_motion(joint.axis, joint.type, value)
            poses[joint.child] = pose
        if len(waiting) == len(pending):
            break  # a tree always shrinks; RobotModel rejects loops
        pending = waiting
    return poses


def axis_in_root(model: RobotModel, joint: str, poses: Mapping[str, Pose]) -> np.ndarray:
    """The unit axis of ``joint`` in the root link, with the links at ``poses``."""
    spec = model.joints[joint]
    frame = poses[spec.parent] * spec.origin
    axis = quat.to_matrix(frame.orientation) @ np.asarray(spec.axis, float)
    return np.asarray(axis / np.linalg.norm(axis))


def within_limits(model: RobotModel, joint: str, value: float) -> float:
    """``value`` moved into ``joint``'s limits (infinite limits leave it as is)."""
    spec = model.joints[joint]
    lower = -math.inf if spec.lower is None else spec.lower
    upper = math.inf if spec.upper is None else spec.upper
    return min(max(value, lower), upper)
