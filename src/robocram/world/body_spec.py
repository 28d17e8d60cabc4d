"""Body specs: the recipe of each pybullet body, so a world can re-create it.

PyBullet's own ``saveState`` cannot bring back a removed body nor drop an added one, and a
copy of a world lives in another physics client; both re-create bodies from these specs.
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Literal

from robocram.tf import Pose, Vector3
from robocram.world.errors import WorldValueError
from robocram.world.pybullet_backend import pybullet

if TYPE_CHECKING:
    from robocram.robots import RobotModel

Rgba = tuple[float, float, float, float]
ShapeKind = Literal["box", "cylinder", "sphere", "plane"]
GREY: Rgba = (0.6, 0.6, 0.6, 1.0)


# Bullet prefixes each message with b3Error[file,line]: or b3Warning[file,line]:
_MESSAGE = re.compile(r"b3(Error|Warning)\[[^\]]*\]:\s*(.*?)(?=b3(?:Error|Warning)\[|\Z)", re.S)


@dataclass
class Chatter:
    """What Bullet's importer printed while loading; ``text`` is set when the block ends."""

    text: str = ""

    def reason(self) -> str:
        """Bullet's errors, after the warning that caused them ("cannot find 'x.obj'")."""
        said = [(kind, text.strip()) for kind, text in _MESSAGE.findall(self.text) if text.strip()]
        first_error = next((i for i, (kind, _) in enumerate(said) if kind == "Error"), None)
        if first_error is None:
            return " ".join(text for _, text in said[-2:])
        cause = [said[first_error - 1][1]] if first_error > 0 else []
        errors = " ".join(text for _, text in said[first_error:])
        return ": ".join([*cause, errors])


@contextlib.contextmanager
def quiet_stdout() -> Iterator[Chatter]:
    """Keep the C-level stdout/stderr chatter of Bullet's URDF importer off the terminal.

    It is captured instead, so a refusal can say why (PyBullet's exception only says
    "Cannot load URDF file.").
    """
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    chatter = Chatter()
    with tempfile.TemporaryFile() as capture:
        try:
            os.dup2(capture.fileno(), 1)
            os.dup2(capture.fileno(), 2)
            yield chatter
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
            capture.seek(0)
            chatter.text = capture.read().decode("utf-8", "replace")


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
            raise WorldValueError(
                f"unknown shape {self.shape!r}; use box, cylinder, sphere or plane"
            )
        if self.shape != "plane" and min(self.size) <= 0:
            raise WorldValueError(f"{self.shape} size {self.size} [m] must be positive")
        if self.mass < 0:
            raise WorldValueError(f"mass {self.mass} [kg] must be >= 0 (0 = static)")

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
    frames (``World.link_pose``) at a fixed pose in their host. ``checked`` says that
    ``path`` already passed the URDF parser (robots write theirs from a checked model);
    every other URDF is read by it before PyBullet sees it (``world/robot_urdf.py``).
    """

    path: Path
    fixed_base: bool = False
    scale: float = 1.0
    mass: float | None = None
    frames: tuple[tuple[str, str, Pose], ...] = ()  # (frame, host link, pose in host)
    checked: bool = False
    parts: tuple[tuple[Path, Pose], ...] = ()  # (subtree's URDF, its root in the root link)
    # the model the file was checked with, held so that loads of the file while a world
    # holds this body share the parse (the model memo holds models only weakly)
    model: RobotModel | None = field(default=None, compare=False, repr=False)

    def create(self, client: int) -> int:
        """Load the URDF into ``client`` at the origin; return its body id."""
        if not Path(self.path).is_file():
            raise FileNotFoundError(f"URDF file {self.path} does not exist")
        refusal: pybullet.error | None = None
        with quiet_stdout() as chatter:
            try:
                body = int(
                    pybullet.loadURDF(
                        str(self.path),
                        useFixedBase=self.fixed_base,
                        globalScaling=self.scale,
                        physicsClientId=client,
                    )
                )
            except pybullet.error as err:
                refusal = err
        if refusal is not None:
            why = chatter.reason() or "PyBullet gave no reason"
            raise pybullet.error(f"{str(refusal).strip()} {why}") from refusal
        if self.mass is not None:
            pybullet.changeDynamics(body, -1, mass=self.mass, physicsClientId=client)
        return body

    @property
    def is_static(self) -> bool:
        """Whether the body is fixed in place."""
        return self.fixed_base


BodySpec = ShapeSpec | MeshSpec | UrdfSpec
