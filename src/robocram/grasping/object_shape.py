"""What the grasp model knows of an object: its box in its own frame, its wall, its handle.

The box is the object's axis-aligned bounding box in the object's own frame (read with the
object turned upright in place, then put back), so a turned object keeps its sizes. Whether
it is hollow (a wall the fingers may straddle at the rim) or has a handle (a bar the
fingers may close on) the knowledge base says (``object_grasps.py``):
``object_wall(Type, Thickness)`` and ``object_handle(Type, Width)``, both in metres.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import lru_cache

from robocram.grasping.errors import GraspingError
from robocram.tf import Pose, Vector3
from robocram.world import UnknownItemError, World, WorldObject, catalogue_names


@dataclass(frozen=True)
class ObjectShape:
    """Bounding box ``low``/``high`` [m] in the object's frame, wall and handle bar [m]."""

    name: str
    low: Vector3
    high: Vector3
    wall: float | None = None
    handle: float | None = None

    @property
    def size(self) -> Vector3:
        """Extents [m] along the object's x, y and z."""
        return (
            self.high[0] - self.low[0],
            self.high[1] - self.low[1],
            self.high[2] - self.low[2],
        )

    @property
    def centre(self) -> tuple[float, float]:
        """The body's axis [m] (x, y): the origin if inside the box, else the box's middle.

        A handle widens the box to one side; the origin of a mug stays on its body's axis.
        """
        return (
            _inside(0.0, self.low[0], self.high[0]),
            _inside(0.0, self.low[1], self.high[1]),
        )

    @property
    def radius(self) -> float:
        """[m] from the body's axis to the nearest side of the box (a round body's radius)."""
        cx, cy = self.centre
        return min(self.high[0] - cx, cx - self.low[0], self.high[1] - cy, cy - self.low[1])

    def reach(self, side: Vector3) -> float:
        """[m] from the body's axis to the box's side in direction ``side`` (an axis)."""
        cx, cy = self.centre
        if side[0]:
            return self.high[0] - cx if side[0] > 0 else cx - self.low[0]
        return self.high[1] - cy if side[1] > 0 else cy - self.low[1]


def _inside(value: float, low: float, high: float) -> float:
    return value if low < value < high else (low + high) / 2


def shape_of(
    world: World, obj: WorldObject, wall: float | None = None, handle: float | None = None
) -> ObjectShape:
    """The shape of ``obj`` in ``world``, its box measured in its own frame."""
    pose = world.pose(obj)
    upright = pose.orientation == (0.0, 0.0, 0.0, 1.0)
    if not upright:
        world.set_pose(obj, Pose(pose.position))
    try:
        low, high = world.aabb(obj)
    finally:
        if not upright:
            world.set_pose(obj, pose)
    x, y, z = pose.position
    return ObjectShape(
        obj.name,
        (low[0] - x, low[1] - y, low[2] - z),
        (high[0] - x, high[1] - y, high[2] - z),
        wall,
        handle,
    )


@lru_cache(maxsize=64)
def _measured(kind: str) -> ObjectShape:
    with World() as world:
        return shape_of(world, world.add_item(kind, kind))


def catalogue_shape(
    kind: str, name: str, wall: float | None = None, handle: float | None = None
) -> ObjectShape:
    """The shape of a catalogue item of type ``kind`` (measured once per process).

    For environments without a world (recording, a real robot): the object's type says
    its size.

    Raises:
        GraspingError: ``kind`` is not in the catalogue, so its size is unknown.
    """
    try:
        measured = _measured(kind)
    except UnknownItemError as err:
        raise GraspingError(
            f"no shape for {name!r}: its type {kind!r} is not in the catalogue "
            f"({', '.join(catalogue_names())}); grasp it in a world that holds it"
        ) from err
    return replace(measured, name=name, wall=wall, handle=handle)
