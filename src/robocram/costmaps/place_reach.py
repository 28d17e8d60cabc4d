"""What putting a held object down from a stand needs: the tool poses the place plan uses.

The place plan (``plans.place_object``) keeps the grasp the object is held with: the tool
goes where the object, put at the target, has it (the object's pose in the tool frame
now), first :data:`CARRY_HEIGHT` above, then down; if that does not work, the object is
turned about the vertical by a quarter, a half and three quarters. A stand that reaches
a place for a robot holding something is judged on these tool poses, not on a grasp
from above that the hand does not have.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotObject, World

CARRY_HEIGHT = 0.10  # [m] the held object comes in this far above where it is put
TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)  # [rad] turns of the object, in order


@dataclass(frozen=True)
class PlaceTarget:
    """One way to put the held object down: the arm, and its tool poses in the base frame."""

    arm: str
    place_in_base: Pose
    above_in_base: Pose


def held_objects(world: World, robot: RobotObject) -> list[tuple[str, Pose]]:
    """``(arm, object pose in the arm's tool frame)`` for each object the robot's hands hold."""
    desc = robot.description
    held = []
    for attachment in world.all_attachments():
        if attachment.robot != robot.name:
            continue
        for name, spec in desc.arms.items():
            hand = {*spec.hand_links, *spec.gripper_links, spec.end_effector_link, spec.tool_frame}
            if attachment.link in hand:
                tool = world.link_pose(robot, spec.tool_frame)
                held.append((name, tool.inverse() * world.pose(attachment.obj)))
                break
    return held


def place_targets(
    world: World, robot: RobotObject, target: Pose, base: Pose, arm: str | None = None
) -> list[PlaceTarget]:
    """Tool poses putting what ``robot`` holds at ``target`` (its frame's pose in the map)
    from a stand at ``base``, turn by turn; empty when it holds nothing (in ``arm``)."""
    to_base = base.inverse()
    found = []
    for name, object_in_tool in held_objects(world, robot):
        if arm is not None and name != arm:
            continue
        for turn in TURNS:
            turned = quat.multiply(quat.from_euler(0.0, 0.0, turn), target.orientation)
            tool = Pose(target.position, turned) * object_in_tool.inverse()
            x, y, z = tool.position
            above = Pose((x, y, z + CARRY_HEIGHT), tool.orientation)
            found.append(PlaceTarget(name, to_base * tool, to_base * above))
    return found
