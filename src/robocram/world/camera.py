"""A pinhole camera in the world: optical-frame pose, field of view and clip planes.

The optical frame follows ROS: z forward, x right, y down. Rays and renders share these
intrinsics, so the two visibility methods look through the same frustum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from robocram.tf import Pose
from robocram.world.errors import WorldValueError
from robocram.world.pybullet_backend import pybullet


@dataclass(frozen=True)
class Camera:
    """Optical-frame pose in the world and the field of view [rad]."""

    pose: Pose
    horizontal_fov: float = math.radians(60.0)
    vertical_fov: float = math.radians(45.0)
    near: float = 0.05  # [m] nothing closer is seen
    far: float = 20.0  # [m] nothing further is seen

    def __post_init__(self) -> None:
        for name in ("horizontal_fov", "vertical_fov"):
            fov = getattr(self, name)
            if not 0 < fov < math.pi:
                raise WorldValueError(f"{name} {fov} [rad] must be in (0, pi)")
        if not 0 < self.near < self.far:
            raise WorldValueError(f"need 0 < near ({self.near}) < far ({self.far}) [m]")

    @property
    def tan_half(self) -> tuple[float, float]:
        """``tan(hfov / 2), tan(vfov / 2)``: the image half-extents at unit depth."""
        return math.tan(self.horizontal_fov / 2), math.tan(self.vertical_fov / 2)

    def widened(self, factor: float) -> Camera:
        """The same camera with the image half-extents (in tangent space) times ``factor``."""
        th, tv = self.tan_half
        return replace(
            self,
            horizontal_fov=2 * math.atan(th * factor),
            vertical_fov=2 * math.atan(tv * factor),
        )

    def with_aspect(self, aspect: float) -> Camera:
        """The same vertical field of view with the horizontal one set by ``aspect`` = w / h."""
        tv = self.tan_half[1]
        return replace(self, horizontal_fov=2 * math.atan(tv * aspect))

    def shifted(self, offset: tuple[float, float, float]) -> Camera:
        """The same camera translated by ``offset`` [m] in the world."""
        p = self.pose.position
        moved = (p[0] + offset[0], p[1] + offset[1], p[2] + offset[2])
        return replace(self, pose=Pose(moved, self.pose.orientation))

    def to_optical(self, points_world: NDArray[np.float64]) -> NDArray[np.float64]:
        """Points (N x 3) from world coordinates into the optical frame."""
        m = self.pose.inverse().matrix()
        return np.asarray(points_world @ m[:3, :3].T + m[:3, 3], dtype=np.float64)

    def ray_ends(self, tangents: NDArray[np.float64]) -> tuple[NDArray, NDArray]:
        """World start (at ``near``) and end (at ``far``) points of rays through image tangents.

        ``tangents`` (N x 2) are ``(x / z, y / z)`` in the optical frame.
        """
        dirs = np.column_stack([tangents, np.ones(len(tangents))])
        dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
        m = self.pose.matrix()
        world_dirs = dirs @ m[:3, :3].T
        origin = m[:3, 3]
        return origin + self.near * world_dirs, origin + self.far * world_dirs

    def image_size(self, height: int) -> tuple[int, int]:
        """``(width, height)`` in pixels with square pixels for this field of view."""
        th, tv = self.tan_half
        return max(1, round(height * th / tv)), height

    def view_matrix(self) -> list[float]:
        """OpenGL view matrix of the optical frame (looking along z, y pointing down)."""
        m = self.pose.matrix()
        eye = m[:3, 3]
        target = eye + m[:3, 2]
        up = -m[:3, 1]
        return list(pybullet.computeViewMatrix(eye.tolist(), target.tolist(), up.tolist()))

    def projection_matrix(self) -> list[float]:
        """OpenGL projection matrix of the field of view and clip planes."""
        th, tv = self.tan_half
        return list(
            pybullet.computeProjectionMatrixFOV(
                math.degrees(self.vertical_fov), th / tv, self.near, self.far
            )
        )
