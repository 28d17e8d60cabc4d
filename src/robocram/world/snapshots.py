"""The snapshots part of a world: reading its state whole and putting it back.

Reached as ``world.snapshots``. Besides poses and joint values a world's state holds
what is attached to what and the joint values simulation holds robots at; those are
read and written here, with the block that restores everything on leaving.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

from robocram.world.pybullet_backend import pybullet
from robocram.world.world_core import ObjectRef
from robocram.world.world_part import WorldPart
from robocram.world.world_state import WorldState


class Snapshots(WorldPart):
    """Capture and restore of one world, and the state beyond poses that it carries."""

    @contextlib.contextmanager
    def stored_state(self) -> Iterator[WorldState]:
        """Restore the world exactly on leaving the block (objects added/removed included)."""
        state = WorldState.capture(self._world)
        try:
            yield state
        finally:
            state.restore(self._world)

    def body_state(self, obj: ObjectRef) -> tuple[float, ...]:
        """Numbers that change whenever ``obj``'s shapes move: its body id, base pose and
        joint positions as the backend holds them, read in two calls (a cache of derived
        geometry compares them, cheaper than ``pose`` and ``joint_states``)."""
        w = self._world
        handle = w.object(obj)
        cid = w.physics_client()
        position, orientation = pybullet.getBasePositionAndOrientation(
            handle.body_id, physicsClientId=cid
        )
        joints: tuple[float, ...] = ()
        if handle.movable_joints:
            joints = tuple(w.joint_states(handle).values())
        return (float(handle.body_id), *position, *orientation, *joints)
