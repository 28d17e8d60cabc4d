"""Write URDFs of simple shapes: the builder behind our own HSR and Boxy models.

The robots' real meshes are on no package registry, so every link of our models is one or
a few primitives (box, cylinder, sphere) sized like the real part, with a solid-body
inertia computed from the first shape. Joints carry the real names, origins, axes, limits
and mimic tags; they are written exactly as given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal
from xml.sax.saxutils import quoteattr

Vec3 = tuple[float, float, float]
ZERO: Vec3 = (0.0, 0.0, 0.0)
FRAME_MASS = 0.001  # [kg] of a bare frame, so every simulator sees a positive mass
FRAME_INERTIA = 1e-7  # [kg m^2]
COLORS: dict[str, tuple[float, float, float, float]] = {
    "white": (0.9, 0.9, 0.9, 1.0),
    "grey": (0.5, 0.5, 0.55, 1.0),
    "dark": (0.15, 0.15, 0.17, 1.0),
    "blue": (0.2, 0.35, 0.7, 1.0),
    "orange": (0.9, 0.5, 0.1, 1.0),
}


@dataclass(frozen=True)
class Shape:
    """A primitive at ``xyz``/``rpy`` in its link: box ``dims`` = (x, y, z) extents [m],
    cylinder ``dims`` = (radius, length, 0) along its z axis, sphere ``dims`` = (radius, 0, 0).
    """

    kind: Literal["box", "cylinder", "sphere"]
    dims: Vec3
    xyz: Vec3 = ZERO
    rpy: Vec3 = ZERO

    def geometry_xml(self) -> str:
        """The ``<geometry>`` element of this shape."""
        if self.kind == "box":
            inner = f'<box size="{_v(self.dims)}"/>'
        elif self.kind == "cylinder":
            inner = f'<cylinder radius="{_f(self.dims[0])}" length="{_f(self.dims[1])}"/>'
        else:
            inner = f'<sphere radius="{_f(self.dims[0])}"/>'
        return f"<geometry>{inner}</geometry>"

    def principal_inertia(self, mass: float) -> Vec3:
        """Solid-body inertia [kg m^2] about the shape's own axes, for ``mass`` [kg]."""
        if self.kind == "box":
            x, y, z = self.dims
            return (
                mass * (y * y + z * z) / 12,
                mass * (x * x + z * z) / 12,
                mass * (x * x + y * y) / 12,
            )
        if self.kind == "cylinder":
            r, h, _ = self.dims
            side = mass * (3 * r * r + h * h) / 12
            return (side, side, mass * r * r / 2)
        r = self.dims[0]
        return (2 * mass * r * r / 5,) * 3


def box(x: float, y: float, z: float, xyz: Vec3 = ZERO, rpy: Vec3 = ZERO) -> Shape:
    """A box of extents x, y, z [m]."""
    return Shape("box", (x, y, z), xyz, rpy)


def cylinder(radius: float, length: float, xyz: Vec3 = ZERO, rpy: Vec3 = ZERO) -> Shape:
    """A cylinder along its z axis."""
    return Shape("cylinder", (radius, length, 0.0), xyz, rpy)


def sphere(radius: float, xyz: Vec3 = ZERO) -> Shape:
    """A sphere."""
    return Shape("sphere", (radius, 0.0, 0.0), xyz)


@dataclass(frozen=True)
class Limit:
    """Joint limits: position [rad | m], velocity [rad/s | m/s], effort [N m | N]."""

    lower: float | None
    upper: float | None
    velocity: float
    effort: float


@dataclass(frozen=True)
class MimicTag:
    """``<mimic>``: value = multiplier * master + offset."""

    joint: str
    multiplier: float = 1.0
    offset: float = 0.0


