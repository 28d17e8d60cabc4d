"""Walking a model's tree: children, subtrees, fixed closures, movable ancestors, mimics.

The draft reads structure only: which joints hang below a link, which are rigidly fixed to
it, how many joints move a link, and which joints follow which through ``<mimic>``.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

from robocram.robots.robot_model import RobotModel
from robocram.robots.urdf_elements import Joint


@dataclass(frozen=True, eq=False)
class ModelTree:
    """Parent-child lookups over one model, built once."""

    model: RobotModel
    _children: dict[str, list[Joint]] = field(init=False, repr=False)

    def __post_init__(self) -> None:
        children: dict[str, list[Joint]] = {name: [] for name in self.model.links}
        for joint in self.model.joints.values():
            children[joint.parent].append(joint)
        object.__setattr__(self, "_children", children)

    def child_joints(self, link: str) -> list[Joint]:
        """The joints whose parent is ``link``, in file order."""
        return self._children[link]

    def subtree_joints(self, link: str) -> Iterator[Joint]:
        """Every joint below ``link``, parents before children."""
        for joint in self._children[link]:
            yield joint
            yield from self.subtree_joints(joint.child)

    def subtree_links(self, link: str) -> list[str]:
        """The links below ``link`` (not ``link`` itself), parents first."""
        return [joint.child for joint in self.subtree_joints(link)]

    def fixed_closure(self, link: str) -> list[str]:
        """``link`` and every link fixed to it through fixed joints below it."""
        found = [link]
        for joint in self._children[link]:
            if joint.type == "fixed":
                found += self.fixed_closure(joint.child)
        return found

    def rigid_group(self, link: str) -> set[str]:
        """Every link fixed to ``link`` (above or below it) through fixed joints only."""
        top = link
        joint = self.model.parent_joint(top)
        while joint is not None and joint.type == "fixed":
            top = joint.parent
            joint = self.model.parent_joint(top)
        return set(self.fixed_closure(top))

    def movable_roots(self, link: str) -> list[Joint]:
        """The first movable joints below ``link``: those reached through fixed joints only."""
        return [
            joint
            for fixed in self.fixed_closure(link)
            for joint in self._children[fixed]
            if joint.movable
        ]

    def ancestors(self, link: str) -> list[Joint]:
        """The joints from the root down to ``link``, root first."""
        return self.model.chain(self.model.root_link, link)

    def movable_ancestors(self, link: str) -> list[Joint]:
        """The movable joints from the root down to ``link``, root first."""
        return [joint for joint in self.ancestors(link) if joint.movable]

    def followers(self, master: str) -> list[str]:
        """The joints that mimic ``master``, directly or through other followers."""
        found: list[str] = []
        frontier = [master]
        while frontier:
            name = frontier.pop()
            for joint in self.model.joints.values():
                if joint.mimic is not None and joint.mimic.joint == name:
                    found.append(joint.name)
                    frontier.append(joint.name)
        return found

    def is_mimicked(self, joint: str) -> bool:
        """Whether some joint follows ``joint`` through ``<mimic>``."""
        return any(
            j.mimic is not None and j.mimic.joint == joint for j in self.model.joints.values()
        )

    def below(self, ancestor: str, link: str) -> bool:
        """Whether ``link`` is ``ancestor`` or hangs below it."""
        if link == ancestor or ancestor == self.model.root_link:
            return True
        return any(j.child == ancestor for j in self.ancestors(link))
