"""The view part of a world: robot cameras, what they see, images, and rays.

Reached as ``world.view``. Visibility is judged by rays (default) or by a rendered
segmentation image; both count occlusion and the image edges.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from robocram.tf import Pose, PoseLike, Vector3
from robocram.world import visibility
from robocram.world.camera import Camera
from robocram.world.errors import NoCameraError, WorldValueError
from robocram.world.png import write_png
from robocram.world.pybullet_backend import pybullet
from robocram.world.ray_hit import RayHit, cast_rays
from robocram.world.visibility import Visibility
from robocram.world.world_object import WorldObject
from robocram.world.world_part import WorldPart
from robocram.world.world_tables import ObjectRef

VisibilityMethod = Literal["ray", "render"]
DEFAULT_VISIBILITY: VisibilityMethod = "ray"


class View(WorldPart):
    """Cameras, visibility, rendering and ray casts in one world."""

    def camera(self, robot: ObjectRef, camera: str | None = None) -> Camera:
        """The robot's camera (by name; default the first) at its current pose."""
        handle = self._world.robot(robot)
        cams = handle.description.cameras
        chosen = [c for c in cams if camera is None or c.name == camera]
        if not chosen:
            raise NoCameraError(handle.name, camera, [c.name for c in cams])
        c = chosen[0]
        return Camera(self._world.link_pose(handle, c.frame), c.horizontal_fov, c.vertical_fov)

    def visibility_from(
        self, camera: Camera, obj: ObjectRef, method: VisibilityMethod = DEFAULT_VISIBILITY
    ) -> Visibility:
        """Seen fraction and occluders of ``obj`` from ``camera`` by rays or by a render."""
        handle = self._world.object(obj)
        if method == "ray":
            return visibility.ray_visibility(self._world, camera, handle)
        if method == "render":
            return visibility.render_visibility(self._world, camera, handle)
        raise WorldValueError(f"unknown visibility method {method!r}; use 'ray' or 'render'")

    def visibility_fraction(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> float:
        """Share (0..1) of ``obj`` the robot's camera sees, occlusion and image edges counted."""
        return self.visibility_from(self.camera(robot, camera), obj, method).fraction

    def visible(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        threshold: float = 0.9,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> bool:
        """Whether the robot's camera sees at least ``threshold`` of ``obj``."""
        return self.visibility_fraction(robot, obj, camera, method) >= threshold

    def visible_from(
        self,
        camera: Camera | PoseLike,
        obj: ObjectRef,
        threshold: float = 0.9,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> bool:
        """Whether a camera (a :class:`Camera`, or an optical-frame pose) sees ``obj``."""
        cam = camera if isinstance(camera, Camera) else Camera(Pose.coerce(camera))
        return self.visibility_from(cam, obj, method).fraction >= threshold

    def occluding_objects(
        self,
        robot: ObjectRef,
        obj: ObjectRef,
        camera: str | None = None,
        method: VisibilityMethod = DEFAULT_VISIBILITY,
    ) -> list[WorldObject]:
        """Objects between the robot's camera and ``obj`` (the robot itself may be one)."""
        names = self.visibility_from(self.camera(robot, camera), obj, method).occluders
        return [self._world.object(n) for n in names]

    def render(
        self, camera: Camera | PoseLike, width: int = 640, height: int = 480
    ) -> NDArray[np.uint8]:
        """An ``height x width x 3`` RGB image from ``camera`` (TINY renderer, no window)."""
        cam = camera if isinstance(camera, Camera) else Camera(Pose.coerce(camera))
        cam = cam.with_aspect(width / height)
        _, _, rgba, _, _ = pybullet.getCameraImage(
            width, height, cam.view_matrix(), cam.projection_matrix(),
            renderer=pybullet.ER_TINY_RENDERER, physicsClientId=self._tables.physics_client(),
        )  # fmt: skip
        return np.reshape(np.asarray(rgba, dtype=np.uint8), (height, width, 4))[:, :, :3].copy()

    def save_png(
        self, path: str | Path, camera: Camera | PoseLike, width: int = 640, height: int = 480
    ) -> Path:
        """Render from ``camera`` and write the image to ``path`` as PNG."""
        return write_png(path, self.render(camera, width, height))

    def ray_cast(self, start: Vector3, end: Vector3) -> RayHit | None:
        """The first object on the segment ``start``..``end`` [m], or None."""
        return self.ray_cast_batch([start], [end])[0]

    def ray_cast_batch(
        self, starts: Sequence[Vector3], ends: Sequence[Vector3]
    ) -> list[RayHit | None]:
        """:meth:`ray_cast` for many rays in one pybullet call."""
        if len(starts) != len(ends):
            raise WorldValueError(f"{len(starts)} ray starts but {len(ends)} ends")
        return cast_rays(self._world, starts, ends)
