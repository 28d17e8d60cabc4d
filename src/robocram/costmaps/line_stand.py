"""Where an arm that reaches along a telescope stands to take its hand in and out along
the approach line by the telescope alone.

A base that cannot slide (a differential one) under an arm whose reach runs along a
horizontal prismatic joint (the drafted Stretch's telescope, sideways) reaches a grasp
in a shelf with its base turned a little and its telescope drawn in: the way out to the
pre-grasp then needs the base, and the drive turns the fingers into the shelf (the
fridge's milk: 2.6-5.1 mm into the fridge or the carton). From a stand whose heading lays
the telescope's axis on the approach line, far enough back that the telescope is out by
the approach and :data:`LINE_MARGIN` at the grasp, the arm alone goes in and out.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from robocram.costmaps.validators import IK_RESTARTS
from robocram.kinematics import IKOptions, IKResult, forward_kinematics, solve_ik
from robocram.robots import RobotDescription
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotObject, World

LINE_MARGIN = 0.02  # [m] of telescope left out with the hand drawn back to ``out``
LEVEL = 0.1  # the largest vertical share of a telescope's axis, or of an approach, counted level
PLACINGS = 4  # rounds of placing the base under the arm's best configuration
SETTLED = 1e-3  # [m] a placing that moves the base less has found the stand


def telescope(desc: RobotDescription, arm: str, joints: Mapping[str, float]) -> list[str]:
    """``arm``'s prismatic joints whose axis lies level (in the root link, at ``joints``)."""
    model = desc.model
    if model is None or arm not in desc.arms:
        return []
    found = []
    for name in desc.arms[arm].joints:
        joint = model.joints[name]
        if joint.type != "prismatic" or joint.mimic is not None:
            continue
        axis = _axis(desc, name, joints)
        if abs(axis[2]) <= LEVEL:
            found.append(name)
    return found


def _axis(desc: RobotDescription, name: str, joints: Mapping[str, float]) -> np.ndarray:
    """The unit axis of joint ``name`` in the root link, at ``joints``."""
    joint = desc.model.joints[name]  # type: ignore[union-attr]  # checked by the caller
    child = forward_kinematics(desc, joints, joint.child)
    axis = np.asarray(quat.rotate(child.orientation, joint.axis), dtype=float)
    return axis / max(float(np.linalg.norm(axis)), 1e-12)


def line_stand(
    world: World, robot: str | RobotObject, arm: str, out: Pose, grasp: Pose
) -> Pose | None:
    """The base pose (map) from which ``arm`` alone brings its tool from ``out`` (a pose
    back on the approach line: the pre-grasp, or past it where the hand draws a held thing
    out of a shelf) to ``grasp`` (both map) and back by its level telescope, with
    :data:`LINE_MARGIN` of it left out at ``out``; None where the approach is not level,
    the arm has no such telescope, or IK finds no such stand near where it stands."""
    body = world.robot(robot)
    desc = body.description
    joints = _masters(desc, world.joint_states(body))
    way = np.subtract(grasp.position, out.position)
    depth = float(np.linalg.norm(way))
    level = float(np.hypot(way[0], way[1]))
    prismatic = telescope(desc, arm, joints)
    if depth < 1e-6 or level < depth * (1.0 - LEVEL) or not prismatic:
        return None
    axis = _axis(desc, prismatic[0], joints)
    heading = math.atan2(way[1], way[0]) - math.atan2(axis[1], axis[0])
    turn = quat.from_euler(0.0, 0.0, heading)
    ahead = np.array([way[0], way[1]]) / level  # the approach's level direction (map)
    travel = depth + LINE_MARGIN  # the telescope's travel wanted at the grasp
    stand = Pose((*world.pose(body).position[:2], 0.0), turn)
    for _ in range(PLACINGS):
        result = _arm_alone(desc, arm, stand.inverse() * grasp, joints)
        reached = _masters(desc, {**joints, **result.joint_positions})
        tool = forward_kinematics(desc, reached, desc.arms[arm].tool_frame)
        tool_xy = np.asarray((Pose((0.0, 0.0, 0.0), turn) * tool).position[:2])
        back = max(0.0, travel - _drawn_out(desc, arm, reached, prismatic))  # out further
        x, y = np.asarray(grasp.position[:2]) - tool_xy - back * ahead
        moved = math.hypot(x - stand.position[0], y - stand.position[1])
        stand = Pose((float(x), float(y), 0.0), turn)
        if result.success and moved < SETTLED:
            break
    at_grasp = _arm_alone(desc, arm, stand.inverse() * grasp, joints)
    seed = _masters(desc, {**joints, **at_grasp.joint_positions})
    at_out = _arm_alone(desc, arm, stand.inverse() * out, seed)
    if not (at_grasp.success and at_out.success):
        return None
    left = _drawn_out(desc, arm, _masters(desc, {**seed, **at_out.joint_positions}), prismatic)
    return stand if left >= LINE_MARGIN - SETTLED else None


def _masters(desc: RobotDescription, joints: Mapping[str, float]) -> dict[str, float]:
    """``joints`` without the mimic followers (forward kinematics sets them)."""
    model = desc.model
    return {j: v for j, v in joints.items() if model is None or model.joints[j].mimic is None}


def _drawn_out(
    desc: RobotDescription, arm: str, joints: Mapping[str, float], prismatic: list[str]
) -> float:
    """How far [m] the tool comes back when the ``prismatic`` joints draw in to their
    lower limits from ``joints`` (their followers with them: a telescope's sections)."""
    model, frame = desc.model, desc.arms[arm].tool_frame
    drawn = {**joints}
    for name in prismatic:
        lower = model.joints[name].lower  # type: ignore[union-attr]  # a loaded model
        drawn[name] = lower if lower is not None else joints[name]
    there = forward_kinematics(desc, joints, frame).position
    back = forward_kinematics(desc, drawn, frame).position
    return float(np.linalg.norm(np.subtract(there, back)))


def _arm_alone(
    desc: RobotDescription, arm: str, target: Pose, seed: Mapping[str, float]
) -> IKResult:
    """IK for ``arm``'s tool at ``target`` (root link), the torso free, the base still."""
    options = IKOptions(use_torso=desc.torso_joint is not None, max_restarts=IK_RESTARTS)
    return solve_ik(desc, arm, target, seed=seed, options=options)
