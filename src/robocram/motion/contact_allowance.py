"""A contact a trajectory's motion was allowed to make, and how deep it may go.

The planner allows some contacts for one motion (a hand closing round a handle, a held bowl
leaving its table). A trajectory carries them, so whoever checks it later (the trace's
audit, ``robocram runs audit``) honours the same allowance, up to its bound.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.motion.errors import MotionError


@dataclass(frozen=True)
class ContactAllowance:
    """``robot_side`` may touch ``other`` during the motion, penetrating at most ``depth``."""

    robot_side: str  # a robot link, or the name of an object the robot holds
    other: str  # an object name, "object/link" for one link of it, or "*": any object
    depth: float  # [m] the deepest penetration allowed

    def __post_init__(self) -> None:
        if not self.depth >= 0.0:
            raise MotionError(
                f"a contact allowance's depth is a bound in metres >= 0, got {self.depth} "
                f"for {self.robot_side!r} and {self.other!r}"
            )

    def covers(self, robot_side: str, other: str, other_link: str) -> bool:
        """Whether it allows ``robot_side`` against ``other`` (or its link ``other_link``)."""
        return self.robot_side == robot_side and self.other in ("*", other, f"{other}/{other_link}")
