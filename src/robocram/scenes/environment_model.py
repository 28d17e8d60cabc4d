"""An environment URDF's links, joints and collision boxes, and their poses at any joint values.

Read for drafting (:mod:`robocram.scenes.environment_draft`): only the tree, the joints'
origins, axes and limits, and the collision shapes' sizes matter. Mesh URIs are found as
the robots' are (``package_paths``, ``ROS_PACKAGE_PATH``, a package beside the URDF,
relative paths); a mesh found counts as the box of its vertices' bounds, so surfaces and
their sizes come from the meshes. A mesh not found has no size: the draft says so where it
matters, and its stand-ins guess one.
"""

from __future__ import annotations

import hashlib
import math
import tempfile
import warnings
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from robocram.robots import (
    MissingMeshWarning,
    PackageNotFoundError,
    PackagePathError,
    RobotModel,
)
from robocram.robots.link_centre import mesh_box
from robocram.robots.package_resolver import PackageResolver
from robocram.robots.safe_xml import XmlNode, decode_xml, parse_xml
from robocram.scenes.errors import SceneError
from robocram.scenes.stand_in import StandIn
from robocram.tf import Pose, Vector3
from robocram.tf import quaternion as quat
from robocram.world.robot_urdf import check_loadable

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET


@dataclass(frozen=True)
class Box:
    """A collision box (or a cylinder's bounding box) at ``origin`` in its link's frame."""

    origin: Pose
    size: Vector3  # [m]


@dataclass(frozen=True)
class EnvJoint:
    """A URDF joint: its type, its parent and child links, origin, axis and limits."""

    name: str
    type: str
    parent: str
    child: str
    origin: Pose
    axis: Vector3
    lower: float
    upper: float

    @property
    def moves(self) -> bool:
        """Whether it is a prismatic or revolute joint with some range."""
        return self.type in ("prismatic", "revolute", "continuous") and self.upper > self.lower

    def motion(self, value: float) -> Pose:
        """The child's pose in the joint frame at ``value`` [m | rad]."""
        if self.type == "prismatic":
            return Pose(tuple(a * value for a in self.axis))  # type: ignore[arg-type]
        if self.type in ("revolute", "continuous"):
            return Pose(orientation=quat.from_axis_angle(self.axis, value))
        return Pose()


@dataclass(frozen=True)
class EnvironmentModel:
    """Links (with their boxes and mesh counts) and joints of an environment URDF."""

    name: str
    boxes: Mapping[str, tuple[Box, ...]]
    meshes: Mapping[str, int]  # link -> number of mesh collision shapes
    joints: Mapping[str, EnvJoint]  # by child link
    root: str
    unfound: frozenset[str] = frozenset()  # links with a mesh file that is not there

    @classmethod
    def from_file(
        cls, path: str | Path, package_paths: Iterable[str | Path] = ()
    ) -> EnvironmentModel:
        """Read the URDF at ``path``; ``package_paths`` hold packages its meshes name.

        The robots' URDF door reads it first, so an environment is refused for what a
        robot's URDF is: a link with two parents, a loop, an undefined link, numbers that
        are not finite, crossed limits (and the tree walks below always end).

        Raises:
            UrdfError: malformed or unsafe XML, or not a tree (naming the link or joints).
            TooManyLinksError: more links than PyBullet holds (``MAX_LINKS``), even cut
                into bodies at subtrees hung on fixed joints from the root.
            SceneError: no links.
        """
        file = Path(path)
        paths = tuple(package_paths)
        check_urdf(file, paths)
        root = parse_xml(decode_xml(file.read_bytes(), file), file)
        resolver = PackageResolver.default(paths)
        boxes = {
            n.attrib["name"]: (*_boxes(n), *_mesh_boxes(n, file.parent, resolver))
            for n in root.findall("link")
        }
        meshes = {n.attrib["name"]: _count_meshes(n) for n in root.findall("link")}
        joints = {j.child: j for j in (_joint(n) for n in root.findall("joint"))}
        roots = sorted(set(boxes) - set(joints))
        if not roots:
            raise SceneError(f"{file}: no root link (no links, or a cycle); give a URDF tree")
        unfound = frozenset(
            n.attrib["name"]
            for n in root.findall("link")
            for uri in _mesh_files(n)
            if mesh_file(uri, file.parent, resolver) is None
        )
        name = root.attrib.get("name", file.stem)
        return cls(name, boxes, meshes, joints, roots[0], unfound)

    def with_stand_ins(self, stand_ins: Iterable[StandIn]) -> EnvironmentModel:
        """This model with each stand-in's boxes added to its link's."""
        boxes = dict(self.boxes)
        for stand_in in stand_ins:
            extra = tuple(Box(Pose(c), s) for c, s in stand_in.boxes())
            boxes[stand_in.link] = boxes.get(stand_in.link, ()) + extra
        return replace(self, boxes=boxes)

    def pose(self, link: str, values: Mapping[str, float] | None = None) -> Pose:
        """``link``'s pose in the root's frame, joints at ``values`` (default 0) [m | rad]."""
        chain: list[EnvJoint] = []
        while link in self.joints:
            joint = self.joints[link]
            chain.append(joint)
            link = joint.parent
        pose = Pose()
        for joint in reversed(chain):
            value = (values or {}).get(joint.name, 0.0)
            pose = pose * joint.origin * joint.motion(value)
        return pose

    def children(self, link: str) -> Iterator[EnvJoint]:
        """The joints whose parent is ``link``."""
        return (j for j in self.joints.values() if j.parent == link)

    def fixed_subtree(self, link: str) -> list[str]:
        """``link`` and every link fixed to it (through fixed joints only)."""
        found = [link]
        for joint in self.children(link):
            if joint.type == "fixed":
                found += self.fixed_subtree(joint.child)
        return found

    def moved_by_joint(self, link: str) -> bool:
        """Whether a moving joint lies between the root and ``link``."""
        while link in self.joints:
            if self.joints[link].moves:
                return True
            link = self.joints[link].parent
        return False


