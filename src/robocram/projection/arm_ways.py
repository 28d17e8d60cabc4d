"""The ways an arm came along, kept so that it can go back along one.

A hand that let a bowl go low in a drawer (Boxy, household 33) had come in on a planned
path that cleared the counter's top by half a millimetre; from the put, the straight
joint segment back dips 18 mm into the top and OMPL finds no way round the narrow
passage. The way it came is known, though: each arm motion projection follows is kept
(its joint waypoints and where the base stood), the last :data:`WAYS_KEPT` per arm, and a
joint goal at the start of one, asked for from its end, may go back along it
(``arm.move_joints`` under ``allow_hand``, after the way planned afresh failed).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from robocram.motion.joint_path import JointPath
from robocram.tf import Pose

if TYPE_CHECKING:
    from robocram.projection.projected_robot import ProjectedRobot

WAYS_KEPT = 4  # per arm: a put's way in has at most two legs (carry, above, put)
AT = 1e-4  # [rad | m] a joint this near a waypoint's value is there
BASE_AT = 1e-6  # [m | quaternion] a base this near where a way was taken stands there


@dataclass(frozen=True)
class ArmWay:
    """The joint waypoints an arm went through, the first where it started, with the base
    standing at ``base`` (map)."""

    base: Pose
    joints: tuple[str, ...]
    waypoints: tuple[tuple[float, ...], ...]

    def back(self) -> tuple[tuple[float, ...], ...]:
        """The waypoints from the end back to the start, the end left out (it is there)."""
        return tuple(reversed(self.waypoints[:-1]))


def remember(robot: ProjectedRobot, arm: str, path: JointPath) -> None:
    """Keep ``path``, just followed by ``arm``, as the arm's newest way."""
    if len(path.waypoints) < 2:
        return
    ways = robot.arm_ways.setdefault(arm, [])
    ways.append(ArmWay(robot.world.pose(robot.name), path.joints, path.waypoints))
    del ways[:-WAYS_KEPT]


def way_back(robot: ProjectedRobot, arm: str, goal: Mapping[str, float]) -> ArmWay | None:
    """``arm``'s newest way that ran from ``goal`` (the same joints) to where the arm is
    now, the base standing where it did; None if no kept way did."""
    base = robot.world.pose(robot.name)
    now = robot.world.joint_states(robot.name)
    for way in reversed(robot.arm_ways.get(arm, [])):
        if set(way.joints) != set(goal) or not _same_base(way.base, base):
            continue
        first, last = way.waypoints[0], way.waypoints[-1]
        if all(
            abs(first[k] - goal[j]) <= AT and abs(last[k] - now[j]) <= AT
            for k, j in enumerate(way.joints)
        ):
            return way
    return None


def _same_base(a: Pose, b: Pose) -> bool:
    return all(abs(x - y) <= BASE_AT for x, y in zip(a.position, b.position, strict=True)) and all(
        abs(x - y) <= BASE_AT for x, y in zip(a.orientation, b.orientation, strict=True)
    )
