"""Read URDF XML into links and joints, resolving mesh URIs to absolute paths.

A mesh whose package resolves but whose file is missing becomes a box spanning the link's
joints (``robots/stand_in_size.py``), marked with the mesh it stands in for; the caller
warns once per model.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path

from robocram.robots.errors import PackageNotFoundError, UrdfError, closest_names
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.safe_xml import XmlNode
from robocram.robots.stand_in_size import StandInBox, is_stand_in, stand_in_boxes
from robocram.robots.urdf_elements import (
    JOINT_TYPES,
    Collision,
    Geometry,
    Inertial,
    Joint,
    Link,
    Mimic,
    Visual,
)
from robocram.tf import Pose

_DEFAULT_BOX = 0.05  # [m] edge of a stand-in box when nothing tells the link's size
_MIN_AXIS = 1e-9  # a joint axis shorter than this has no direction
# Mesh formats PyBullet or trimesh read: a mesh named otherwise (../../etc/passwd) is refused
MESH_SUFFIXES = frozenset({".stl", ".dae", ".obj", ".ply", ".off", ".glb", ".gltf", ".3mf"})


@dataclass
class UrdfParts:
    """What one URDF document holds, before it becomes a ``RobotModel``."""

    name: str
    links: dict[str, Link]
    joints: dict[str, Joint]
    missing_meshes: list[str] = field(default_factory=list)
    missing_packages: list[str] = field(default_factory=list)
    dangling_mimics: list[tuple[str, str]] = field(default_factory=list)  # (joint, its target)
    # what each mesh reference was found to be: (uri, the path it resolved to or None for
    # a package found nowhere, whether a file is there); the parts hold while these do
    mesh_checks: list[tuple[str, str | None, bool]] = field(default_factory=list)


@dataclass
class _Reader:
    source: str
    base_dir: Path | None
    resolver: PackageResolver
    missing_packages_as_boxes: bool = False
    missing_meshes: list[str] = field(default_factory=list)
    missing_packages: list[str] = field(default_factory=list)
    colors: dict[str, tuple[float, ...]] = field(default_factory=dict)  # named materials
    stand_in_boxes: dict[str, StandInBox] = field(default_factory=dict)  # by link
    mesh_checks: list[tuple[str, str | None, bool]] = field(default_factory=list)

    def fail(self, node: XmlNode, problem: str) -> UrdfError:
        return UrdfError(self.source, problem, node.line)

    def attr(self, node: XmlNode, key: str) -> str:
        if key not in node.attrib:
            raise self.fail(node, f"<{node.tag}> lacks the required attribute {key!r}")
        return node.attrib[key]

    def floats(
        self, node: XmlNode | None, key: str, default: tuple[float, ...]
    ) -> tuple[float, ...]:
        if node is None or key not in node.attrib:
            return default
        try:
            values = tuple(float(v) for v in node.attrib[key].split())
        except ValueError as err:
            raise self.fail(node, f"{key}={node.attrib[key]!r} is not numbers") from err
        if len(values) != len(default):
            raise self.fail(node, f"{key}={node.attrib[key]!r} needs {len(default)} numbers")
        if not all(math.isfinite(v) for v in values):
            raise self.fail(node, f"{key}={node.attrib[key]!r} is not finite; give real numbers")
        return values

    def number(self, node: XmlNode | None, key: str, default: float | None) -> float | None:
        if node is None or key not in node.attrib:
            return default
        return self.floats(node, key, (0.0,))[0]

    def origin(self, node: XmlNode) -> Pose:
        origin = node.find("origin")
        xyz = self.floats(origin, "xyz", (0.0, 0.0, 0.0))
        rpy = self.floats(origin, "rpy", (0.0, 0.0, 0.0))
        return Pose.from_xyz_rpy(xyz, rpy)

    def geometry(self, node: XmlNode, stand_in: Callable[[str], Geometry]) -> Geometry:
        geom = node.find("geometry")
        shape = geom.children[0] if geom is not None and geom.children else None
        if shape is None:
            raise self.fail(node, f"<{node.tag}> has no <geometry> shape")
        if shape.tag == "box":
            return Geometry("box", size=self.floats(shape, "size", (0.0, 0.0, 0.0)))  # type: ignore[arg-type]
        if shape.tag == "cylinder":
            radius, length = self.number(shape, "radius", 0.0), self.number(shape, "length", 0.0)
            return Geometry("cylinder", radius=radius or 0.0, length=length or 0.0)
        if shape.tag == "sphere":
            return Geometry("sphere", radius=self.number(shape, "radius", 0.0) or 0.0)
        if shape.tag == "mesh":
            return self.mesh(shape, stand_in)
        if shape.tag == "capsule":  # its middle; the caps come from :meth:`capsule_caps`
            radius, length = self.number(shape, "radius", 0.0), self.number(shape, "length", 0.0)
            return Geometry("cylinder", radius=radius or 0.0, length=length or 0.0)
        raise self.fail(
            shape, f"unknown geometry <{shape.tag}>; use box, cylinder, capsule, sphere or mesh"
        )

    def capsule_caps(self, node: XmlNode) -> tuple[tuple[Geometry, Pose], ...]:
        """The two spheres ending a ``<capsule>`` (a cylinder along z with round ends, as
        PyBullet and Gazebo read it), in the element's frame; none for other shapes."""
        geom = node.find("geometry")
        shape = geom.children[0] if geom is not None and geom.children else None
        if shape is None or shape.tag != "capsule":
            return ()
        radius = self.number(shape, "radius", 0.0) or 0.0
        half = (self.number(shape, "length", 0.0) or 0.0) / 2
        ball = Geometry("sphere", radius=radius)
        return ((ball, Pose((0.0, 0.0, half))), (ball, Pose((0.0, 0.0, -half))))

    def mesh(self, shape: XmlNode, stand_in: Callable[[str], Geometry]) -> Geometry:
        uri = self.attr(shape, "filename")
        try:
            path = self.resolver.resolve(uri, self.base_dir)
        except PackageNotFoundError as err:
            if not self.missing_packages_as_boxes:
                raise
            self.missing_packages.append(err.package)
            self.mesh_checks.append((uri, None, False))
            return stand_in(uri)
        if path.suffix.lower() not in MESH_SUFFIXES:
            raise self.fail(
                shape,
                f"mesh {uri!r} is no mesh file; give one of {', '.join(sorted(MESH_SUFFIXES))}",
            )
        is_file = path.is_file()
        self.mesh_checks.append((uri, str(path), is_file))
        if not is_file:
            self.missing_meshes.append(uri)
            return stand_in(uri)
        scale = self.floats(shape, "scale", (1.0, 1.0, 1.0))
        return Geometry("mesh", filename=str(path), scale=scale)  # type: ignore[arg-type]

    def inertial(self, node: XmlNode) -> Inertial | None:
        inertial = node.find("inertial")
        if inertial is None:
            return None
        mass = self.number(inertial.find("mass"), "value", 0.0) or 0.0
        tensor = inertial.find("inertia")
        keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
        values = tuple(self.number(tensor, k, 0.0) or 0.0 for k in keys)
        return Inertial(mass, values, self.origin(inertial))  # type: ignore[arg-type]

    def link(self, node: XmlNode) -> Link:
        inertial = self.inertial(node)
        name = self.attr(node, "name")
        box = self.stand_in_boxes.get(name)
        shapes = [
            self.primitive_extents(n) for n in node.findall("visual") + node.findall("collision")
        ]
        extents = next((e for e in shapes if e), None)

        def stand_in(uri: str) -> Geometry:
            """From the kinematics (``robots/stand_in_size.py``); a link no joint names: its
            other shapes' size, else a small cube. Never from the inertia."""
            if box is not None:
                return box.geometry(uri)
            return Geometry("box", size=extents or (_DEFAULT_BOX,) * 3, filename=uri)

        def placed(element: XmlNode, geometry: Geometry) -> Pose:
            if box is not None and is_stand_in(geometry):
                return box.centre  # the box spans the link's joints, whatever the mesh's origin
            return self.origin(element)

        visuals = tuple(
            shape
            for v in node.findall("visual")
            for shape in (
                self.visual(v, stand_in, placed),
                *(
                    Visual(ball, self.origin(v) * at, v.attrib.get("name"))
                    for ball, at in self.capsule_caps(v)
                ),
            )
        )
        collisions = tuple(
            shape
            for c in node.findall("collision")
            for shape in (
                self.collision(c, stand_in, placed),
                *(
                    Collision(ball, self.origin(c) * at, c.attrib.get("name"))
                    for ball, at in self.capsule_caps(c)
                ),
            )
        )
        return Link(name, visuals, collisions, inertial)

    def collision(
        self,
        node: XmlNode,
        stand_in: Callable[[str], Geometry],
        placed: Callable[[XmlNode, Geometry], Pose],
    ) -> Collision:
        geometry = self.geometry(node, stand_in)
        return Collision(geometry, placed(node, geometry), node.attrib.get("name"))

    def primitive_extents(self, node: XmlNode) -> tuple[float, float, float] | None:
        geom = node.find("geometry")
        if geom is None or not geom.children or geom.children[0].tag == "mesh":
            return None
        return self.geometry(node, lambda _: Geometry("box")).extents()

    def visual(
        self,
        node: XmlNode,
        stand_in: Callable[[str], Geometry],
        placed: Callable[[XmlNode, Geometry], Pose],
    ) -> Visual:
        material = node.find("material")
        name = material.attrib.get("name") if material is not None else None
        color = material.find("color") if material is not None else None
        rgba = self.floats(color, "rgba", (0.0,) * 4) if color is not None else None
        if rgba is None and name is not None:
            rgba = self.colors.get(name)
        geometry = self.geometry(node, stand_in)
        return Visual(geometry, placed(node, geometry), node.attrib.get("name"), name, rgba)  # type: ignore[arg-type]

    def joint(self, node: XmlNode) -> Joint:
        name, kind = self.attr(node, "name"), self.attr(node, "type")
        if kind not in JOINT_TYPES:
            raise self.fail(
                node, f"joint {name!r} has unknown type {kind!r}; use one of {JOINT_TYPES}"
            )
        parent, child = node.find("parent"), node.find("child")
        if parent is None or child is None:
            raise self.fail(
                node, f"joint {name!r} needs a <parent link=...> and a <child link=...>"
            )
        limit, dynamics, mimic = node.find("limit"), node.find("dynamics"), node.find("mimic")
        safety = node.find("safety_controller")
        lower, upper = joint_limits(
            kind, self.number(limit, "lower", 0.0), self.number(limit, "upper", 0.0)
        )
        if kind in ("revolute", "prismatic") and limit is None:
            raise self.fail(node, f"{kind} joint {name!r} needs a <limit lower=... upper=...>")
        self.check_limits(limit, name, lower, upper)
        axis = self.floats(node.find("axis"), "xyz", (1.0, 0.0, 0.0))
        if kind not in ("fixed", "floating") and math.hypot(*axis) < _MIN_AXIS:
            raise self.fail(
                node.find("axis") or node, f"joint {name!r} has a zero axis; give a direction"
            )
        return Joint(
            name=name,
            type=kind,  # type: ignore[arg-type]
            parent=self.attr(parent, "link"),
            child=self.attr(child, "link"),
            origin=self.origin(node),
            axis=axis,  # type: ignore[arg-type]
            lower=lower,
            upper=upper,
            velocity=self.number(limit, "velocity", None),
            effort=self.number(limit, "effort", None),
            mimic=None if mimic is None else self.mimic(mimic),
            damping=self.number(dynamics, "damping", 0.0) or 0.0,
            friction=self.number(dynamics, "friction", 0.0) or 0.0,
            soft_lower=self.number(safety, "soft_lower_limit", None),
            soft_upper=self.number(safety, "soft_upper_limit", None),
        )

    def check_limits(
        self, limit: XmlNode | None, name: str, lower: float | None, upper: float | None
    ) -> None:
        """Refuse crossed limits and negative speed or effort, naming the line."""
        if limit is None:
            return
        if lower is not None and upper is not None and lower > upper:
            raise self.fail(limit, f"joint {name!r} has lower limit {lower} > upper {upper}")
        for key in ("velocity", "effort"):
            value = self.number(limit, key, None)
            if value is not None and value < 0:
                raise self.fail(limit, f"joint {name!r} has negative {key} {value}; use >= 0")

    def mimic(self, node: XmlNode) -> Mimic:
        return Mimic(
            self.attr(node, "joint"),
            self.number(node, "multiplier", 1.0) or 0.0,
            self.number(node, "offset", 0.0) or 0.0,
        )


