"""Write a robot model back to URDF XML that PyBullet and pinocchio load as is.

Mesh filenames are absolute paths, so the file works from any folder; stand-in boxes of
missing meshes are ordinary boxes. Transmissions and simulator tags are not kept.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterable

from robocram.robots.urdf_elements import Geometry, Inertial, Joint, Link
from robocram.tf import Pose


def _num(value: float) -> str:
    return repr(float(value))


def _nums(values: Iterable[float]) -> str:
    return " ".join(_num(v) for v in values)


def _origin(parent: ET.Element, pose: Pose) -> None:
    ET.SubElement(parent, "origin", xyz=_nums(pose.position), rpy=_nums(pose.rpy()))


def _geometry(parent: ET.Element, geometry: Geometry) -> None:
    node = ET.SubElement(parent, "geometry")
    if geometry.kind == "box":
        ET.SubElement(node, "box", size=_nums(geometry.size))
    elif geometry.kind == "cylinder":
        ET.SubElement(node, "cylinder", radius=_num(geometry.radius), length=_num(geometry.length))
    elif geometry.kind == "sphere":
        ET.SubElement(node, "sphere", radius=_num(geometry.radius))
    else:
        ET.SubElement(node, "mesh", filename=geometry.filename, scale=_nums(geometry.scale))


def _inertial(parent: ET.Element, inertial: Inertial) -> None:
    node = ET.SubElement(parent, "inertial")
    _origin(node, inertial.origin)
    ET.SubElement(node, "mass", value=_num(inertial.mass))
    keys = ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")
    ET.SubElement(
        node, "inertia", {k: _num(v) for k, v in zip(keys, inertial.inertia, strict=True)}
    )


def _link(root: ET.Element, link: Link) -> None:
    node = ET.SubElement(root, "link", name=link.name)
    if link.inertial is not None:
        _inertial(node, link.inertial)
    for visual in link.visuals:
        v = ET.SubElement(node, "visual", {"name": visual.name} if visual.name else {})
        _origin(v, visual.origin)
        _geometry(v, visual.geometry)
        if visual.rgba is not None:
            material = ET.SubElement(v, "material", name=visual.material or f"{link.name}_color")
            ET.SubElement(material, "color", rgba=_nums(visual.rgba))
    for collision in link.collisions:
        c = ET.SubElement(node, "collision", {"name": collision.name} if collision.name else {})
        _origin(c, collision.origin)
        _geometry(c, collision.geometry)


def _joint(root: ET.Element, joint: Joint) -> None:
    node = ET.SubElement(root, "joint", name=joint.name, type=joint.type)
    _origin(node, joint.origin)
    ET.SubElement(node, "parent", link=joint.parent)
    ET.SubElement(node, "child", link=joint.child)
    if joint.type != "fixed":
        ET.SubElement(node, "axis", xyz=_nums(joint.axis))
    limit: dict[str, str] = {}
    if joint.lower is not None and math.isfinite(joint.lower):
        limit["lower"] = _num(joint.lower)
    if joint.upper is not None and math.isfinite(joint.upper):
        limit["upper"] = _num(joint.upper)
    if joint.velocity is not None:
        limit["velocity"] = _num(joint.velocity)
    if joint.effort is not None:
        limit["effort"] = _num(joint.effort)
    if limit and joint.type != "fixed":
        ET.SubElement(node, "limit", limit)
    if joint.damping or joint.friction:
        ET.SubElement(node, "dynamics", damping=_num(joint.damping), friction=_num(joint.friction))
    if joint.mimic is not None:
        m = joint.mimic
        attrs = {"joint": m.joint, "multiplier": _num(m.multiplier), "offset": _num(m.offset)}
        ET.SubElement(node, "mimic", attrs)


def write_urdf(name: str, links: Iterable[Link], joints: Iterable[Joint]) -> str:
    """URDF XML text of the links and joints, indented, with an XML declaration."""
    root = ET.Element("robot", name=name)
    for link in links:
        _link(root, link)
    for joint in joints:
        _joint(root, joint)
    ET.indent(root)
    return '<?xml version="1.0"?>\n' + ET.tostring(root, encoding="unicode") + "\n"
