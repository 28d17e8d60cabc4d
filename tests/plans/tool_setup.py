"""Scenes for the tool action tests: a tabletop with the objects, the tool in the hand."""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import GripperClosedCompletely, GripperMetOneSide
from robocram.grasping.hand import hand_of, tool_orientation
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.tf.quaternion import Quaternion
from robocram.world import World

DOWN = (0.0, 0.0, -1.0)
TORSO_LIFT = 0.2  # [m] the torso's goal, where its limits allow
# how each tool is held: (where the hand goes, over the work [m], in the robot's heading;
# the hand's approach, "down" or "ahead"; how far the tool's frame is below the tool frame)
GRIPS = {
    "spoon": ((-0.05, 0.0, 0.3), "down", 0.13),  # the stick held 13 cm over the head
    "sponge": ((-0.05, 0.0, 0.2), "down", 0.01),
    "knife": ((-0.2, 0.0, 0.25), "down", 0.0),  # the handle's middle, blade ahead
    "cup": ((-0.15, -0.05, 0.2), "ahead", 0.05),  # from the side, 5 cm over its bottom
}


def grip_orientation(world: World, robot: str, arm: str, approach: str) -> Quaternion:
    """The tool frame's orientation (map) that puts ``arm``'s hand, as the grasp model reads
    it from the kinematics, onto ``approach`` ("down" or "ahead" along the robot's
    heading), its fingers closing across the heading: any robot's hand, not one's axes."""
    yaw = quat.to_euler(world.pose(robot).orientation)[2]
    ahead = (math.cos(yaw), math.sin(yaw), 0.0)
    across = (-math.sin(yaw), math.cos(yaw), 0.0)
    hand = hand_of(world.robot(robot).description, arm)
    return tool_orientation(hand, DOWN if approach == "down" else ahead, across)


@dataclass(frozen=True)
class ToolScene:
    """A tabletop world, the robot, the arm holding the tool, and the work's spot (map)."""

    world: World
    robot: str
    arm: str
    spot: tuple[float, float, float]  # [m] on the table top, where the work lies


def tool_scene(robot: str, tool: str, arm: str | None = None) -> ToolScene:
    """A tabletop for ``robot`` without its mug and bottle; ``arm`` has gripped a
    ``tool`` (``<tool>-1``) put between its open fingers, over the table (default: the
    right arm, else the robot's first)."""
    scene = tabletop_scene(robot)
    world = scene.world
    arms = world.robot(scene.robot).description.arms
    arm = arm or ("right" if "right" in arms else next(iter(arms)))
    world.remove("mug-1")
    world.remove("bottle-1")
    x, y, h = scene.look_target.pose.position
    offset, approach, below = GRIPS[tool]
    name = f"{tool}-1"
    yaw = quat.to_euler(world.pose(scene.robot).orientation)[2]
    c, s = math.cos(yaw), math.sin(yaw)
    at = (x + c * offset[0] - s * offset[1], y + s * offset[0] + c * offset[1], h + offset[2])
    with simulated_robot(world, scene.robot):
        torso = world.robot(scene.robot).description.torso_joint
        if torso is not None:  # up to 0.2 m, as its limits allow (Boxy's runs below 0)
            lift = min(TORSO_LIFT, world.bodies.joint_limits(scene.robot, torso).upper)
            perform(a.motion(type="moving-torso", joint_angle=lift))
        target = Pose(at, grip_orientation(world, scene.robot, arm, approach))
        perform(a.motion(type="moving-tcp", arm=arm, target=target))
        perform(a.motion(type="opening", gripper=arm))
        spec = world.robot(scene.robot).description.arms[arm]
        tcp = world.link_pose(scene.robot, spec.tool_frame).position
        upright = quat.from_euler(0.0, 0.0, yaw)
        at = (tcp[0], tcp[1], tcp[2] - below)
        add_tool_object(world, name, tool, Pose(at, upright))
        try:
            gripped = perform(a.motion(type="gripping", gripper=arm))
        except GripperMetOneSide as one_side:  # a tool frame off the fingers' middle
            if one_side.shift is None:
                raise
            dx, dy, dz = one_side.shift  # the hand's way to centre it: the tool the other
            world.set_pose(name, Pose((at[0] - dx, at[1] - dy, at[2] - dz), upright))
            gripped = perform(a.motion(type="gripping", gripper=arm))
        except GripperClosedCompletely:  # short fingers (the HSR's) pass under it: at the frame
            perform(a.motion(type="opening", gripper=arm))
            world.set_pose(name, Pose(tcp, upright))
            gripped = perform(a.motion(type="gripping", gripper=arm))
    if gripped != name:
        raise AssertionError(f"{robot}'s {arm} hand gripped {gripped!r}, not {name!r}")
    return ToolScene(world, scene.robot, arm, (x, y, h))
