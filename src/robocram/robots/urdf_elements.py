"""The parts of a URDF model: joints, links, their geometry and inertia, as frozen values.

Joint limits: revolute and prismatic joints carry their URDF limits; continuous joints
have ``lower = -inf`` and ``upper = inf``; fixed, floating and planar joints have ``None``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from robocram.tf import Pose

JointType = Literal["revolute", "continuous", "prismatic", "fixed", "floating", "planar"]
JOINT_TYPES: tuple[str, ...] = (
    "revolute",
    "continuous",
    "prismatic",
    "fixed",
    "floating",
    "planar",
)
MOVABLE_TYPES: tuple[str, ...] = ("revolute", "continuous", "prismatic")
GeometryKind = Literal["box", "cylinder", "sphere", "mesh"]


@dataclass(frozen=True)
class Geometry:
    """A shape: a box (``size``), cylinder (``radius``, ``length``), sphere or mesh file."""

    kind: GeometryKind
    size: tuple[float, float, float] = (0.0, 0.0, 0.0)  # [m] box extents
    radius: float = 0.0  # [m]
    length: float = 0.0  # [m]
    filename: str = ""  # absolute path of a mesh
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def extents(self) -> tuple[float, float, float] | None:
        """Size [m] of the shape's bounding box, or ``None`` for a mesh (unknown without it)."""
        if self.kind == "box":
            return self.size
        if self.kind == "cylinder":
            return (2 * self.radius, 2 * self.radius, self.length)
        if self.kind == "sphere":
            return (2 * self.radius,) * 3
        return None


@dataclass(frozen=True)
class Visual:
    """A shape drawn for a link, at ``origin`` in the link frame."""

    geometry: Geometry
    origin: Pose = Pose()
    name: str | None = None
    material: str | None = None
    rgba: tuple[float, float, float, float] | None = None


@dataclass(frozen=True)
class Collision:
    """A shape used for contact, at ``origin`` in the link frame."""

    geometry: Geometry
    origin: Pose = Pose()
    name: str | None = None


@dataclass(frozen=True)
class Inertial:
    """Mass [kg] and inertia tensor [kg m^2] (ixx, ixy, ixz, iyy, iyz, izz) at ``origin``."""

    mass: float
    inertia: tuple[float, float, float, float, float, float]
    origin: Pose = Pose()


@dataclass(frozen=True)
class Link:
    """A rigid body (or a bare frame when it has no shapes and no inertia)."""

    name: str
    visuals: tuple[Visual, ...] = ()
    collisions: tuple[Collision, ...] = ()
    inertial: Inertial | None = None


@dataclass(frozen=True)
class Mimic:
    """This joint follows ``joint``: value = multiplier * master value + offset."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass(frozen=True)
class Joint:
    """A joint from ``parent`` link to ``child`` link, at ``origin`` in the parent frame.

    ``lower``/``upper`` are [rad] or [m]; continuous joints have -inf/inf and fixed,
    floating or planar joints ``None``. ``velocity`` [rad/s | m/s] and ``effort``
    [N m | N] are ``None`` when the URDF gives none. ``soft_lower``/``soft_upper`` are the
    ``<safety_controller>`` soft limits, ``None`` without one: a real robot's controllers
    (the PR2's) stop the joint there, so :attr:`working_limits` is what IK may use.
    """

    name: str
    type: JointType
    parent: str
    child: str
    origin: Pose = Pose()
    axis: tuple[float, float, float] = (1.0, 0.0, 0.0)
    lower: float | None = None
    upper: float | None = None
    velocity: float | None = None
    effort: float | None = None
    mimic: Mimic | None = None
    damping: float = 0.0
    friction: float = 0.0
    soft_lower: float | None = None
    soft_upper: float | None = None

    @property
    def working_limits(self) -> tuple[float | None, float | None]:
        """The soft limits where the URDF has them (inside the hard ones), else the hard."""
        lower, upper = self.lower, self.upper
        if self.soft_lower is not None and lower is not None:
            lower = max(lower, self.soft_lower)
        if self.soft_upper is not None and upper is not None:
            upper = min(upper, self.soft_upper)
        if lower is not None and upper is not None and lower > upper:
            return self.lower, self.upper  # soft limits that cross are ignored
        return lower, upper

    @property
    def movable(self) -> bool:
        """Whether the joint has one degree of freedom a joint state can set."""
        return self.type in MOVABLE_TYPES