def joint_limits(
    kind: str, lower: float | None, upper: float | None
) -> tuple[float | None, float | None]:
    """Limits as the model keeps them: -inf/inf for continuous, ``None`` for multi-DOF/fixed."""
    if kind == "continuous":
        return -math.inf, math.inf
    if kind in ("revolute", "prismatic"):
        return lower, upper
    return None, None


def read_urdf(
    root: XmlNode,
    source: str,
    base_dir: Path | None,
    resolver: PackageResolver,
    missing_packages_as_boxes: bool = False,
) -> UrdfParts:
    """Links and joints of a ``<robot>`` element; duplicate names raise :class:`UrdfError`.

    ``missing_packages_as_boxes``: a mesh in a package found nowhere gets a box, as a
    missing file does, instead of :class:`PackageNotFoundError`.
    """
    if root.tag != "robot":
        raise UrdfError(source, f"root element is <{root.tag}>, a URDF needs <robot>", root.line)
    reader = _Reader(source, base_dir, resolver, missing_packages_as_boxes)
    for material in root.findall("material"):
        color = material.find("color")
        if color is not None and "name" in material.attrib:
            reader.colors[material.attrib["name"]] = reader.floats(color, "rgba", (0.0,) * 4)
    links: dict[str, Link] = {}
    joints: dict[str, Joint] = {}
    for node in root.findall("joint"):
        joint = reader.joint(node)
        if joint.name in joints:
            raise reader.fail(node, f"joint {joint.name!r} is defined twice")
        joints[joint.name] = joint
    dangling = [
        (n, j.mimic.joint) for n, j in joints.items() if j.mimic and j.mimic.joint not in joints
    ]
    for joint_name, _ in dangling:
        joints[joint_name] = replace(joints[joint_name], mimic=None)
    bodied = {
        node.attrib.get("name", "")
        for node in root.findall("link")
        if node.findall("visual") or node.findall("collision")
    }
    reader.stand_in_boxes = stand_in_boxes(joints, bodied)
    for node in root.findall("link"):
        link = reader.link(node)
        if link.name in links:
            raise reader.fail(node, f"link {link.name!r} is defined twice")
        links[link.name] = link
    for node in root.findall("joint"):
        joint = joints[node.attrib["name"]]
        for role, link_name in (("parent", joint.parent), ("child", joint.child)):
            if link_name not in links:
                hint = _did_you_mean(link_name, links)
                raise reader.fail(
                    node,
                    f"joint {joint.name!r} has {role} link {link_name!r}, "
                    f"which the URDF does not define{hint}",
                )
    name = reader.attr(root, "name")
    return UrdfParts(
        name,
        links,
        joints,
        reader.missing_meshes,
        reader.missing_packages,
        dangling,
        reader.mesh_checks,
    )


def _did_you_mean(name: str, candidates: dict[str, Link]) -> str:
    close = closest_names(name, candidates)
    return f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
