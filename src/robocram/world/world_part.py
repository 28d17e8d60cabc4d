"""The base of a world's parts (``world.bodies``, ``world.contacts``, ``world.physics``,
``world.snapshots``, ``world.view``): a weak reference to the world they serve, and the
world's tables, which only the world and its parts reach.

Weak, so a part does not make a reference cycle with its world: a world nobody holds is
freed (and its physics client closed) at once, as before it had parts. The tables hold
no reference to the world, so a part may hold them.
"""

from __future__ import annotations

import weakref
from typing import TYPE_CHECKING

from robocram.world.errors import WorldClosedError
from robocram.world.world_tables import WorldTables

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade


class WorldPart:
    """One job of a :class:`~robocram.world.world.World`, reached as an attribute of it."""

    def __init__(self, world: WorldFacade, tables: WorldTables):
        self._ref = weakref.ref(world)
        self._tables = tables

    @property
    def _world(self) -> WorldFacade:
        """The world served; gone (only a part kept, not its world): closed."""
        world = self._ref()
        if world is None:
            raise WorldClosedError()
        return world
