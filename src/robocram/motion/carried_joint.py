"""A joint of another object that moves along with a trajectory (a drawer the hand pulls).

Opening a drawer, the hand holds the handle and the drawer's joint follows it: the robot's
trajectory is what is executed, and the drawer moves because the hand moves it. Whoever
replays the trajectory alone (the trace's audit, a viewer) would see the hand push through a
drawer standing still. A trajectory carries the joints it moves this way, with their values
at its start and end; between them the joint moves in proportion to the trajectory's time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from robocram.motion.errors import MotionError


@dataclass(frozen=True)
class CarriedJoint:
    """``joint`` of ``obj`` goes from ``start`` to ``end`` [m | rad] along the trajectory."""

    obj: str
    joint: str
    start: float
    end: float

    def __post_init__(self) -> None:
        if not (math.isfinite(self.start) and math.isfinite(self.end)):
            raise MotionError(
                f"a carried joint's values are finite [m | rad], got {self.start} and "
                f"{self.end} for {self.obj!r}'s {self.joint!r}"
            )

    def at(self, fraction: float) -> float:
        """The joint's value ``fraction`` (0 to 1) of the way through the trajectory."""
        share = min(max(fraction, 0.0), 1.0)
        return self.start + (self.end - self.start) * share
