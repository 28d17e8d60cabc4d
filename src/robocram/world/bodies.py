"""The bodies part of a world: more ways to add bodies, and the less everyday questions
about their links, joints and attachments.

Reached as ``world.bodies``; the everyday ones (``add_box``, ``pose``, ``joint_states``,
``attach``...) stay on :class:`~robocram.world.world.World` itself.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from robocram.world.attachment import Attachment
from robocram.world.body_slots import link_slot
from robocram.world.body_spec import GREY, MeshSpec, Rgba, ShapeSpec
from robocram.world.joint_state import JointLimits
from robocram.world.pybullet_backend import pybullet
from robocram.world.world_object import WorldObject
from robocram.world.world_part import WorldPart
from robocram.world.world_tables import ORIGIN, ObjectRef

if TYPE_CHECKING:
    from robocram.tf import PoseLike


class Bodies(WorldPart):
    """Adding floors, primitives and meshes; body ids, link frames, limits, attachments."""

    def add_floor(self, name: str = "floor") -> WorldObject:
        """Add the static ground plane z = 0 (type ``floor``)."""
        return self._world.add_object(name, "floor", ShapeSpec("plane"))

    def add_cylinder(
        self,
        name: str,
        radius: float,
        height: float,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        color: Rgba = GREY,
    ) -> WorldObject:
        """Add an upright cylinder [m] centred at ``pose``."""
        spec = ShapeSpec("cylinder", (2 * radius, 2 * radius, height), mass, color)
        return self._world.add_object(name, "cylinder", spec, pose)

    def add_sphere(
        self,
        name: str,
        radius: float,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        color: Rgba = GREY,
    ) -> WorldObject:
        """Add a sphere of ``radius`` [m] centred at ``pose``."""
        spec = ShapeSpec("sphere", (2 * radius, 2 * radius, 2 * radius), mass, color)
        return self._world.add_object(name, "sphere", spec, pose)

    def add_mesh(
        self,
        name: str,
        path: str | Path,
        pose: PoseLike = ORIGIN,
        mass: float = 0.0,
        scale: float = 1.0,
        color: Rgba = GREY,
        type: str = "mesh",  # noqa: A002
    ) -> WorldObject:
        """Add a body from an OBJ/STL mesh file."""
        spec = MeshSpec(Path(path), scale, mass, color)
        return self._world.add_object(name, type, spec, pose)

    def link_frames(self, obj: ObjectRef, links: Sequence[str]) -> list[tuple[float, ...]]:
        """Per link of ``links``: its frame in the world as ``(x, y, z, qx, qy, qz, qw)``,
        read from the backend in one call (checks read tens of links per configuration)."""
        w = self._world
        handle = w.object(obj)
        index = handle.link_index
        try:
            indices = [index[link] for link in links]
        except KeyError:
            indices = [link_slot(handle, link) for link in links]  # names the culprit
        if (
            min(indices, default=0) >= 0
            and not handle.parts
            and not handle.link_offset.keys() & set(links)
        ):
            states = pybullet.getLinkStates(
                handle.body_id, indices, computeForwardKinematics=True,
                physicsClientId=self._tables.physics_client(),
            )  # fmt: skip
            return [(*st[4], *st[5]) for st in states]
        poses = [w.link_pose(handle, link) for link in links]  # the root or added frames
        return [(*p.position, *p.orientation) for p in poses]

    def attachments(self, robot: ObjectRef) -> dict[str, str]:
        """Objects attached to ``robot``: object name -> link name."""
        name = self._world.object(robot).name
        return {a.obj: a.link for a in self._tables.all_attachments() if a.robot == name}

    def attached_to(self, obj: ObjectRef) -> Attachment | None:
        """The attachment holding ``obj``, if any."""
        name = self._world.object(obj).name
        return next((a for a in self._tables.all_attachments() if a.obj == name), None)

    def all_attachments(self) -> list[Attachment]:
        """Every attachment of the world, in the order they were made."""
        return self._tables.all_attachments()

    def insert(self, handle: WorldObject, pose: PoseLike = ORIGIN) -> WorldObject:
        """Create ``handle``'s body from its spec, index it, place it at ``pose``; return it.

        The handle may be one removed earlier: it gets a new body and keeps its identity.
        """
        return self._tables.insert(handle, pose)

    def owner(self, body: int) -> WorldObject | None:
        """The object a pybullet body id (a part's too) belongs to; None if no object's."""
        return self._tables.owner(body)

    def joint_limits(self, obj: ObjectRef, joint: str) -> JointLimits:
        """Position limits [rad | m] of a movable joint; continuous ones are -inf/inf."""
        return self._tables.joint_limits(obj, joint)
