"""A drafted trunk stands as its URDF draws it: a joint whose zero lies outside its limits
is made up for by the joint before it that turns about the same axis.

The world starts each joint at its value nearest 0. Rollin' Justin's ``torso3_joint`` may
not go below 0.1745 rad, so it starts there and, with ``torso2_joint`` at 0, leans the
upper trunk, both shoulders and the head 10 degrees forward of the URDF's upright zero
pose; the arms' reach and the room between them and the other parked hand are then not
the ones its URDF was drawn with (the tabletop mug: its handle grasps out of reach, the
one reached blocked by the mug, or the left hand into the parked right one). Turning
``torso2_joint`` back by as much puts every link from ``torso3`` up as at zero; the joint
before the clamped one is taken first, so the clamp's own link and all above it stand as
drawn (``torso4_joint`` instead would stand the shoulders 5 cm forward, and Justin missed
the mug so). The trunk's joints are cut out of the arms' chains
(:mod:`~robocram.robots.draft.trunk`), so nothing moves them afterwards: this is where
the trunk stays, like a legged robot's ``stance`` (:mod:`~.stance`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from robocram.robots.draft.link_poses import axis_in_root, link_poses
from robocram.robots.draft.stance import Stance
from robocram.robots.model_pose import resting_value
from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint
from robocram.tf import Pose
from robocram.tf import quaternion as quat

PARALLEL = 0.999  # |cos| between two joints' axes (root link) above which they are one axis
UPRIGHT = 1e-3  # [rad] the trunk's top may stand off its zero-pose orientation this much


def upright_trunk(model: RobotModel, trunk: Sequence[str]) -> Stance | None:
    """The values [rad] of ``trunk``'s joints (root first) that make up for the revolute
    ones starting off 0 (their zero out of limits), each by the nearest joint before it
    about a parallel axis, else after it; None where every trunk joint can start at 0 or
    no such joint makes up for one (the top would not stand as at zero)."""
    joints = [model.joints[name] for name in trunk]
    rest = {j.name: resting_value(j) for j in joints if j.movable and j.mimic is None}
    off = [j for j in joints if j.type in ("revolute", "continuous") and rest.get(j.name, 0.0)]
    if not off:
        return None
    zero = link_poses(model)
    values: dict[str, float] = {}
    for joint in off:
        partner = _partner(model, joints, joint, zero, set(values) | {j.name for j in off})
        if partner is None:
            return None
        sign = float(np.sign(_axis(model, partner, zero) @ _axis(model, joint, zero)))
        value = round(-sign * rest[joint.name], 6)
        values[partner.name] = value
    top = joints[-1].child
    turned = link_poses(model, {**rest, **values})[top].orientation
    if quat.angle_between(turned, zero[top].orientation) > UPRIGHT:
        return None
    clamped = ", ".join(f"{j.name} {rest[j.name]:+.4f}" for j in off)
    turns = ", ".join(f"{name} {value:+.4f}" for name, value in values.items())
    why = (
        f"trunk: joints whose zero is out of limits start off it ({clamped} rad) and would "
        f"lean the links above them; turned about the same axis ({turns} rad), the trunk's "
        f"top ({top}) stands as the URDF draws it at zero"
    )
    return Stance(values, why)


def _axis(model: RobotModel, joint: Joint, zero: Mapping[str, Pose]) -> np.ndarray:
    """``joint``'s unit axis in the root link at the zero pose."""
    return axis_in_root(model, joint.name, zero)


def _partner(
    model: RobotModel, joints: list[Joint], joint: Joint, zero: Mapping[str, Pose], taken: set[str]
) -> Joint | None:
    """The revolute trunk joint nearest ``joint`` (before it first) whose axis is parallel
    to its own and whose limits take the turn back; None if none does."""
    at = joints.index(joint)
    order = [*reversed(joints[:at]), *joints[at + 1 :]]
    axis = _axis(model, joint, zero)
    rest = resting_value(joint)
    for other in order:
        if other.name in taken or other.type not in ("revolute", "continuous") or other.mimic:
            continue
        dot = float(_axis(model, other, zero) @ axis)
        if abs(dot) < PARALLEL:
            continue
        value = -np.sign(dot) * rest
        lower = -np.inf if other.lower is None else other.lower
        upper = np.inf if other.upper is None else other.upper
        if lower <= value <= upper:
            return other
    return None
