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

``GripperDescription.suction()`` is a hand that cannot close: no finger joints, an end
effector fixed to the wrist (a suction cup, a tool flange, a ball). It holds what its tool
frame touches: the grasp brings the tool frame onto the object's surface, gripping
attaches the object there, and opening releases it. It has no opening (``max_opening``
stays ``None``) and no joints to move.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal, get_args

from robocram.robots.errors import DescriptionError

GripperKind = Literal["fingers", "suction"]
"""``fingers``: joints open and close it; ``suction``: it holds what its tool frame touches."""
GRIPPER_KINDS: tuple[str, ...] = get_args(GripperKind)


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
        max_opening: [m] widest gap between the fingers; ``None``: derived at load (a
            suction hand has none).
        kind: ``fingers`` (joints move it) or ``suction`` (fixed, holds what it touches).
    """

    joints: tuple[GripperJoint, ...] = ()
    max_opening: float | None = None
    curled_hand: bool = False  # joints left out: the curling joints, found at load
    kind: GripperKind = "fingers"

    def __post_init__(self) -> None:
        if self.kind not in GRIPPER_KINDS:
            raise DescriptionError(
                f"gripper kind {self.kind!r} is none of {GRIPPER_KINDS}: fingers (joints "
                "open and close it) or suction (it holds what its tool frame touches)"
            )

    @property
    def is_suction(self) -> bool:
        """Whether it holds by touch (no fingers to move, no opening)."""
        return self.kind == "suction"

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
    def suction(cls) -> GripperDescription:
        """A fixed end effector that holds what its tool frame touches (no finger joints).

        The tool frame must sit on the hand's tip, x pointing out of it: a grasp puts that
        point on the object's surface, and nothing of the hand may go into the object.
        """
        return cls((), None, kind="suction")

    @classmethod
    def parallel(cls, joints: tuple[tuple[str, float, float], ...]) -> GripperDescription:
        """A gripper opening at each joint's upper limit and closing at its lower one.

        ``joints`` holds ``(name, lower, upper)`` per joint.
        """
        return cls(tuple(GripperJoint(name, upper, lower) for name, lower, upper in joints))
