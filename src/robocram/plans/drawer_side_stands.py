"""Stands beside an opened drawer, facing across it: the arm reaches over a side wall.

A drawer's front is its tallest wall and carries the handle; its side walls are low (the
stove's lower drawer: front 0.35 m, sides 0.15 m). An HSR took a bowl lying by that
drawer's left wall with none of its eight rim grasps from any stand in front of the
drawer (arm, wrist and finger links met the drawer; a stand with the shoulder in line
with the rim nearer the middle met the handle). From beside the pulled-out drawer,
facing across it, it takes the bowl over the side wall. These stands are tried only
after every stand in front of the drawer failed.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from robocram.plans.container_access import OpenedContainer
from robocram.plans.environment_links import environment_link_pose
from robocram.plans.known_robot import KnownRobot
from robocram.plans.stands import REACH_DISTANCES, front_stands, yaw_of
from robocram.tf import Pose, PoseStamped

SIDE_SHIFTS = (0.0, 0.1, 0.2)  # [m] from the object towards the drawer's front: a base
# level with the object meets the counter the drawer came out of (refused, no try)


def side_stands(
    robot: KnownRobot, where: PoseStamped, arms: list[str], opened: OpenedContainer
) -> Iterator[tuple[Pose, str | None]]:
    """Stands (map) beside ``opened`` (a drawer) facing across it towards the object seen
    at ``where`` (map), each arm's shoulder in line with the object, :data:`SIDE_SHIFTS`
    towards the drawer's front and :data:`REACH_DISTANCES` sideways from it; the side the
    object lies towards first (its wall is the nearer one to reach over)."""
    out = yaw_of(opened.stand.pose) + math.pi  # the drawer's front faces the opening stand
    across = (-math.sin(out), math.cos(out))  # sideways along the drawer's front
    part = opened.container
    middle = environment_link_pose(part.environment, part.link, "a drawer").position
    x, y, z = where.pose.position
    towards = (x - middle[0]) * across[0] + (y - middle[1]) * across[1]
    near = 1.0 if towards >= 0.0 else -1.0
    for side in (near, -near):
        for shift in SIDE_SHIFTS:
            point = Pose((x + shift * math.cos(out), y + shift * math.sin(out), z))
            for stand in front_stands(
                robot, arms, point, out + side * math.pi / 2, REACH_DISTANCES
            ):
                yield stand.pose, stand.arm
