"""How a gripper or hand opens and closes: per joint, its open and closed positions.

A parallel gripper needs nothing written: its ``gripper_joints`` open at their upper
limits and close at their lower ones, and URDF ``<mimic>`` followers move with them. A hand
whose fingers the URDF does not couple (a simulator plugin does on the real robot) lists
every finger joint with its open and closed value: all of them move together, each
linearly from closed to open, which is the coupling declared in the description. The first
joint is the master: a ``setting-gripper`` position is a value of that joint.
``max_opening`` [m] is the widest gap between the fingers, what a grasp model compares with
an object's size; left ``None`` it is derived from the URDF at load.

``GripperDescription.curling()`` says the same of a hand without writing its joints out:
every finger joint below the wrist that is straight at 0 curls to its upper limit (the
TIAGo's Hey5 has 29); the joints are found at load, in the URDF's order.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class GripperJoint:
    """One joint of a gripper or hand and where it stands open and closed [rad | m]."""

    name: str
    open: float
    closed: float


@dataclass(frozen=True)
class GripperDescription:
    """The joints of a gripper or hand, moving together from closed to open.

    Attributes:
        joints: the commanded joints, master first; their URDF mimic followers follow.
        max_opening: [m] widest gap between the fingers; ``None``: derived at load.
    """

    joints: tuple[GripperJoint, ...]
    max_opening: float | None = None
    curled_hand: bool = False  # joints left out: the curling joints, found at load

    @property
    def names(self) -> tuple[str, ...]:
        """The joints' names, master first."""
        return tuple(j.name for j in self.joints)

    def at(self, fraction: float) -> dict[str, float]:
        """Joint values [rad | m] at ``fraction`` of the way from closed (0) to open (1)."""
        return {j.name: j.closed + fraction * (j.open - j.closed) for j in self.joints}

    def fraction_of(self, master_value: float) -> float:
        """How far open (0 closed, 1 open) the gripper is with its master at ``master_value``."""
        master = self.joints[0]
        return (master_value - master.closed) / (master.open - master.closed)

    @classmethod
    def curling(cls, max_opening: float | None = None) -> GripperDescription:
        """A hand whose finger joints, straight at 0, curl to their upper limits together.

        The joints (revolute, not ``<mimic>`` followers, lower limit 0 and upper above it,
        below the arm's ``end_effector_link``) are found at load.
        """
        return cls((), max_opening, curled_hand=True)

    @classmethod
    def parallel(cls, joints: tuple[tuple[str, float, float], ...]) -> GripperDescription:
        """A gripper opening at each joint's upper limit and closing at its lower one.

        ``joints`` holds ``(name, lower, upper)`` per joint.
        """
        return cls(tuple(GripperJoint(name, upper, lower) for name, lower, upper in joints))
