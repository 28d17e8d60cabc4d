"""One point of closest approach between two bodies, as the world reports it."""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Vector3


@dataclass(frozen=True)
class ContactPoint:
    """Where ``link_a`` of ``obj_a`` comes nearest ``link_b`` of ``obj_b``.

    ``distance`` [m] is signed: negative when the bodies penetrate. ``normal_on_b`` points
    from ``obj_b`` towards ``obj_a``. Positions are in the world frame [m].
    """

    obj_a: str
    obj_b: str
    link_a: str
    link_b: str
    position_on_a: Vector3
    position_on_b: Vector3
    normal_on_b: Vector3
    distance: float  # [m]