def check_urdf(file: Path, package_paths: Iterable[str | Path] = ()) -> RobotModel:
    """Read ``file`` through the robots' URDF door: the checks every URDF passes.

    Missing meshes and packages are the draft's to report (as unfound links), not warned
    about here. A file with more links than PyBullet holds is refused before the draft's
    walks (quadratic in the links) start, unless it loads as several bodies (cut at
    subtrees hung on fixed joints from the root): it could not be loaded anyway.
    Read as loading reads it first: a file whose packages are all found gives the same
    model either way, and the world's load of it then shares this one, parsed once.
    """
    paths = tuple(package_paths)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        try:
            model = RobotModel.from_file(file, paths)
        except PackageNotFoundError:
            model = RobotModel.from_file(file, paths, missing_packages_as_boxes=True)
    check_loadable(model.name, str(file), model)
    return model


def _floats(text: str | None, default: tuple[float, ...]) -> tuple[float, ...]:
    return tuple(float(v) for v in text.split()) if text else default


def _origin(node: XmlNode | None) -> Pose:
    if node is None:
        return Pose()
    x, y, z = _floats(node.attrib.get("xyz"), (0.0, 0.0, 0.0))
    roll, pitch, yaw = _floats(node.attrib.get("rpy"), (0.0, 0.0, 0.0))
    return Pose((x, y, z), quat.from_euler(roll, pitch, yaw))


def _boxes(link: XmlNode) -> Iterator[Box]:
    for shape in link.findall("collision"):
        geometry = shape.find("geometry")
        if geometry is None or not geometry.children:
            continue
        kind = geometry.children[0]
        if kind.tag == "box":
            sx, sy, sz = _floats(kind.attrib.get("size"), (0.0, 0.0, 0.0))
            yield Box(_origin(shape.find("origin")), (sx, sy, sz))
        elif kind.tag == "cylinder":
            r, length = float(kind.attrib["radius"]), float(kind.attrib["length"])
            yield Box(_origin(shape.find("origin")), (2 * r, 2 * r, length))


def _mesh_boxes(link: XmlNode, base: Path, resolver: PackageResolver) -> Iterator[Box]:
    """The bounds of each collision mesh of ``link`` that is found and read, as boxes."""
    for shape in link.findall("collision"):
        geometry = shape.find("geometry")
        mesh = geometry.find("mesh") if geometry is not None else None
        if mesh is None:
            continue
        found = mesh_file(mesh.attrib.get("filename", ""), base, resolver)
        bounds = mesh_box(str(found)) if found is not None else None
        if bounds is None:
            continue
        scale = _floats(mesh.attrib.get("scale"), (1.0, 1.0, 1.0))
        low, high = ([v * s for v, s in zip(c, scale, strict=True)] for c in bounds)
        centre = tuple((lo + hi) / 2 for lo, hi in zip(low, high, strict=True))
        size = tuple(abs(hi - lo) for lo, hi in zip(low, high, strict=True))
        yield Box(_origin(shape.find("origin")) * Pose(centre), size)  # type: ignore[arg-type]


