"""Qualitative relations of objects: above, below, supported by, stable.

``above(a, b)``: the bounding boxes overlap in x and y and a's box centre is higher than
b's top. ``supported_by(a, b)``: a touches b and is above it. ``stable``: simulating on
for a while moves nothing by more than 5 mm or 0.15 rad.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

from robocram.world.closest_points import contact
from robocram.world.visibility import aabb
from robocram.world.world_object import RobotObject, WorldObject

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade

STABLE_DISTANCE = 0.005  # [m]
STABLE_ANGLE = 0.15  # [rad]
STABLE_SECONDS = 0.5  # [s] simulated to see whether anything moves
OVERLAP_MARGIN = 0.0  # [m]


def above(world: WorldFacade, a: WorldObject, b: WorldObject) -> bool:
    """Whether ``a`` is over ``b``: x-y overlap and a's centre higher than b's top."""
    if a is b:
        return False
    low_a, high_a = aabb(world, a)
    low_b, high_b = aabb(world, b)
    overlap = all(
        low_a[i] <= high_b[i] + OVERLAP_MARGIN and low_b[i] <= high_a[i] + OVERLAP_MARGIN
        for i in (0, 1)
    )
    return bool(overlap and (low_a[2] + high_a[2]) / 2 > high_b[2])


def below(world: WorldFacade, a: WorldObject, b: WorldObject) -> bool:
    """Whether ``a`` is under ``b`` (``b`` above ``a``)."""
    return above(world, b, a)


def supported_by(world: WorldFacade, a: WorldObject, b: WorldObject) -> bool:
    """Whether ``a`` rests on ``b``: they touch and ``a`` is above ``b``."""
    return contact(world, a, b) and above(world, a, b)


def stable(
    world: WorldFacade,
    simulate: Callable[[float], object],
    objects: Sequence[WorldObject] | None = None,
    seconds: float = STABLE_SECONDS,
) -> bool:
    """Whether ``objects`` (default: every free movable object) stay put when ``simulate``
    runs the world on.

    Runs the simulation in place and restores the world exactly afterwards, which is the
    same as simulating a copy but avoids re-creating the bodies.
    """
    carried = {att.obj for att in world.bodies.all_attachments()}
    watched = [
        o
        for o in (objects if objects is not None else world.objects())
        if not o.is_static and not isinstance(o, RobotObject) and o.name not in carried
    ]
    if not watched:
        return True
    before = {o.name: world.pose(o) for o in watched}
    with world.snapshots.stored_state():
        simulate(seconds)
        after = {o.name: world.pose(o) for o in watched}
    return all(
        before[n].distance_to(after[n]) <= STABLE_DISTANCE
        and before[n].angle_to(after[n]) <= STABLE_ANGLE
        for n in before
    )
