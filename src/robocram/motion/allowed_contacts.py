"""A robot description's allowed contacts as a test on (robot link, other) pairs.

``RobotDescription.allowed_contacts`` holds rules ``(robot links, other)``: robot links
``*``, ``gripper`` or ``hand`` (an arm's, paired with that arm's held objects), ``base``
(links no joint moves) or a link name; other ``floor`` (objects of type floor), ``held``
(what the arm holds), an object type, an object name, or a robot link name. The scene asks
once per pair when it is built, never per check.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from dataclasses import dataclass

from robocram.motion.errors import MotionError
from robocram.robots import LoadedDescription

ROBOT_SIDES = ("*", "gripper", "hand", "base")


@dataclass(frozen=True)
class Other:
    """The other party of a contact: a world object, a held object or a robot link."""

    name: str  # object name, or the robot link's name
    type: str  # object type; "robot" for a robot link
    held_by: str | None = None  # the arm holding it, for a held object


@dataclass(frozen=True)
class AllowedContacts:
    """The rules of one robot, with the link sets its words stand for."""

    rules: tuple[tuple[str, str], ...]
    gripper_links: Mapping[str, frozenset[str]]  # arm -> its gripper links
    hand_links: Mapping[str, frozenset[str]]  # arm -> its hand links
    base_links: frozenset[str]  # links no movable joint moves
    free_links: frozenset[str]  # links that may touch anything (``allowed_links``)

    @classmethod
    def of(cls, desc: LoadedDescription, free_links: Collection[str] = ()) -> AllowedContacts:
        """The rules of ``desc``; ``free_links`` may touch anything (CRAM's allow_hand)."""
        model = desc.model
        for link in free_links:
            model.link(link)  # a DescriptionError naming close links
        for robot_side, _ in desc.allowed_contacts:
            if robot_side not in ROBOT_SIDES and robot_side not in model.links:
                raise MotionError(
                    f"allowed contact rule ({robot_side!r}, ...) of {desc.name}: the robot side "
                    f"must be one of {ROBOT_SIDES} or a link name"
                )
        return cls(
            tuple(desc.allowed_contacts),
            {name: frozenset(arm.gripper_links) for name, arm in desc.arms.items()},
            {name: frozenset(arm.hand_links) for name, arm in desc.arms.items()},
            frozenset(_base_links(desc)),
            frozenset(free_links),
        )

    def allows(self, link: str, other: Other) -> bool:
        """Whether robot ``link`` may touch ``other``."""
        if link in self.free_links:
            return True
        return any(self._rule_allows(rule, link, other) for rule in self.rules)

    def allows_any_link(self, other: Other) -> bool:
        """Whether a ``*`` rule lets every link touch ``other`` (held objects follow these)."""
        return any(
            side == "*" and self._rule_allows((side, o), "", other) for side, o in self.rules
        )

    def _rule_allows(self, rule: tuple[str, str], link: str, other: Other) -> bool:
        robot_side, other_side = rule
        if robot_side in ("gripper", "hand"):
            links = self.gripper_links if robot_side == "gripper" else self.hand_links
            arms = [arm for arm, members in links.items() if link in members]
            if not arms:
                return False
            if other_side == "held":
                return other.held_by in arms
            return _other_matches(other_side, other)
        if robot_side == "base" and link not in self.base_links:
            return False
        if robot_side not in ROBOT_SIDES and robot_side != link:
            return False
        if other_side == "held":
            return other.held_by is not None
        return _other_matches(other_side, other)


def _other_matches(word: str, other: Other) -> bool:
    if word == "floor":
        return other.type == "floor"
    return word in (other.type, other.name)


def _base_links(desc: LoadedDescription) -> set[str]:
    """Links whose path from the root crosses no movable joint."""
    model = desc.model
    found = {model.root_link}
    changed = True
    while changed:
        changed = False
        for joint in model.joints.values():
            if joint.parent in found and joint.child not in found and not joint.movable:
                found.add(joint.child)
                changed = True
    return found
