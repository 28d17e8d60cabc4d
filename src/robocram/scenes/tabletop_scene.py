"""A small tabletop scene: a robot, a table with a mug it can pick from above, a bottle.

Used by the demo, the pick-up example and the projection tests. The placement is worked
out from the robot's description (:mod:`robocram.scenes.placement`), so any robot with a
gripper arm gets a scene; the plan that runs in it is the same for all.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots import RobotDescription, load_description
from robocram.scenes.placement import (
    TABLE_DEPTH,
    facing_yaw,
    placement_arm,
    table_height,
    tabletop_placement,
)
from robocram.scenes.scene_robot import place_robot
from robocram.scenes.standing import (
    LOWEST_TABLE,
    PEDESTAL_TABLE,
    stand_on_a_pedestal,
)
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import World


@dataclass(frozen=True)
class TabletopScene:
    """A robot and a table with a mug, and the point on the table to look at (map)."""

    world: World
    robot: str
    look_target: PoseStamped


def tabletop_scene(robot: str | RobotDescription, world: World | None = None) -> TabletopScene:
    """Floor, ``robot`` (a name, a description file or a description) at the origin, arms
    parked, a table with a mug and a bottle in front of it: along the map's x, where the
    robot's arm works (it stands turned if its arm works sideways, as Stretch's does).
    A robot whose root is not at its feet stands on the floor; an arm too low for a table
    stands on a pedestal (:mod:`robocram.scenes.standing`).

    Raises:
        UnfitRobotError: the robot has no gripper arm, or it cannot reach past its base.
    """
    desc = load_description(robot)
    world = world if world is not None else World()
    world.bodies.add_floor()
    turned = quat.from_euler(0.0, 0.0, facing_yaw(desc))
    name = place_robot(world, desc, Pose((0.0, 0.0, 0.0), turned))
    arm = placement_arm(world.robot(name).description)
    if arm is not None and table_height(world, name, arm) < LOWEST_TABLE:
        stand_on_a_pedestal(world, name, PEDESTAL_TABLE - table_height(world, name, arm))
    place = tabletop_placement(world, name)
    height, (mug_x, mug_y), table_x = place.table_height, place.mug_xy, place.table_x
    world.add_box("table", (TABLE_DEPTH, 1.0, height), pose=Pose((table_x, 0.0, height / 2)))
    world.add_item("mug-1", "mug", pose=Pose((mug_x, mug_y, height)))
    world.add_item("bottle-1", "bottle", pose=Pose((table_x + 0.15, 0.3, height + 0.125)))
    return TabletopScene(world, name, PoseStamped("map", (mug_x, mug_y, height)))
