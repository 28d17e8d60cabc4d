"""Where a link of a robot model is for given joint values, without a physics or IK library.

The robots layer derives values from the URDF (camera heights at the torso's limits, a
gripper's opening, the checks that a tool frame or torso makes sense) and may import only
logic and tf, so it composes the joints' origins and motions itself. Kinematics has the
fast pinocchio version for IK; this one is for a few poses at load time.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from robocram.robots.mimic import mimic_followers
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint
from robocram.tf import Pose
from robocram.tf import quaternion as quat


def resting_value(joint: Joint) -> float:
    """The value nearest 0 within the joint's limits [rad | m] (what an unset joint holds)."""
    lower = -math.inf if joint.lower is None else joint.lower
    upper = math.inf if joint.upper is None else joint.upper
    return min(max(0.0, lower), upper)


def finite_limits(joint: Joint) -> tuple[float, float] | None:
    """The joint's ``(lower, upper)`` limits [rad | m], or None unless both are finite."""
    if joint.lower is None or joint.upper is None:
        return None
    if not (math.isfinite(joint.lower) and math.isfinite(joint.upper)):
        return None
    return joint.lower, joint.upper


def _motion(joint: Joint, value: float) -> Pose:
    """The joint's own motion at ``value``: a turn about or a slide along its axis."""
    norm = math.sqrt(sum(a * a for a in joint.axis)) or 1.0
    axis = (joint.axis[0] / norm, joint.axis[1] / norm, joint.axis[2] / norm)
    if joint.type in ("revolute", "continuous"):
        return Pose(orientation=quat.from_axis_angle(axis, value))
    if joint.type == "prismatic":
        return Pose((axis[0] * value, axis[1] * value, axis[2] * value))
    return Pose()


def joint_transform(joint: Joint, value: float = 0.0) -> Pose:
    """``parent_T_child`` of ``joint`` at ``value`` [rad | m]: its origin, then its motion."""
    return joint.origin * _motion(joint, value)


def link_pose(model: RobotModel, link: str, joints: Mapping[str, float] | None = None) -> Pose:
    """Pose of ``link`` in the model's root link for ``joints`` [rad | m].

    Joints not given rest at the value nearest 0 within their limits; mimic joints follow
    their masters.
    """
    values = mimic_followers(model, dict(joints or {}))
    pose = Pose()
    for joint in model.chain(model.root_link, link):
        value = values.get(joint.name, resting_value(joint))
        pose = pose * joint_transform(joint, value)
    return pose


def link_poses(
    model: RobotModel, links: Iterable[str], joints: Mapping[str, float] | None = None
) -> dict[str, Pose]:
    """:func:`link_pose` of each of ``links`` for ``joints``, the same poses bit for bit.

    A joint's transform is composed once for all the links below it, not once per link
    (the PR2's 82 links at rest: 82 transforms instead of 760); products are taken in
    :func:`link_pose`'s order, from the root down.
    """
    values = mimic_followers(model, dict(joints or {}))
    below: dict[str, Pose] = {}  # a link's pose, by the link (one chain reaches each)
    poses = {}
    for name in links:
        pose = Pose()
        for joint in model.chain(model.root_link, name):
            found = below.get(joint.child)
            if found is None:
                value = values.get(joint.name, resting_value(joint))
                found = below[joint.child] = pose * joint_transform(joint, value)
            pose = found
        poses[name] = pose
    return poses


def resting_link_poses(model: RobotModel) -> dict[str, Pose]:
    """Every link's :func:`link_pose` at rest (no joints given)."""
    return link_poses(model, model.links)


def subtree_links(model: RobotModel, link: str) -> tuple[str, ...]:
    """``link`` and every link below it, breadth first."""
    children: dict[str, list[str]] = {}
    for joint in model.joints.values():
        children.setdefault(joint.parent, []).append(joint.child)
    found, queue = [], [link]
    while queue:
        current = queue.pop(0)
        found.append(current)
        queue.extend(children.get(current, ()))
    return tuple(found)
