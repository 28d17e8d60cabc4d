"""A small tabletop scene: a robot, a table with a mug it can pick from above, a bottle.

Used by the demo, the pick-up example and the projection tests. The placement is worked
out from the robot's description (:mod:`robocram.scenes.placement`), so any robot with a
gripper arm gets a scene; the plan that runs in it is the same for all.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.robots import RobotDescription
from robocram.scenes.handle_turn import turn_handle_to_arm
from robocram.scenes.placement import (
    TABLE_DEPTH,
)
from robocram.scenes.table_robot import robot_at_a_table
from robocram.tf import Pose, PoseStamped
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
    robot's arm works (it stands turned if its arm works sideways, as Stretch's does); the
    mug's handle faces the arm where its hand takes the handle only (``handle_turn.py``).
    A robot whose root is not at its feet stands on the floor; an arm too low for a table
    stands on a pedestal (:mod:`robocram.scenes.standing`). A robot whose fixed camera looks
    onto its own top gets the mug there and no table or bottle (:mod:`~.own_top`).

    Raises:
        UnfitRobotError: the robot has no gripper arm, or it cannot reach past its base.
    """
    world = world if world is not None else World()
    name, place = robot_at_a_table(world, robot)
    height, (mug_x, mug_y), table_x = place.table_height, place.mug_xy, place.table_x
    if not place.on_robot:  # else the mug lies on the robot's own top (scenes/own_top.py)
        world.add_box("table", (TABLE_DEPTH, 1.0, height), pose=Pose((table_x, 0.0, height / 2)))
    mug = world.add_item("mug-1", "mug", pose=Pose((mug_x, mug_y, height)))
    turn_handle_to_arm(world, name, mug)
    if not place.on_robot:
        world.add_item("bottle-1", "bottle", pose=Pose((table_x + 0.15, 0.3, height + 0.125)))
    look_x = place.look_x if place.look_x is not None else mug_x
    return TabletopScene(world, name, PoseStamped("map", (look_x, mug_y, height)))
