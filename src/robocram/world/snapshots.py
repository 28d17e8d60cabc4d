"""The snapshots part of a world: reading its state whole and putting it back.

Reached as ``world.snapshots``. Besides poses and joint values a world's state holds
what is attached to what and the joint values simulation holds robots at; those are
written here (and the holds read), with the block that restores everything on leaving.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterable, Iterator, Mapping, Sequence

from robocram.world.attachment import Attachment
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_part import WorldPart
from robocram.world.world_state import WorldState
from robocram.world.world_tables import ObjectRef
from robocram.world.written_bases import BaseInput


class Snapshots(WorldPart):
    """Capture and restore of one world, and the state beyond poses that it carries."""

    @contextlib.contextmanager
    def stored_state(self) -> Iterator[WorldState]:
        """Restore the world exactly on leaving the block (objects added/removed included)."""
        state = WorldState.capture(self._tables)
        try:
            yield state
        finally:
            state.restore(self._tables)

    def bases(self, obj: ObjectRef) -> list[BaseInput]:
        """Per body of ``obj``: its id and the base (COM position, orientation) that puts
        it exactly where it stands: as last written while it stands so, else as read."""
        handle = self._world.object(obj)
        written = self._tables.base_inputs(handle)
        cid = self._tables.physics_client()
        found: list[BaseInput] = []
        for body in handle.bodies:
            pos, orn = written.get(body) or pybullet.getBasePositionAndOrientation(
                body, physicsClientId=cid
            )
            found.append((body, tuple(pos), tuple(orn)))
        return found

    def put_bases(self, obj: ObjectRef, bases: Sequence[BaseInput]) -> None:
        """Write ``obj``'s bodies' bases (as :meth:`bases` gives them), at rest."""
        self._tables.put_bases(self._world.object(obj), bases)

    def body_state(self, obj: ObjectRef) -> tuple[float, ...]:
        """Numbers that change whenever ``obj``'s shapes move: its body id, base pose and
        joint positions as the backend holds them, read in two calls (a cache of derived
        geometry compares them, cheaper than ``pose`` and ``joint_states``)."""
        w = self._world
        handle = w.object(obj)
        cid = self._tables.physics_client()
        position, orientation = pybullet.getBasePositionAndOrientation(
            handle.body_id, physicsClientId=cid
        )
        joints: tuple[float, ...] = ()
        if handle.movable_joints:
            joints = tuple(w.joint_states(handle).values())
        return (float(handle.body_id), *position, *orientation, *joints)

    def capture(self) -> WorldState:
        """The world's state now, whole (objects, bodies, attachments, holds, time)."""
        return WorldState.capture(self._tables)

    def restore(self, state: WorldState) -> None:
        """Put the world back to ``state`` (captured from it): objects, poses, joints."""
        state.restore(self._tables)

    def recreate(self, state: WorldState) -> None:
        """Fill this empty world (a copy's, in its own client) with new handles in ``state``."""
        state.recreate(self._tables)

    def set_attachments(self, attachments: Iterable[Attachment]) -> None:
        """Replace every attachment by ``attachments`` (kept relative poses, nothing moves)."""
        self._tables.set_attachments(attachments)

    def held_joints(self, obj: ObjectRef) -> dict[str, float]:
        """The joint values [rad | m] that simulation holds ``obj``'s joints at, by name."""
        return self._tables.held_joints(obj)

    def set_held_joints(self, obj: ObjectRef, values: Mapping[str, float]) -> None:
        """Hold exactly ``values`` (joint name -> [rad | m]) from now on; nothing moves now."""
        self._tables.set_held_joints(obj, values)
