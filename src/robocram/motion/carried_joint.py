"""A joint of another object that moves along with a trajectory (a drawer the hand pulls).

Opening a drawer, the hand holds the handle and the drawer's joint follows it: the robot's
trajectory is what is executed, and the drawer moves because the hand moves it. Whoever
replays the trajectory alone (the trace's audit, a viewer) would see the hand push through a
drawer standing still. A trajectory carries the joints it moves this way, with their values
at the start and end of the hand's step.

Between them the joint goes where the hand takes it. A step names the robot's link that
holds the part (``link``, the tool frame) and the line that link travels (``line``: from
where it was to where it goes): at any moment the joint has gone the share of its way that
the link's position has gone along that line. So a step the base drives part of and the arm
the rest moves the part across both trajectories, never back, and a motion that starts and
ends slowly never lets the part run ahead of the hand into the fingers. A joint with no
line moves in proportion to its trajectory's time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from robocram.motion.errors import MotionError
from robocram.tf import Vector3


@dataclass(frozen=True)
class CarriedJoint:
    """``joint`` of ``obj`` goes from ``start`` to ``end`` [m | rad] along the trajectory."""

    obj: str
    joint: str
    start: float
    end: float
    link: str = ""  # the robot's link that holds the part ("": none, by time)
    line: tuple[Vector3, Vector3] | None = None  # [m, map] where ``link`` goes from and to

    def __post_init__(self) -> None:
        if not (math.isfinite(self.start) and math.isfinite(self.end)):
            raise MotionError(
                f"a carried joint's values are finite [m | rad], got {self.start} and "
                f"{self.end} for {self.obj!r}'s {self.joint!r}"
            )

    def at(self, fraction: float) -> float:
        """The joint's value ``fraction`` (0 to 1) of the way from ``start`` to ``end``."""
        share = min(max(fraction, 0.0), 1.0)
        return self.start + (self.end - self.start) * share

    def share(self, position: Vector3) -> float:
        """How far (0 to 1) ``link`` at ``position`` [m, map] has gone along ``line``: the
        share of the way the joint has gone with it."""
        if self.line is None:
            raise MotionError(f"{self.obj!r}'s {self.joint!r} moves by time: it has no line")
        begin, finish = np.asarray(self.line[0]), np.asarray(self.line[1])
        way = finish - begin
        length = float(way @ way)
        if length <= 0.0:
            return 1.0
        return min(max(float((np.asarray(position) - begin) @ way) / length, 0.0), 1.0)
