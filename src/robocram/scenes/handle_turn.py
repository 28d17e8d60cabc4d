"""The mug's handle turned to the arm that takes it by the handle alone.

A hand that opens narrower than the mug's body closes round nothing of it but its handle,
from above (``grasping/grasp_model.py``). With the handle to the left, as the scenes lay
it, the hand must open along the arm's reach, turned a quarter from how a wrist held out
straight holds it: Baxter's right arm, beside its torso, then put its elbow into the torso
(11-21 IK solutions each, all in collision) and its left arm fell 2-4 cm short. Turned to
face the arm's shoulder, the handle lies across the reach, nearer the shoulder, and the
hand comes down on it opening across: both of Baxter's picks then succeed. A hand wide
enough for the body keeps the handle where it was: nothing changes for it.
"""

from __future__ import annotations

import math

from robocram.robots import LoadedDescription
from robocram.scenes.placement import placement_arm, shoulder_in_map
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World, WorldObject


def handle_only(desc: LoadedDescription, body_width: float) -> bool:
    """Whether the scene's picking arm opens narrower than ``body_width`` [m]: it can take
    the mug by its handle only."""
    arm = placement_arm(desc)
    gripper = arm.gripper if arm is not None else None
    if gripper is None or gripper.is_suction or gripper.max_opening is None:
        return False
    return gripper.max_opening < body_width


def _reaches(world: World, mug: WorldObject) -> dict[tuple[float, float], float]:
    """How far [m] the mug reaches from its axis along the map's x, -x, y and -y."""
    low, high = world.aabb(mug)
    x, y, _ = world.pose(mug).position
    return {
        (1.0, 0.0): high[0] - x,
        (-1.0, 0.0): x - low[0],
        (0.0, 1.0): high[1] - y,
        (0.0, -1.0): y - low[1],
    }


def turn_handle_to_arm(world: World, robot: str, mug: WorldObject) -> None:
    """Turn ``mug`` about its vertical axis so that its handle faces the shoulder of the
    arm that picks it, where that arm's hand opens narrower than the mug's body
    (:func:`handle_only`); else leave it. Its axis stays where it is."""
    desc = world.robot(robot).description
    arm = placement_arm(desc)
    pose = world.pose(mug)
    x, y, _ = pose.position
    reaches = _reaches(world, mug)
    handle = max(reaches, key=lambda side: reaches[side])
    if arm is None or not handle_only(desc, 2.0 * min(reaches.values())):
        return
    shoulder = shoulder_in_map(world, robot, arm)
    toward = math.atan2(shoulder[1] - y, shoulder[0] - x)
    turn = toward - math.atan2(handle[1], handle[0])
    yaw = quat.to_euler(pose.orientation)[2] + turn
    world.set_pose(mug, Pose(pose.position, quat.from_euler(0.0, 0.0, yaw)))
