"""The base of a world's parts (``world.bodies``, ``world.contacts``, ``world.physics``,
``world.snapshots``, ``world.view``): a weak reference to the world they serve.

Weak, so a part does not make a reference cycle with its world: a world nobody holds is
freed (and its physics client closed) at once, as before it had parts.
"""

from __future__ import annotations

import weakref

from robocram.world.errors import WorldClosedError
from robocram.world.world_core import WorldCore


class WorldPart:
    """One job of a :class:`~robocram.world.world.World`, reached as an attribute of it."""

    def __init__(self, world: WorldCore):
        self._ref = weakref.ref(world)

    @property
    def _world(self) -> WorldCore:
        """The world served; gone (only a part kept, not its world): closed."""
        world = self._ref()
        if world is None:
            raise WorldClosedError()
        return world
