"""Scenes for the tool action tests: a tabletop with the objects, the tool in the hand."""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.designators import a
from robocram.execution import perform
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose
from robocram.world import World

DOWN = (0.0, math.sin(math.pi / 4), 0.0, math.cos(math.pi / 4))  # a tool frame's x down
UPRIGHT_IN_DOWN = (0.0, -math.sin(math.pi / 4), 0.0, math.cos(math.pi / 4))
# how each tool sits in a tool frame: (where the hand goes, over the work; object in tcp)
GRIPS = {
    "spoon": ((-0.05, 0.0, 0.3), DOWN, Pose((0.13, 0.0, 0.0), UPRIGHT_IN_DOWN)),
    "sponge": ((-0.05, 0.0, 0.2), DOWN, Pose((0.01, 0.0, 0.0), UPRIGHT_IN_DOWN)),
    "knife": ((-0.2, 0.0, 0.25), DOWN, Pose((0.0, 0.0, 0.0), UPRIGHT_IN_DOWN)),
    "cup": ((-0.15, -0.05, 0.2), (0.0, 0.0, 0.0, 1.0), Pose((0.0, 0.0, -0.05))),
}


@dataclass(frozen=True)
class ToolScene:
    """A tabletop world, the robot, the arm holding the tool, and the work's spot (map)."""

    world: World
    robot: str
    arm: str
    spot: tuple[float, float, float]  # [m] on the table top, where the work lies


def tool_scene(robot: str, tool: str, arm: str = "right") -> ToolScene:
    """A tabletop for ``robot`` without its mug and bottle; ``arm`` has gripped a
    ``tool`` (``<tool>-1``) put between its open fingers, over the table."""
    scene = tabletop_scene(robot)
    world = scene.world
    world.remove("mug-1")
    world.remove("bottle-1")
    x, y, h = scene.look_target.pose.position
    offset, down, object_in_tcp = GRIPS[tool]
    name = f"{tool}-1"
    with simulated_robot(world, scene.robot):
        perform(a.motion(type="moving-torso", joint_angle=0.2))
        target = Pose((x + offset[0], y + offset[1], h + offset[2]), down)
        perform(a.motion(type="moving-tcp", arm=arm, target=target))
        perform(a.motion(type="opening", gripper=arm))
        spec = world.robot(scene.robot).description.arms[arm]
        tcp = world.link_pose(scene.robot, spec.tool_frame)
        add_tool_object(world, name, tool, tcp * object_in_tcp)
        gripped = perform(a.motion(type="gripping", gripper=arm))
    if gripped != name:
        raise AssertionError(f"{robot}'s {arm} hand gripped {gripped!r}, not {name!r}")
    return ToolScene(world, scene.robot, arm, (x, y, h))
