"""What putting a held object down from a stand needs: the tool poses the place plan uses.

The place plan (``plans.place_object``) keeps the grasp the object is held with: the tool
goes where the object, put at the target (:data:`PLACE_GAP` above it), has it (the
object's pose in the tool frame now), coming in from above if it can; after letting go
the hand backs off :data:`RETREAT` towards the wrist. If that does not work, the object
is turned about the vertical by a quarter, a half and three quarters. A stand that
reaches a place for a robot holding something is judged on these tool poses (the put and
the retreat, which the plan needs), not on a grasp from above that the hand lacks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.costmaps.grasps import approach_axis
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotObject, World

PLACE_GAP = 0.005  # [m] the object is let go this far above the target
RETREAT = 0.10  # [m] the open hand backs off this far towards the wrist
TURNS = (0.0, math.pi / 2, -math.pi / 2, math.pi)  # [rad] turns of the object, in order


@dataclass(frozen=True)
class PlaceTarget:
    """One way to put the held object down: the arm, and its tool poses in the base frame."""

    arm: str
    place_in_base: Pose
    retreat_in_base: Pose


def held_objects(world: World, robot: RobotObject) -> list[tuple[str, Pose]]:
    """``(arm, object pose in the arm's tool frame)`` for each object the robot's hands hold."""
    desc = robot.description
    held = []
    for attachment in world.bodies.all_attachments():
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
    x, y, z = target.position
    found = []
    for name, object_in_tool in held_objects(world, robot):
        if arm is not None and name != arm:
            continue
        back = -approach_axis(robot.description, name) * RETREAT  # tool frame
        for turn in TURNS:
            turned = quat.multiply(quat.from_euler(0.0, 0.0, turn), target.orientation)
            tool = Pose((x, y, z + PLACE_GAP), turned) * object_in_tool.inverse()
            retreat = tool * Pose((float(back[0]), float(back[1]), float(back[2])))
            found.append(PlaceTarget(name, to_base * tool, to_base * retreat))
    return found
