"""The contacts part of a world: what touches what, how near links come, and the
bounds and shapes those answers are made from.

Reached as ``world.contacts``. A robot and the objects attached to it never collide
with each other here, but :meth:`Contacts.contact_points` is the raw geometry.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Sequence
from functools import partial
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.logic.lru import LRUCache
from robocram.tf import Vector3
from robocram.world import closest_points, link_contacts, visibility
from robocram.world.body_slots import link_slot
from robocram.world.collision_shapes import CollisionShape, collision_shapes
from robocram.world.contact_point import ContactPoint
from robocram.world.derived import Derived
from robocram.world.obstacle_boxes import KeptObstacleBoxes, ObstacleBoxes
from robocram.world.versions import Versions
from robocram.world.world_object import RobotObject, WorldObject
from robocram.world.world_part import WorldPart
from robocram.world.world_tables import ObjectRef, WorldTables

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade


class Contacts(WorldPart):
    """Collisions, contact points, link distances and link bounds of one world."""

    def __init__(self, world: WorldFacade, tables: WorldTables):
        super().__init__(world, tables)
        self._radii: Derived[str, dict[str, float]] = Derived(Versions.created)  # link -> [m]
        self._boxes = KeptObstacleBoxes()

    def link_aabb(self, obj: ObjectRef, link: str) -> tuple[Vector3, Vector3]:
        """World-aligned bounds ``(lower, upper)`` [m] of one link of ``obj``."""
        w = self._world
        handle = w.object(obj)
        low, high = visibility.link_aabb(w, handle, link_slot(handle, link))
        return (low[0], low[1], low[2]), (high[0], high[1], high[2])

    def link_aabbs(self, obj: ObjectRef) -> dict[str, tuple[Vector3, Vector3]]:
        """World-aligned bounds ``(lower, upper)`` [m] of every link of ``obj``, by link name.

        One entry per body part (a frame folded into its host link is not repeated); a
        single-shape body has one, under the object's name.
        """
        handle = self._world.object(obj)
        names: dict[int, str] = {}
        for name, index in handle.link_index.items():
            names.setdefault(index, name)
        names.setdefault(-1, handle.name)
        return {
            name: visibility.link_aabb(self._world, handle, i) for i, name in sorted(names.items())
        }

    def collision_shapes(self, obj: ObjectRef) -> list[CollisionShape]:
        """The collision shapes of ``obj`` at their current poses in map (a snapshot)."""
        return collision_shapes(self._world, self._world.object(obj))

    def collisions(
        self, obj: ObjectRef, ignore: Iterable[ObjectRef] = (), distance: float = 0.002
    ) -> list[WorldObject]:
        """Objects touching or penetrating ``obj`` within ``distance`` [m].

        A robot and the objects attached to it never collide with each other.
        """
        w = self._world
        skip = [w.object(o) for o in ignore]
        touched = {
            name for _, name in link_contacts.link_contacts(w, w.object(obj), None, skip, distance)
        }
        return [o for o in w.objects() if o.name in touched]  # the world's order

    def in_collision(
        self, obj: ObjectRef, ignore: Iterable[ObjectRef] = (), ignore_floor: bool = True
    ) -> bool:
        """Whether ``obj`` touches anything but ``ignore`` and what it carries.

        Objects of type ``floor`` are ignored unless ``ignore_floor`` is False: robot bases
        (HSR, Boxy) stand on it.
        """
        skip = list(ignore) + (self._world.objects(type="floor") if ignore_floor else [])
        return bool(self.collisions(obj, skip))

    def link_pairs_in_contact(
        self,
        obj: ObjectRef,
        ignore: Iterable[ObjectRef] = (),
        distance: float = 0.0,
        links: Iterable[str] | None = None,
        obstacles: ObstacleBoxes | None = None,
    ) -> list[tuple[str, WorldObject, str]]:
        """``(link of obj, other object, its link)`` triples within ``distance`` [m].

        Found through Bullet's broadphase, so a robot in a kitchen of hundreds of links
        costs only the pairs whose bounds overlap. Nothing is skipped but ``ignore``;
        ``links`` limits the links of ``obj`` asked about (default: all). ``obstacles``
        (:meth:`obstacle_boxes`, read since only ``obj`` moved) replaces the broadphase.
        """
        w = self._world
        skip = [w.object(o) for o in ignore]
        return link_contacts.link_pairs_in_contact(
            w, w.object(obj), skip, distance, links, obstacles
        )

    def obstacle_boxes(self, ignore: Iterable[ObjectRef] = ()) -> ObstacleBoxes:
        """The bounds of every link of every object but ``ignore``, read now: pass them to
        :meth:`link_distances` and :meth:`link_pairs_in_contact` while nothing else moves."""
        w = self._world
        names = [w.object(o).name for o in ignore]
        return self._boxes.boxes(w, names)

    def link_radii(self, obj: ObjectRef) -> dict[str, float]:
        """Per link of ``obj``: a radius [m] about the link's frame that holds its shapes.

        Taken once per body from its world-aligned bounds at the pose it is in (such a box
        holds the link's shapes whatever its orientation, so the radius bounds them
        forever: the shapes are rigid in the link's frame).
        """
        handle = self._world.object(obj)
        made = partial(self._link_radii, handle)
        return dict(self._radii.get(handle.name, made, self._world.versions))

    def _link_radii(self, handle: WorldObject) -> dict[str, float]:
        """The radii read now, or those read of a body of the same model in the same
        state in any world (kept on the model: a new scene's robot asks again). The key
        holds all they follow from: the body's spec, links, pose and joint values."""
        w = self._world
        model = handle.description.model if isinstance(handle, RobotObject) else handle.urdf_model
        if model is None:
            return self._read_radii(handle)
        key = (
            handle.name, handle.spec, tuple(w.link_names(handle)), w.pose(handle),
            tuple(w.joint_states(handle).items()), tuple(handle.link_offset.items()),
        )  # fmt: skip
        kept = model.derived(_radii_of_model)
        found = kept.get(key)
        if found is None:
            found = self._read_radii(handle)
            kept.put(key, found)
        return found  # never handed out itself: link_radii copies it

    def _read_radii(self, handle: WorldObject) -> dict[str, float]:
        radii = {}
        for link in self._world.link_names(handle):
            origin = np.array(self._world.link_pose(handle, link).position)
            low, high = self.link_aabb(handle, link)
            far = np.maximum(np.abs(np.subtract(low, origin)), np.abs(np.subtract(high, origin)))
            radii[link] = float(np.linalg.norm(far))
        return radii

    def link_distances(
        self,
        obj: ObjectRef,
        ignore: Iterable[ObjectRef] = (),
        distance: float = 0.05,
        links: Iterable[str] | None = None,
        obstacles: ObstacleBoxes | None = None,
    ) -> list[tuple[str, WorldObject, str, float]]:
        """``(link of obj, other object, its link, distance [m])`` nearer than ``distance``.

        The distance is the smallest between the two links (negative: penetration); a
        planner steps as far as the nearest one allows. Nothing is skipped but ``ignore``.
        """
        w = self._world
        skip = [w.object(o) for o in ignore]
        return link_contacts.link_distances(w, w.object(obj), skip, distance, links, obstacles)

    def self_contacts(
        self, obj: ObjectRef, pairs: Iterable[tuple[str, str]], distance: float = 0.0
    ) -> list[tuple[str, str]]:
        """The pairs of ``obj``'s own links among ``pairs`` nearer than ``distance`` [m]."""
        w = self._world
        return link_contacts.self_contacts(w, w.object(obj), pairs, distance)

    def self_distances(
        self,
        obj: ObjectRef,
        pairs: Sequence[tuple[str, str]],
        reach: float,
        exact: Callable[[NDArray[np.float64]], Iterable[int]] | None = None,
    ) -> NDArray[np.float64]:
        """Per pair of ``obj``'s own links: a lower bound [m] on their distance, exact
        (negative: penetration depth) where their bounds come within ``reach`` or for
        the pairs ``exact`` picks from the bounds' gaps."""
        w = self._world
        return link_contacts.self_distances(w, w.object(obj), pairs, reach, exact)

    def contact_points(
        self,
        a: ObjectRef,
        b: ObjectRef | None = None,
        link_a: str | None = None,
        link_b: str | None = None,
        distance: float = 0.0,
    ) -> list[ContactPoint]:
        """Points where ``a`` (or its ``link_a``) comes within ``distance`` [m] of ``b``.

        ``b`` None means every other object. ``distance`` 0 gives touching and penetrating
        points; a larger one also gives near misses (``ContactPoint.distance`` > 0).
        Attachments are not skipped here: this is the raw geometry.
        """
        w = self._world
        first = w.object(a)
        others = [w.object(b)] if b is not None else [o for o in w if o is not first]
        return [
            point
            for other in others
            for point in closest_points.closest_points(w, first, other, distance, link_a, link_b)
        ]

    def links_contact_points(
        self, a: ObjectRef, links: Collection[str], b: ObjectRef, distance: float = 0.0
    ) -> list[ContactPoint]:
        """:meth:`contact_points` of ``a`` and ``b`` on ``a``'s ``links`` only (points are
        named by the first name of their link): a gripper's links asked alone cost a
        fraction of the whole robot."""
        w = self._world
        return closest_points.links_closest_points(w, w.object(a), links, w.object(b), distance)

    def contact(self, a: ObjectRef, b: ObjectRef) -> bool:
        """Whether ``a`` and ``b`` touch (within 2 mm)."""
        w = self._world
        return closest_points.contact(w, w.object(a), w.object(b))


KEPT_RADII = 8  # per model: the radii of its bodies in the last states read


def _radii_of_model(model: object) -> LRUCache[tuple[object, ...], dict[str, float]]:
    """The link radii a model keeps per body and state (never changed once read)."""
    return LRUCache(KEPT_RADII)
