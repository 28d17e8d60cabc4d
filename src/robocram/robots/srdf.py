"""Read an SRDF (a robot's MoveIt configuration) against the URDF it describes.

An SRDF says what drafting must otherwise guess: planning groups (the joints of an arm),
end effectors (which group hangs on which link), named joint states ("home", "stow") and
link pairs whose collisions MoveIt never checks. Elements robocram does not use are
skipped; every name used is checked against the URDF, so a mismatched pair of files fails
here, naming the element, rather than as a strange draft.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from dataclasses import dataclass
from pathlib import Path

from robocram.robots.errors import DescriptionError, SrdfError, UrdfError, closest_names
from robocram.robots.robot_model import RobotModel
from robocram.robots.safe_xml import XmlNode, decode_xml, parse_xml
from robocram.robots.urdf_elements import Joint

_LIMIT_SLACK = 1e-6  # [rad | m] a state this far past a limit is at it (as descriptions)


@dataclass(frozen=True)
class SrdfGroup:
    """A planning group: its joints (fixed ones too) and links, as MoveIt expands them."""

    name: str
    joints: tuple[str, ...]
    links: tuple[str, ...]


@dataclass(frozen=True)
class SrdfEndEffector:
    """An end effector: the group of its links, hanging on ``parent_link``."""

    name: str
    group: str
    parent_link: str
    parent_group: str | None = None


@dataclass(frozen=True)
class SrdfState:
    """A named joint state of one group: joint values [rad | m]."""

    name: str
    group: str
    values: Mapping[str, float]


@dataclass(frozen=True)
class Srdf:
    """What robocram takes from an SRDF, every name checked against the URDF."""

    source: Path
    groups: Mapping[str, SrdfGroup]
    end_effectors: tuple[SrdfEndEffector, ...]
    states: tuple[SrdfState, ...]
    disabled_pairs: tuple[tuple[str, str], ...]


class _Reader:
    """Checks names of one SRDF document against ``model`` as it reads."""

    def __init__(self, source: Path, root: XmlNode, model: RobotModel) -> None:
        self.source, self.root, self.model = source, root, model
        self.nodes = {g.attrib.get("name", ""): g for g in root.findall("group")}
        self.virtual = {v.attrib.get("name", "") for v in root.findall("virtual_joint")}
        self.groups: dict[str, SrdfGroup] = {}

    def fail(self, node: XmlNode, problem: str) -> SrdfError:
        return SrdfError(self.source, f"<{node.tag}>: {problem}", node.line)

    def attr(self, node: XmlNode, key: str) -> str:
        if not node.attrib.get(key):
            raise self.fail(node, f"lacks the required attribute {key!r}; add it")
        return node.attrib[key]

    def name(self, node: XmlNode, key: str, kind: str) -> str:
        """The ``kind`` ("link", "joint", "group") that attribute ``key`` names, checked."""
        value = self.attr(node, key)
        pools: dict[str, Collection[str]] = {
            "link": self.model.links,
            "joint": self.model.joints,
            "group": self.nodes,
        }
        pool = pools[kind]
        if value not in pool:
            close = closest_names(value, pool)
            hint = f"did you mean {' or '.join(map(repr, close))}? " if close else ""
            raise self.fail(
                node,
                f"{kind} {value!r} is not in {self.model.source}; {hint}"
                "fix the SRDF, or pass the URDF it was written for",
            )
        return value

    def group(self, name: str, seen: tuple[str, ...] = ()) -> SrdfGroup:
        """Group ``name`` expanded: joints bring their child link, links their parent joint."""
        if name in self.groups:
            return self.groups[name]
        node = self.nodes[name]
        if name in seen:
            raise self.fail(node, f"group {name!r} contains itself; remove the cycle")
        joints: list[str] = []
        links: list[str] = []
        for child in node.children:
            if child.tag == "joint":
                joints.append(self.name(child, "name", "joint"))
                links.append(self.model.joints[joints[-1]].child)
            elif child.tag == "link":
                links.append(self.name(child, "name", "link"))
                parent = self.model.parent_joint(links[-1])
                joints += [parent.name] if parent is not None else []
            elif child.tag == "chain":
                chain = self._chain(child)
                joints, links = joints + [j.name for j in chain], links + [j.child for j in chain]
            elif child.tag == "group":
                inner = self.group(self.name(child, "name", "group"), (*seen, name))
                joints, links = joints + list(inner.joints), links + list(inner.links)
        found = SrdfGroup(name, tuple(dict.fromkeys(joints)), tuple(dict.fromkeys(links)))
        self.groups[name] = found
        return found

    def _chain(self, node: XmlNode) -> list[Joint]:
        base, tip = self.name(node, "base_link", "link"), self.name(node, "tip_link", "link")
        try:
            return self.model.chain(base, tip)
        except DescriptionError as err:
            raise self.fail(node, f"{tip!r} is not below {base!r}; swap or fix the links") from err

    def state(self, node: XmlNode) -> SrdfState:
        values: dict[str, float] = {}
        for joint in node.findall("joint"):
            if joint.attrib.get("name") in self.virtual:
                continue  # the base's pose, not a joint of the URDF
            name = self.name(joint, "name", "joint")
            values[name] = self.joint_value(joint, name)
        group = self.name(node, "group", "group")
        return SrdfState(self.attr(node, "name"), group, values)

    def joint_value(self, node: XmlNode, name: str) -> float:
        """The ``value`` of a group state's joint: a finite number within its limits (the
        state may become a parking pose)."""
        text = self.attr(node, "value").split()
        if not text:
            raise self.fail(node, f"joint {name!r} has a blank value; give a number")
        try:
            value = float(text[0])
        except ValueError as err:
            raise self.fail(node, f"value {text[0]!r} is no number; give one") from err
        joint = self.model.joints[name]
        lower = -math.inf if joint.lower is None else joint.lower
        upper = math.inf if joint.upper is None else joint.upper
        if not (math.isfinite(value) and lower - _LIMIT_SLACK <= value <= upper + _LIMIT_SLACK):
            raise self.fail(
                node,
                f"value {text[0]!r} of joint {name!r} is not a finite number within its "
                f"limits [{lower}, {upper}]; give one",
            )
        return value

    def end_effector(self, node: XmlNode) -> SrdfEndEffector:
        parent_group = None
        if node.attrib.get("parent_group"):
            parent_group = self.name(node, "parent_group", "group")
        return SrdfEndEffector(
            self.attr(node, "name"),
            self.name(node, "group", "group"),
            self.name(node, "parent_link", "link"),
            parent_group,
        )


def read_srdf(path: str | Path, model: RobotModel) -> Srdf:
    """The groups, end effectors, named states and disabled pairs of the SRDF at ``path``.

    Raises:
        SrdfError: the file is unreadable, not well-formed, not ``<robot>``, or names a
            link, joint or group that ``model`` (its URDF) does not have.
    """
    source = Path(path).expanduser().resolve()
    try:
        root = parse_xml(decode_xml(source.read_bytes(), source), source)
    except OSError as err:
        raise SrdfError(source, f"cannot read the SRDF: {err.strerror}") from err
    except UrdfError as err:
        raise SrdfError(source, err.problem, err.line) from err
    if root.tag != "robot":
        raise SrdfError(source, f"root element is <{root.tag}>, an SRDF needs <robot>", root.line)
    reader = _Reader(source, root, model)
    groups = {name: reader.group(name) for name in reader.nodes}
    pairs = tuple(
        (reader.name(n, "link1", "link"), reader.name(n, "link2", "link"))
        for n in root.findall("disable_collisions")
    )
    return Srdf(
        source,
        groups,
        tuple(reader.end_effector(n) for n in root.findall("end_effector")),
        tuple(reader.state(n) for n in root.findall("group_state")),
        pairs,
    )
