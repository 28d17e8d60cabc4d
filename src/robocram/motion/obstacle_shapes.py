"""One world object's collision geometry in coal, where it stands, kept while it stands.

A clearance query tests the moving links against the objects around them. Reading an
object's shapes and making coal geometry of them costs milliseconds for a kitchen (268
boxes), far more than the queries of a motion; but the kitchen, the table and a mug
waiting on the counter do not move between motions. :class:`ObstacleCache` keeps each
object's :class:`ObstacleShapes` with the object's state (body, pose, joint values) and
rebuilds them only when that state changed. A cache belongs to one world and is kept
with it (:func:`obstacle_cache`, ``World.derived``): no module holds one.
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass, field
from functools import partial
from itertools import chain
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.kinematics.robot_kinematics import pose_to_se3
from robocram.logic.lru import LRUCache
from robocram.motion.coal_shapes import coal_geometries
from robocram.motion.joint_trajectory import FloatArray
from robocram.robots.lazy_library import LazyLibrary
from robocram.world import Derived, Stamp, World, WorldObject

if TYPE_CHECKING:
    import coal
    import pinocchio as pin
else:
    coal = LazyLibrary("coal")
    pin = LazyLibrary("pinocchio")

# Shapes are reused while an object's position [m], quaternion and joint values [rad | m]
# each stay within this of the state they were read in.
DRIFT_TOLERANCE = 1e-6
HUGE = 1e9  # [m] the half extents of a half-space's box
# [m] the most that moves a point of a reused object's shapes (within 10 m of its frame,
# through joints of up to 10 m of lever): clearances are lowered by it.
DRIFT = 1e-4
KEPT_STACKS = 4  # obstacle tables kept per world
KEPT_STATES = 8  # per parsed URDF: the shapes of its bodies in the last states read


@dataclass(frozen=True)
class ObstacleShapes:
    """The convex pieces of one object in map, with a map-aligned box around each."""

    obj: WorldObject
    geometries: tuple[coal.CollisionGeometry, ...]
    placements: tuple[pin.SE3, ...]  # map -> geometry
    labels: tuple[str, ...]  # per piece: "object", or "object/link" of a many-link object
    rotations: FloatArray  # (pieces, 3, 3) the placements' rotations
    translations: FloatArray  # (pieces, 3) [m] and translations
    local_centres: FloatArray  # (pieces, 3) [m] each piece's box centre in its own frame
    local_halves: FloatArray  # (pieces, 3) [m] and half extents (huge for a half-space)

    @functools.cached_property
    def centres(self) -> FloatArray:
        """(pieces, 3) [m] the centres of the map-aligned boxes (kept: the pieces do not
        move, and every new stack of a kitchen's 268 pieces asked for them again)."""
        return np.einsum("pij,pj->pi", self.rotations, self.local_centres) + self.translations

    @functools.cached_property
    def halves(self) -> FloatArray:
        """(pieces, 3) [m] their half extents."""
        return np.einsum("pij,pj->pi", np.abs(self.rotations), self.local_halves)

    @classmethod
    def of(cls, world: World, obj: WorldObject) -> ObstacleShapes:
        """Read ``obj``'s shapes from ``world`` now."""
        names = obj.index_names()
        many = len(obj.link_index) > 1
        geometries, placements, labels = [], [], []
        centres, halves = [], []
        for shape in world.contacts.collision_shapes(obj):
            index = obj.link_index.get(shape.link)
            link = names.get(index, shape.link) if index is not None else shape.link
            label = f"{obj.name}/{link}" if many else obj.name
            placement = pose_to_se3(shape.pose)
            for piece in coal_geometries(shape.kind, shape.extents, shape.mesh):
                piece.computeLocalAABB()
                if isinstance(piece, coal.Halfspace):
                    centre, half = np.zeros(3), np.full(3, HUGE)
                else:
                    box = piece.aabb_local
                    low, high = np.asarray(box.min_, float), np.asarray(box.max_, float)
                    centre, half = (low + high) / 2.0, (high - low) / 2.0
                geometries.append(piece)
                placements.append(placement)
                labels.append(label)
                centres.append(centre)
                halves.append(half)
        return cls(
            obj, tuple(geometries), tuple(placements), tuple(labels),
            np.array([p.rotation for p in placements], dtype=float).reshape(-1, 3, 3),
            np.array([p.translation for p in placements], dtype=float).reshape(-1, 3),
            np.array(centres, dtype=float).reshape(-1, 3),
            np.array(halves, dtype=float).reshape(-1, 3),
        )  # fmt: skip

    def moved(self, delta: pin.SE3) -> ObstacleShapes:
        """The same pieces after the whole object moved by ``delta`` (in map): cheaper
        than reading its shapes again (a settling bowl, a placed mug)."""
        rotation, translation = np.asarray(delta.rotation), np.asarray(delta.translation)
        return dataclasses.replace(
            self,
            placements=tuple(delta * p for p in self.placements),
            rotations=np.einsum("ij,pjk->pik", rotation, self.rotations),
            translations=self.translations @ rotation.T + translation,
        )


@dataclass(frozen=True)
class StackedShapes:
    """Several objects' pieces as one table, for the pairs of a check."""

    shapes: tuple[ObstacleShapes, ...]
    owner: NDArray[np.intp]  # per piece: its object's index in ``shapes``
    geometries: tuple[coal.CollisionGeometry, ...]
    placements: tuple[pin.SE3, ...]
    labels: tuple[str, ...]
    centres: FloatArray  # (pieces, 3)
    halves: FloatArray  # (pieces, 3)

    @classmethod
    def of(cls, shapes: list[ObstacleShapes]) -> StackedShapes:
        """Stack ``shapes`` in order."""
        counts = [len(s.labels) for s in shapes]
        return cls(
            tuple(shapes),
            np.repeat(np.arange(len(shapes), dtype=np.intp), counts),
            tuple(chain.from_iterable(s.geometries for s in shapes)),
            tuple(chain.from_iterable(s.placements for s in shapes)),
            tuple(chain.from_iterable(s.labels for s in shapes)),
            np.concatenate([s.centres for s in shapes]) if shapes else np.zeros((0, 3)),
            np.concatenate([s.halves for s in shapes]) if shapes else np.zeros((0, 3)),
        )


@dataclass
class ObstacleCache:
    """Per object of one world: its shapes, and the state they were read in.

    Shapes are kept while the object's state stays within :data:`DRIFT_TOLERANCE` of the
    state they were read in (a settled kitchen's drawers creep by 1e-8 under simulation);
    :data:`DRIFT` bounds how far that can move any point of them.
    """

    # per object: it, the state its shapes were read in, the shapes, that state's base
    # pose (a moved object's next move starts from it)
    _entries: dict[str, tuple[WorldObject, NDArray[np.float64], ObstacleShapes, pin.SE3]] = field(
        default_factory=dict
    )
    builds: int = 0  # how many times shapes were read (for tests and figures)
    _stacked: Derived[tuple[int, ...], StackedShapes] = field(
        default_factory=lambda: Derived(size=KEPT_STACKS)
    )
    _read: dict[str, Stamp] = field(default_factory=dict)  # counters when last seen so

    def stacked(self, shapes: list[ObstacleShapes]) -> StackedShapes:
        """``shapes`` as one table, kept for the last :data:`KEPT_STACKS` sets asked for
        (checkers with and without a held object alternate). A kept stack holds its
        shapes, so the ids in its key are not reused while it is kept."""
        key = tuple(id(s) for s in shapes)
        return self._stacked.get(key, partial(StackedShapes.of, shapes))

    def shapes(self, world: World, obj: WorldObject) -> ObstacleShapes:
        """``obj``'s shapes as it stands now: the kept ones if its state is unchanged."""
        stamp = world.versions.body(obj.name)
        entry = self._entries.get(obj.name)
        if entry is not None and entry[0] is obj and self._read.get(obj.name) == stamp:
            return entry[2]  # nothing wrote to it since it was last seen: no compare
        state = np.array(world.snapshots.body_state(obj), dtype=float)
        if entry is not None and entry[0] is obj and _near(entry[1], state):
            self._read[obj.name] = stamp
            return entry[2]
        base = _base(state)
        if entry is not None and entry[0] is obj and _rigidly_moved(entry[1], state):
            shapes = entry[2].moved(base * entry[3].inverse())
        else:
            shapes = _shapes_in_state(world, obj, state)
            self.builds += 1
        self._entries[obj.name] = (obj, state, shapes, base)
        self._read[obj.name] = stamp
        return shapes


def _shapes_in_state(world: World, obj: WorldObject, state: NDArray[np.float64]) -> ObstacleShapes:
    """``obj``'s shapes read now, or those a body of the same model read in the same state
    in any world (kept on the parsed URDF the bodies share: each new kitchen scene read its
    268 pieces again). The key holds all the reading depends on: the body's spec, its
    exact state (body id, base pose, joint values), its links' indices and offsets."""
    model = obj.urdf_model
    if model is None:
        return ObstacleShapes.of(world, obj)
    key = (
        obj.name, obj.type, obj.spec, state.tobytes(), tuple(obj.link_index.items()),
        tuple(obj.link_offset.items()), obj.parts, obj.part_offsets,
    )  # fmt: skip
    kept = model.derived(_kept_in_states)
    found = kept.get(key)
    if found is None:
        found = ObstacleShapes.of(world, obj)
        kept.put(key, found)
        return found
    return dataclasses.replace(found, obj=obj)  # the geometry is read-only: shared


def _kept_in_states(model: object) -> LRUCache[tuple[object, ...], ObstacleShapes]:
    """The shapes a parsed URDF keeps, per body and state (a few: doors open or shut)."""
    return LRUCache(KEPT_STATES)


def _near(kept: NDArray[np.float64], now: NDArray[np.float64]) -> bool:
    return (
        kept.shape == now.shape
        and kept[0] == now[0]
        and float(np.abs(kept - now).max()) <= DRIFT_TOLERANCE
    )


def _rigidly_moved(kept: NDArray[np.float64], now: NDArray[np.float64]) -> bool:
    """Whether only the base pose changed: same body, same joint values."""
    return kept.shape == now.shape and kept[0] == now[0] and bool((kept[8:] == now[8:]).all())


def _base(state: NDArray[np.float64]) -> pin.SE3:
    """The body's base pose in a state (position, then quaternion x, y, z, w)."""
    x, y, z, w = state[4:8]
    return pin.SE3(pin.Quaternion(w, x, y, z).toRotationMatrix(), state[1:4].copy())


def obstacle_cache(world: World) -> ObstacleCache:
    """The cache of ``world``'s obstacle shapes, kept with the world (``World.derived``)."""
    return world.derived(_new_cache)


def _new_cache(world: World) -> ObstacleCache:
    return ObstacleCache()