@dataclass
class UrdfBuilder:
    """Collects links and joints in order and writes one URDF document."""

    name: str
    comment: str
    parts: list[str] = field(default_factory=list)

    def link(
        self, name: str, shapes: tuple[Shape, ...] = (), mass: float = 0.0, color: str = "grey"
    ) -> None:
        """Add a link drawn and collided as ``shapes``; inertia from the first shape."""
        body = [_inertial(shapes[0] if shapes else None, mass)]
        for s in shapes:
            origin = _origin(s.xyz, s.rpy)
            body.append(
                f'    <visual>{origin}{s.geometry_xml()}<material name="{color}"/></visual>'
            )
            body.append(f"    <collision>{origin}{s.geometry_xml()}</collision>")
        self.parts.append(f'  <link name="{name}">\n' + "\n".join(body) + "\n  </link>")

    def joint(
        self,
        name: str,
        kind: str,
        parent: str,
        child: str,
        xyz: Vec3 = ZERO,
        rpy: Vec3 = ZERO,
        axis: Vec3 | None = None,
        limit: Limit | None = None,
        mimic: MimicTag | None = None,
    ) -> None:
        """Add a joint; movable joints need ``axis`` and (unless continuous) ``limit``."""
        body = [_origin(xyz, rpy), f'<parent link="{parent}"/>', f'<child link="{child}"/>']
        if axis is not None:
            body.append(f'<axis xyz="{_v(axis)}"/>')
        if limit is not None:
            bounds = ""
            if limit.lower is not None and limit.upper is not None:
                bounds = f'lower="{_f(limit.lower)}" upper="{_f(limit.upper)}" '
            body.append(
                f'<limit {bounds}velocity="{_f(limit.velocity)}" effort="{_f(limit.effort)}"/>'
            )
        if mimic is not None:
            body.append(
                f'<mimic joint="{mimic.joint}" multiplier="{_f(mimic.multiplier)}" '
                f'offset="{_f(mimic.offset)}"/>'
            )
        inner = "\n    ".join(body)
        self.parts.append(f'  <joint name="{name}" type="{kind}">\n    {inner}\n  </joint>')

    def frame(self, name: str, parent: str, joint: str, xyz: Vec3 = ZERO, rpy: Vec3 = ZERO) -> None:
        """Add a bare frame fixed to ``parent`` by the fixed joint ``joint``."""
        self.link(name)
        self.joint(joint, "fixed", parent, name, xyz, rpy)

    def xml(self) -> str:
        """The URDF document."""
        materials = [
            f'  <material name="{n}"><color rgba="{" ".join(_f(c) for c in rgba)}"/></material>'
            for n, rgba in COLORS.items()
        ]
        head = f'<?xml version="1.0"?>\n<!--{self.comment}-->\n<robot name={quoteattr(self.name)}>'
        return "\n".join([head, *materials, *self.parts, "</robot>"]) + "\n"


def _inertial(shape: Shape | None, mass: float) -> str:
    if shape is None or mass <= 0.0:
        i = FRAME_INERTIA
        return (
            f'    <inertial><mass value="{_f(FRAME_MASS)}"/>'
            f'<inertia ixx="{i}" ixy="0" ixz="0" iyy="{i}" iyz="0" izz="{i}"/></inertial>'
        )
    ixx, iyy, izz = shape.principal_inertia(mass)
    return (
        f'    <inertial>{_origin(shape.xyz, shape.rpy)}<mass value="{_f(mass)}"/>'
        f'<inertia ixx="{_f(ixx)}" ixy="0" ixz="0" iyy="{_f(iyy)}" iyz="0" izz="{_f(izz)}"/>'
        "</inertial>"
    )


def _origin(xyz: Vec3, rpy: Vec3) -> str:
    return f'<origin xyz="{_v(xyz)}" rpy="{_v(rpy)}"/>'


def _v(v: Vec3) -> str:
    return " ".join(_f(c) for c in v)


def _f(x: float) -> str:
    if not math.isfinite(x):
        raise ValueError(f"non-finite number {x!r} in a URDF attribute")
    text = f"{x:.10g}"
    return "0" if text == "-0" else text
