"""Jumps: a robot's joint or base that changes with no trajectory to move it.

The watch keeps where each robot is known to be: a stored world state says it exactly,
and a trajectory takes the joints it names from its first point to its last. A stored
state whose robot differs from that by more than the tolerance, or a trajectory that
starts elsewhere, is a jump: the robot was put there, not moved (a torso set by
``moving-torso``, grippers and the neck set at once). Mimic joints follow their masters
and are not judged; continuous joints and the base's yaw are compared modulo 2 pi.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping

from robocram.motion import BODY_JOINTS
from robocram.robots import RobotModel
from robocram.tf import Pose
from robocram.tf.quaternion import to_euler
from robocram.traces.audit_findings import AuditFinding, FindingKind, FindingPlace


class TeleportWatch:
    """Where one robot is known to be, and the jumps found on the way."""

    def __init__(self, robot_name: str, model: RobotModel, tolerance: float) -> None:
        self.robot = robot_name
        self.tolerance = tolerance  # [rad | m]
        self.known: dict[str, float] = {}
        self.jumped: set[str] = set()  # the joints (and base joints) of the last jumps
        self._judged = {j.name for j in model.movable_joints() if j.mimic is None}
        self._angles = {j.name for j in model.movable_joints() if j.type == "continuous"}
        self._angles |= {"roll", "pitch", "yaw"}

    def state(
        self, joints: Mapping[str, float], pose: Pose, place: FindingPlace
    ) -> Iterator[AuditFinding]:
        """Jumps to a stored state (its robot's joints and base pose); then it is known."""
        now = {j: v for j, v in joints.items() if j in self._judged}
        now |= dict(zip(BODY_JOINTS, (*pose.position, *to_euler(pose.orientation)), strict=True))
        yield from self._jumps(now, place, "set by a stored state")
        self.known.update(now)

    def trajectory(
        self, start: Mapping[str, float], end: Mapping[str, float], place: FindingPlace
    ) -> Iterator[AuditFinding]:
        """Jumps to a trajectory's first point; then its joints are known at its last."""
        judged = self._judged.union(BODY_JOINTS)
        yield from self._jumps(
            {j: v for j, v in start.items() if j in judged}, place, "where its trajectory starts"
        )
        self.known.update({j: v for j, v in end.items() if j in judged})

    def _jumps(
        self, now: Mapping[str, float], place: FindingPlace, how: str
    ) -> Iterator[AuditFinding]:
        self.jumped = set()
        for joint, value in now.items():
            before = self.known.get(joint)
            if before is None:
                continue
            jump = value - before
            if joint in self._angles:
                jump = math.remainder(jump, math.tau)
            if abs(jump) > self.tolerance:
                self.jumped.add(joint)
                what = f"{self.robot} {_named(joint)} {before:.4f} -> {value:.4f} {how}"
                yield place.finding(FindingKind.TELEPORT, 0.0, what, abs(jump), self.tolerance)


def _named(joint: str) -> str:
    return f"base {joint}" if joint in BODY_JOINTS else f"joint {joint}"
