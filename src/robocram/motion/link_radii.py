"""How far a robot link's collision shapes reach from the link's own frame, exactly.

The world's radii (``world.contacts.link_radii``) come from world-aligned bounds read at load
and may be 1.7 times the true reach of a link turned across them (a PR2's shoulder pan
link: 0.58 m against 0.27 m). A walk that steps by levers (joint axis to frame plus the
radius) takes steps in proportion: here the radius is read off the shapes themselves, as
PyBullet collides them (:mod:`~robocram.motion.robot_geometry`): every vertex of a convex
hull, the corners of a primitive's own box.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from robocram.motion.robot_geometry import RobotGeometry
from robocram.robots import RobotModel
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import coal
else:
    coal = LazyLibrary("coal")


def shape_radii(model: RobotModel) -> dict[str, float]:
    """Per link with collision shapes: the farthest [m] a point of them is from its frame.
    Kept with the model (``model.derived(shape_radii)``)."""
    geometry = model.derived(RobotGeometry.of)
    radii: dict[str, float] = {}
    for link, parts in geometry.parts.items():
        _, frame = geometry.frame(link)  # the link's frame in its joint's (4x4)
        joint_to_link = np.linalg.inv(frame)
        far = 0.0
        for part in parts:
            local = _points(part.geometry)  # (n, 3) in the geometry's frame
            in_joint = local @ np.asarray(part.placement.rotation).T + np.asarray(
                part.placement.translation
            )
            in_link = in_joint @ joint_to_link[:3, :3].T + joint_to_link[:3, 3]
            far = max(far, float(np.sqrt((in_link * in_link).sum(axis=1)).max()))
        radii[link] = far
    return radii


def _points(shape: coal.CollisionGeometry) -> np.ndarray:
    """Points whose hull holds ``shape``: a convex hull's vertices, else its box's corners."""
    if isinstance(shape, coal.ConvexBase):
        return np.asarray(shape.points(), dtype=float).reshape(-1, 3)
    shape.computeLocalAABB()
    box = shape.aabb_local
    low, high = np.asarray(box.min_, dtype=float), np.asarray(box.max_, dtype=float)
    return np.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1])
                     for z in (low[2], high[2])])  # fmt: skip
