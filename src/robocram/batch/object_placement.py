"""Where a variant puts the scene's objects: shifts from the scene's poses, or absolute poses.

A shift is ``(dx, dy, dz)`` [m] or ``(dx, dy, dz, dyaw)`` [m, rad] from where the scene put
the object; an absolute pose (in ``map``) is ``(x, y, z, yaw)``, ``(x, y, z)`` (upright,
yaw 0), ``((x, y, z), (qx, qy, qz, qw))``, ``(x, y, z, qx, qy, qz, qw)`` or a
:class:`~robocram.tf.Pose`. Both are stored as
plain tuples so a variant pickles anywhere and compares by value.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping
from typing import Any, TypeVar

import numpy as np

from robocram.batch.errors import BadVariant
from robocram.tf import Pose, quaternion
from robocram.world import World

Shift = tuple[float, float, float, float]  # dx, dy, dz [m], dyaw [rad]
Pose7 = tuple[float, float, float, float, float, float, float]  # x, y, z [m], qx, qy, qz, qw
Placements = Mapping[str, Any] | Iterable[tuple[str, Any]]  # object name -> placement
T = TypeVar("T")

POSE_FORMS = (
    "(x, y, z, yaw), (x, y, z), ((x, y, z), (qx, qy, qz, qw)), (x, y, z, qx, qy, qz, qw) "
    "or a Pose [m, rad]"
)


def _items(value: Placements, field: str) -> list[Any]:
    if isinstance(value, str | bytes) or not isinstance(value, Mapping | Iterable):
        raise BadVariant(field, value, "give a mapping of object name -> placement")
    items = list(value.items() if isinstance(value, Mapping) else value)
    for item in items:
        if not (isinstance(item, tuple) and len(item) == 2 and isinstance(item[0], str)):
            raise BadVariant(field, item, "give a mapping of object name -> placement")
    return items


def _finite(value: object, size: tuple[int, ...]) -> tuple[float, ...] | None:
    """``value`` as floats if it is a sequence of one of the ``size``s of finite numbers."""
    try:
        out = tuple(float(c) for c in value)  # type: ignore[attr-defined]
    except (TypeError, ValueError):
        return None
    if len(out) not in size or not all(math.isfinite(c) for c in out):
        return None
    return out


def _shift(value: object) -> Shift | None:
    v = _finite(value, (3, 4))
    return None if v is None else (v[0], v[1], v[2], v[3] if len(v) == 4 else 0.0)


def _pose7(value: object) -> Pose7 | None:
    if isinstance(value, Pose):
        return (*value.position, *value.orientation)
    flat = _finite(value, (3, 4, 7))
    if flat is not None and len(flat) == 7 and any(flat[3:]):  # the stored form
        return (flat[0], flat[1], flat[2], *quaternion.normalized(flat[3:]))
    if flat is not None and len(flat) in (3, 4):
        yaw = flat[3] if len(flat) == 4 else 0.0
        return (flat[0], flat[1], flat[2], *quaternion.from_euler(0.0, 0.0, yaw))
    if isinstance(value, tuple | list) and len(value) == 2:
        position, orientation = _finite(value[0], (3,)), _finite(value[1], (4,))
        if position is not None and orientation is not None and any(orientation):
            return (*position, *quaternion.normalized(orientation))  # type: ignore[return-value]
    return None


def _coerce(
    value: Placements, field: str, read: Callable[[object], T | None], fix: str
) -> tuple[tuple[str, T], ...]:
    out: dict[str, T] = {}
    for name, given in _items(value, field):
        placement = read(given)
        if placement is None:
            raise BadVariant(f"{field}[{name!r}]", given, fix)
        out[name] = placement
    return tuple(sorted(out.items()))


def coerce_shifts(value: Placements) -> tuple[tuple[str, Shift], ...]:
    """Object shifts as sorted ``(name, (dx, dy, dz, dyaw))`` pairs, or :class:`BadVariant`."""
    return _coerce(value, "object_shifts", _shift, "give a finite (dx, dy, dz[, dyaw]) [m, rad]")


def coerce_poses(value: Placements) -> tuple[tuple[str, Pose7], ...]:
    """Absolute object poses (map) as sorted ``(name, pose7)`` pairs, or :class:`BadVariant`."""
    return _coerce(value, "object_poses", _pose7, f"give {POSE_FORMS}")


def place_objects(
    world: World,
    variant: str,
    shifts: tuple[tuple[str, Shift], ...],
    poses: tuple[tuple[str, Pose7], ...],
    jitter: float,
    seed: int,
) -> None:
    """Move the objects in ``world``; ``jitter`` [m] adds a seeded xy noise to each one.

    Raises:
        BadVariant: an object is not in the world (the message lists the ones that are).
    """
    rng = np.random.default_rng(seed)
    moves = [(name, _shifted(world.pose(_known(world, name, variant)), s)) for name, s in shifts]
    moves += [(_known(world, name, variant), Pose(p[:3], p[3:])) for name, p in poses]
    for name, pose in moves:
        jx, jy = rng.normal(0.0, jitter, 2) if jitter > 0 else (0.0, 0.0)
        x, y, z = pose.position
        world.set_pose(name, Pose((x + jx, y + jy, z), pose.orientation))


def _known(world: World, name: str, variant: str) -> str:
    if name not in world:
        known = ", ".join(sorted(o.name for o in world.objects()))
        raise BadVariant(f"{variant}: object", name, f"not in the scene; use one of {known}")
    return name


def _shifted(pose: Pose, shift: Shift) -> Pose:
    dx, dy, dz, dyaw = shift
    x, y, z = pose.position
    turn = quaternion.from_euler(0.0, 0.0, dyaw)
    return Pose((x + dx, y + dy, z + dz), quaternion.multiply(turn, pose.orientation))