def _count_meshes(link: XmlNode) -> int:
    return sum(
        1
        for shape in link.findall("collision")
        if (g := shape.find("geometry")) is not None and g.find("mesh") is not None
    )


def _mesh_files(link: XmlNode) -> Iterator[str]:
    for shape in [*link.findall("visual"), *link.findall("collision")]:
        geometry = shape.find("geometry")
        mesh = geometry.find("mesh") if geometry is not None else None
        if mesh is not None:
            yield mesh.attrib.get("filename", "")


def _joint(node: XmlNode) -> EnvJoint:
    parent, child, axis, limit = (node.find(t) for t in ("parent", "child", "axis", "limit"))
    if parent is None or child is None:
        raise SceneError(f"joint {node.attrib.get('name')!r} lacks a parent or child link")
    ax = _floats(axis.attrib.get("xyz") if axis is not None else None, (1.0, 0.0, 0.0))
    norm = math.sqrt(sum(a * a for a in ax)) or 1.0
    lower = float(limit.attrib.get("lower", 0.0)) if limit is not None else 0.0
    upper = float(limit.attrib.get("upper", 0.0)) if limit is not None else 0.0
    if node.attrib.get("type") == "continuous":
        lower, upper = -math.pi, math.pi
    return EnvJoint(
        node.attrib["name"],
        node.attrib.get("type", "fixed"),
        parent.attrib["link"],
        child.attrib["link"],
        _origin(node.find("origin")),
        (ax[0] / norm, ax[1] / norm, ax[2] / norm),
        lower,
        upper,
    )


def loadable_urdf(
    urdf: str | Path,
    stand_ins: Iterable[StandIn] = (),
    folder: Path | None = None,
    package_paths: Iterable[str | Path] = (),
) -> Path:
    """``urdf`` itself, or a copy in ``folder`` without the shapes PyBullet cannot load.

    Meshes found (``package_paths``, ``ROS_PACKAGE_PATH``, a package beside the URDF) are
    named by their absolute paths in the copy, since PyBullet resolves no ``package://``.
    Mesh files that are not there are left out of the copy: the links stay, as frames
    that move with their joints, unless ``stand_ins`` give them boxes instead (as
    collision and visual shapes).
    """
    import xml.etree.ElementTree as ET  # the file was read safely by from_file first

    path = Path(urdf)
    paths = tuple(package_paths)
    EnvironmentModel.from_file(path, paths)  # refuses unsafe XML before ElementTree sees it
    tree = ET.parse(path)
    resolver = PackageResolver.default(paths)
    shapes = tuple(stand_ins)
    by_link = {s.link: s for s in shapes}
    dropped = 0
    for link in tree.getroot().iter("link"):
        for shape in [*link.findall("visual"), *link.findall("collision")]:
            mesh = shape.find("geometry/mesh")
            if mesh is None:
                continue
            uri = mesh.get("filename", "")
            found = mesh_file(uri, path.parent, resolver)
            if found is None:
                link.remove(shape)
                dropped += 1
            elif uri != str(found):
                mesh.set("filename", str(found))
                dropped += 1
        stand_in = by_link.pop(link.get("name", ""), None)
        if stand_in is not None:
            _add_boxes(link, stand_in)
            dropped += 1
    if by_link:
        raise SceneError(f"{path.name} has no links {sorted(by_link)} for the stand-ins")
    if not dropped:
        return path
    key = hashlib.sha1(f"{path.resolve()}{sorted(map(repr, shapes))}{paths}".encode())
    folder = folder or Path(tempfile.gettempdir()) / "robocram-environments" / key.hexdigest()[:12]
    folder.mkdir(parents=True, exist_ok=True)
    copy = folder / f"{path.stem}.loadable.urdf"
    tree.write(copy, encoding="unicode")
    return copy


def _add_boxes(link: ET.Element, stand_in: StandIn) -> None:
    import xml.etree.ElementTree as ET  # noqa: F811  (only writes elements)

    for centre, size in stand_in.boxes():
        for tag in ("visual", "collision"):
            shape = ET.SubElement(link, tag)
            ET.SubElement(shape, "origin", xyz=" ".join(f"{v:.6g}" for v in centre), rpy="0 0 0")
            geometry = ET.SubElement(shape, "geometry")
            ET.SubElement(geometry, "box", size=" ".join(f"{v:.6g}" for v in size))


def mesh_file(uri: str, base: Path, resolver: PackageResolver) -> Path | None:
    """The mesh file ``uri`` names (from the URDF's folder ``base``), None if not there."""
    try:
        found = resolver.resolve(uri, base)
    except (PackageNotFoundError, PackagePathError):
        return None
    return found if found.is_file() else None
