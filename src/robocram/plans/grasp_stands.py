"""Stands in front of an opened container facing a grasp's point, not the object's middle.

A bowl is gripped by its rim, 8 cm off its middle. Standing with its arm's shoulder in
line with the middle of the bowl beside a drawer's side wall, Boxy reached neither rim:
the near one put the hand into the wall, and lifting the far one out of the drawer was
beyond the arm sideways (IK reaches that lift 0.75-0.85 m ahead only with the hand in
front of the base's middle). So these stands face each grasp point aside of the middle
with the base's middle, and either arm may take it there. They are tried only after the
stands in line with the object's middle failed.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from robocram.designators import ObjectDesignator, an
from robocram.plans.container_access import OpenedContainer
from robocram.plans.grasp_failures import ObjectUngraspable
from robocram.plans.known_robot import KnownRobot
from robocram.plans.pick_object import grasp_choices, object_spec
from robocram.plans.stands import REACH_DISTANCES, planar_pose, yaw_of
from robocram.tf import Pose, PoseStamped

ASIDE = 0.01  # [m] grasp points nearer than this sideways count as one line


def grasp_point_stands(
    robot: KnownRobot,
    seen: ObjectDesignator,
    where: PoseStamped,
    arms: list[str],
    opened: OpenedContainer,
) -> Iterator[tuple[Pose, str | None]]:
    """Stands (map) facing ``opened``'s front with the base's middle in line with one of
    the grasp points (by any of ``arms``) of the object seen at ``where`` (map) that lie
    aside of its middle, :data:`REACH_DISTANCES` away; the arm to use there (None: any)."""
    out = yaw_of(opened.stand.pose) + math.pi  # the container's front faces the stand
    facing = out + math.pi
    across = (-math.sin(out), math.cos(out))  # sideways along the container's front
    cx, cy, _ = where.pose.position
    _, spec, _ = object_spec(an.object(type=seen.get("type"), name=seen.get("name"), pose=where))
    lines: list[float] = [0.0]  # the middle's line: its stands were tried already
    for arm in arms:
        try:
            choices = grasp_choices(robot, spec, arm, None)
        except ObjectUngraspable:
            continue
        for choice in choices:
            x, y, _ = choice.grasp_pose.position
            side = (x - cx) * across[0] + (y - cy) * across[1]
            if any(abs(side - line) < ASIDE for line in lines):
                continue
            lines.append(side)
    use = arms[0] if len(arms) == 1 else None
    for side in lines[1:]:
        px, py = cx + side * across[0], cy + side * across[1]
        for distance in REACH_DISTANCES:
            stand = (px + math.cos(out) * distance, py + math.sin(out) * distance)
            yield planar_pose(stand[0], stand[1], facing), use
