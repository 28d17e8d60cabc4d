"""Body specs: the recipe of each pybullet body, so a world can re-create it.

PyBullet's own ``saveState`` cannot bring back a removed body nor drop an added one, and a
copy of a world lives in another physics client; both re-create bodies from these specs.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import pybullet

from robocram.tf import Pose, Vector3

Rgba = tuple[float, float, float, float]
ShapeKind = Literal["box", "cylinder", "sphere", "plane"]
GREY: Rgba = (0.6, 0.6, 0.6, 1.0)


@contextlib.contextmanager
def quiet_stdout() -> Iterator[None]:
    """Silence the C-level stdout/stderr chatter of Bullet's URDF importer while loading."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        os.dup2(devnull, 2)
        yield
    finally:
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for fd in (*saved, devnull):
            os.close(fd)


@dataclass(frozen=True)
class ShapeSpec:
    """A primitive body. ``size`` [m]: box extents, cylinder (diameter, diameter, height).

    A sphere uses ``size[0]`` as its diameter; a plane (the floor) ignores ``size``.
    ``mass`` [kg] 0 makes the body static.
    """

    shape: ShapeKind
    size: Vector3 = (1.0, 1.0, 1.0)
    mass: float = 0.0
    color: Rgba = GREY

    def __post_init__(self) -> None:
        if self.shape not in ("box", "cylinder", "sphere", "plane"):
            raise ValueError(f"unknown shape {self.shape!r}; use box, cylinder, sphere or plane")
        if self.shape != "plane" and min(self.size) <= 0:
            raise ValueError(f"{self.shape} size {self.size} [m] must be positive")
        if self.mass < 0:
            raise ValueError(f"mass {self.mass} [kg] must be >= 0 (0 = static)")

    def create(self, client: int) -> int:
        """Create the body in ``client`` at the origin; return its body id."""
        kw = self._geometry()
        col = pybullet.createCollisionShape(physicsClientId=client, **kw)
        vis_kw = dict(kw)
        if self.shape == "cylinder":
            vis_kw["length"] = vis_kw.pop("height")
        if self.shape == "plane":  # planes have no visual in pybullet: draw a wide thin slab
            vis_kw = {"shapeType": pybullet.GEOM_BOX, "halfExtents": (20.0, 20.0, 0.0005)}
            vis_kw["visualFramePosition"] = (0.0, 0.0, -0.0005)
        vis = pybullet.createVisualShape(physicsClientId=client, rgbaColor=self.color, **vis_kw)
        return int(pybullet.createMultiBody(self.mass, col, vis, physicsClientId=client))

    def _geometry(self) -> dict[str, object]:
        sx, sy, sz = self.size
        if self.shape == "box":
            return {"shapeType": pybullet.GEOM_BOX, "halfExtents": (sx / 2, sy / 2, sz / 2)}
        if self.shape == "cylinder":
            return {"shapeType": pybullet.GEOM_CYLINDER, "radius": sx / 2, "height": sz}
        if self.shape == "sphere":
            return {"shapeType": pybullet.GEOM_SPHERE, "radius": sx / 2}
        return {"shapeType": pybullet.GEOM_PLANE, "planeNormal": (0, 0, 1)}

    @property
    def is_static(self) -> bool:
        """Whether the body has no mass and never moves in simulation."""
        return self.mass == 0


@dataclass(frozen=True)
class MeshSpec:
    """A body from a mesh file (OBJ or STL); dynamic bodies collide with its convex hull."""

    path: Path
    scale: float = 1.0
    mass: float = 0.0
    color: Rgba = GREY

    def create(self, client: int) -> int:
        """Create the body in ``client`` at the origin; return its body id."""
        if not Path(self.path).is_file():
            raise FileNotFoundError(f"mesh file {self.path} does not exist; give an OBJ or STL")
        mesh = {"shapeType": pybullet.GEOM_MESH, "fileName": str(self.path)}
        scale = (self.scale,) * 3
        col = pybullet.createCollisionShape(meshScale=scale, physicsClientId=client, **mesh)
        vis = pybullet.createVisualShape(
            meshScale=scale, rgbaColor=self.color, physicsClientId=client, **mesh
        )
        return int(pybullet.createMultiBody(self.mass, col, vis, physicsClientId=client))

    @property
    def is_static(self) -> bool:
        """Whether the body has no mass and never moves in simulation."""
        return self.mass == 0


@dataclass(frozen=True)
class UrdfSpec:
    """A body from a URDF file; ``mass`` [kg], if given, overrides the base link's mass.

    ``frames`` name links folded into a host link before loading: they stay usable as
    frames (``World.link_pose``) at a fixed pose in their host.
    """

    path: Path
    fixed_base: bool = False
    scale: float = 1.0
    mass: float | None = None
    frames: tuple[tuple[str, str, Pose], ...] = ()  # (frame, host link, pose in host)

    def create(self, client: int) -> int:
        """Load the URDF into ``client`` at the origin; return its body id."""
        if not Path(self.path).is_file():
            raise FileNotFoundError(f"URDF file {self.path} does not exist")
        with quiet_stdout():
            body = int(
                pybullet.loadURDF(
                    str(self.path),
                    useFixedBase=self.fixed_base,
                    globalScaling=self.scale,
                    physicsClientId=client,
                )
            )
        if self.mass is not None:
            pybullet.changeDynamics(body, -1, mass=self.mass, physicsClientId=client)
        return body

    @property
    def is_static(self) -> bool:
        """Whether the body is fixed in place."""
        return self.fixed_base


BodySpec = ShapeSpec | MeshSpec | UrdfSpec
