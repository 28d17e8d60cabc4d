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
from dataclasses import dataclass, field

from robocram.motion.joint_path import JointPath
from robocram.tf import Pose

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

    def runs(self, goal: Mapping[str, float], now: Mapping[str, float], base: Pose) -> bool:
        """Whether this way ran from ``goal`` (the same joints) to ``now`` with the base
        at ``base``."""
        if set(self.joints) != set(goal) or not _same_pose(self.base, base):
            return False
        first, last = self.waypoints[0], self.waypoints[-1]
        return all(
            abs(first[k] - goal[j]) <= AT and abs(last[k] - now[j]) <= AT
            for k, j in enumerate(self.joints)
        )


@dataclass
class ArmWays:
    """Per arm, the ways it came along, newest last."""

    kept: dict[str, list[ArmWay]] = field(default_factory=dict)

    def remember(self, arm: str, base: Pose, path: JointPath) -> None:
        """Keep ``path``, just followed by ``arm`` with the base at ``base``."""
        if len(path.waypoints) < 2:
            return
        ways = self.kept.setdefault(arm, [])
        ways.append(ArmWay(base, path.joints, path.waypoints))
        del ways[:-WAYS_KEPT]

    def back(
        self, arm: str, goal: Mapping[str, float], now: Mapping[str, float], base: Pose
    ) -> ArmWay | None:
        """``arm``'s newest way that ran from ``goal`` to ``now``, the base standing at
        ``base``; None if no kept way did."""
        return next((w for w in reversed(self.kept.get(arm, [])) if w.runs(goal, now, base)), None)


def _same_pose(a: Pose, b: Pose) -> bool:
    return all(
        abs(x - y) <= BASE_AT
        for x, y in zip((*a.position, *a.orientation), (*b.position, *b.orientation), strict=True)
    )
