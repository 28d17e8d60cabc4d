"""The robots' facts in a world's knowledge base, kept in step with the robots in it.

The world's tables tell it of every body added or removed. It holds the knowledge base
once one was built and no reference to the world, so that the tables (which the world
holds) do not keep their world alive: a world nobody holds is freed, and its physics
client closed, at once.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from robocram.robots import install_description
from robocram.world.world_object import RobotObject, WorldObject

if TYPE_CHECKING:
    from robocram.logic import KnowledgeBase


class RobotFacts:
    """Installs a robot's description facts when it joins, drops them when its kind leaves."""

    def __init__(self) -> None:
        self._kb: KnowledgeBase | None = None

    def start(self, kb: KnowledgeBase, robots: list[RobotObject]) -> None:
        """Keep ``kb`` in step from now on, starting with the ``robots`` already there."""
        self._kb = kb
        for robot in robots:
            install_description(kb, robot.description)

    def inserted(self, handle: WorldObject) -> None:
        """A robot's facts join the knowledge base."""
        if isinstance(handle, RobotObject) and self._kb is not None:
            install_description(self._kb, handle.description)

    def removed(self, handle: WorldObject, robots: list[RobotObject]) -> None:
        """A robot's facts leave the knowledge base when no robot of its kind is left."""
        if isinstance(handle, RobotObject) and self._kb is not None:
            name = handle.description.name
            if not any(r.description.name == name for r in robots):
                self._kb.add_fact_group(f"{name}_description", [])
