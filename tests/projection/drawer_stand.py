"""The PR2 parked in front of the bowl's drawer: the start of the drawer tests."""

from __future__ import annotations

import math

from robocram.projection import ProjectedRobot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DRAWER = "drawer_unit_drawer_3"  # the bowl's drawer, front at y = 1.9 m, bar handle 2 cm thick
FACING_NORTH = quat.from_euler(0.0, 0.0, math.pi / 2)


def pr2_before_drawer(aside: float, y: float) -> tuple[KitchenScene, ProjectedRobot]:
    """A fresh kitchen with the PR2's arms parked, standing at ``y`` [m] facing the drawer,
    ``aside`` [m] to the west of its handle (0.19: the right arm in line with it)."""
    scene = kitchen_scene("pr2")
    world = scene.world
    desc = world.robot(scene.robot).description
    world.set_joint_states(
        scene.robot, {j: v for a in desc.arms.values() for j, v in a.parking.items()}
    )
    handle_x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
    world.set_pose(scene.robot, Pose((handle_x - aside, y, 0.0), FACING_NORTH))
    return scene, ProjectedRobot.of(world, scene.robot)
