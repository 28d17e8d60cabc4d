"""Snapshots of a world: the set of objects, their poses, velocities, joints and attachments.

Restoring a snapshot removes objects added since, re-creates removed ones from their specs
(the same handles get the new bodies) and puts every body back exactly. A snapshot also
seeds a copy of the world in another physics client.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from robocram.world.attachment import Attachment
from robocram.world.errors import WorldClosedError
from robocram.world.pybullet_backend import pybullet
from robocram.world.versions import Stamp, Versions
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_tables import WorldTables
from robocram.world.written_bases import Vector


@dataclass(frozen=True)
class BodyState:
    """One body's base pose (pybullet's COM frame), velocities and joint positions/speeds."""

    base: tuple[tuple[float, ...], tuple[float, ...]]
    velocity: tuple[tuple[float, ...], tuple[float, ...]]
    joints: tuple[tuple[int, float, float], ...]  # (index, position, velocity)


@dataclass(frozen=True)
class WorldState:
    """Everything :meth:`restore` needs to put a world back as it was."""

    handles: tuple[WorldObject, ...]
    bodies: tuple[tuple[BodyState, ...], ...]  # per handle, per body (a cut model's parts)
    attachments: tuple[Attachment, ...]
    holds: tuple[tuple[str, tuple[tuple[str, float], ...]], ...]  # object -> held joints
    time: float
    stamps: tuple[Stamp, ...] = ()  # per handle, its change counters when captured
    clock: Versions | None = field(default=None, compare=False, repr=False)  # whose counters

    @classmethod
    def capture(cls, world: WorldTables) -> WorldState:
        """Snapshot ``world`` now."""
        if world.closed:
            raise WorldClosedError()
        handles = tuple(world.objects())
        cid = world.physics_client()
        return cls(
            handles=handles,
            bodies=tuple(_object_state(cid, h, world.base_inputs(h)) for h in handles),
            attachments=tuple(world.all_attachments()),
            holds=tuple((h.name, tuple(world.held_joints(h).items())) for h in handles),
            time=world.time,
            stamps=tuple(world.versions.body(h) for h in handles),
            clock=world.versions,
        )

    def restore(self, world: WorldTables) -> None:
        """Put ``world`` (the one captured) back: objects, poses, joints, attachments.

        Objects are matched by identity: one added under a name that an object had when
        the state was captured is removed, and the captured handle comes back.
        """
        keep = {id(h) for h in self.handles}
        for obj in world.objects():
            if id(obj) not in keep:
                world.remove(obj)
        for handle in self.handles:
            if handle.name not in world:
                world.insert(handle)
        self._apply(world, self._unchanged(world))

    def _unchanged(self, world: WorldTables) -> set[str]:
        """The objects nothing moved since the capture: left as they stand, since writing
        a base read from PyBullet back would move it a last bit (after physics moved it,
        the inputs that put it there are unknown)."""
        if self.clock is not world.versions:
            return set()
        versions = world.versions
        return {
            handle.name
            for handle, stamp in zip(self.handles, self.stamps, strict=True)
            if world.object(handle.name) is handle and versions.body(handle) == stamp
        }

    def recreate(self, world: WorldTables) -> None:
        """Fill an empty ``world`` (another client) with new handles in this state."""
        for handle in self.handles:
            world.insert(_clone(handle))
        self._apply(world, set())

    def _apply(self, world: WorldTables, unchanged: set[str]) -> None:
        cid = world.physics_client()
        for handle, states in zip(self.handles, self.bodies, strict=True):
            if handle.name in unchanged:
                continue
            targets = world.object(handle.name).bodies
            for target, body in zip(targets, states, strict=True):
                pybullet.resetBasePositionAndOrientation(target, *body.base, physicsClientId=cid)
                pybullet.resetBaseVelocity(target, *body.velocity, physicsClientId=cid)
                for index, position, velocity in body.joints:
                    pybullet.resetJointState(target, index, position, velocity, physicsClientId=cid)
            world.versions.moved(handle.name)
            world.versions.jointed(handle.name)
            bases = [(t, *b.base) for t, b in zip(targets, states, strict=True)]
            world.wrote_bases(world.object(handle.name), bases)
        world.set_attachments(self.attachments)
        for name, held in self.holds:
            world.set_held_joints(name, dict(held))
        world.time = self.time


def _object_state(
    cid: int, handle: WorldObject, written: Mapping[int, tuple[Vector, Vector]]
) -> tuple[BodyState, ...]:
    return tuple(_body_state(cid, b, written) for b in handle.bodies)


def _body_state(cid: int, body: int, written: Mapping[int, tuple[Vector, Vector]]) -> BodyState:
    """``body``'s state; its base as last written where it still stands so (PyBullet reads
    a base a last bit off what was written: see :mod:`~robocram.world.written_bases`)."""
    pos, orn = written.get(body) or pybullet.getBasePositionAndOrientation(
        body, physicsClientId=cid
    )
    lin, ang = pybullet.getBaseVelocity(body, physicsClientId=cid)
    indices = [
        i
        for i in range(pybullet.getNumJoints(body, physicsClientId=cid))
        if pybullet.getJointInfo(body, i, physicsClientId=cid)[2] != pybullet.JOINT_FIXED
    ]
    states = pybullet.getJointStates(body, indices, physicsClientId=cid) if indices else []
    joints = tuple((i, float(s[0]), float(s[1])) for i, s in zip(indices, states, strict=True))
    return BodyState((tuple(pos), tuple(orn)), (tuple(lin), tuple(ang)), joints)


def _clone(handle: WorldObject) -> WorldObject:
    if isinstance(handle, RobotObject):
        return RobotObject(
            handle.name, handle.type, -1, handle.spec, description=handle.description
        )
    return WorldObject(handle.name, handle.type, -1, handle.spec)
