"""A robot placed to work at a table in front of it: the tabletop scene's and the
workcell's first steps, shared so both stand a robot the same way."""

from __future__ import annotations

from robocram.robots import RobotDescription, load_description
from robocram.scenes.placement import (
    TabletopPlacement,
    facing_yaw,
    placement_arm,
    table_height,
    tabletop_placement,
)
from robocram.scenes.scene_robot import place_robot
from robocram.scenes.standing import LOWEST_TABLE, PEDESTAL_TABLE, stand_on_a_pedestal
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World


def robot_at_a_table(world: World, robot: str | RobotDescription) -> tuple[str, TabletopPlacement]:
    """Floor, ``robot`` at the origin turned to where its arm works (a sideways arm's
    robot stands turned), on a pedestal if its arm is too low for a table; its object
    name and where a table and a mug go in front of it.

    Raises:
        UnfitRobotError: the robot has no gripper arm, or it cannot reach past its base.
    """
    desc = load_description(robot)
    world.bodies.add_floor()
    turned = quat.from_euler(0.0, 0.0, facing_yaw(desc))
    name = place_robot(world, desc, Pose((0.0, 0.0, 0.0), turned))
    arm = placement_arm(world.robot(name).description)
    if arm is not None and table_height(world, name, arm) < LOWEST_TABLE:
        stand_on_a_pedestal(world, name, PEDESTAL_TABLE - table_height(world, name, arm))
    return name, tabletop_placement(world, name)
