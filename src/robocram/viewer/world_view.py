"""The 3-D world in the browser: a viser scene node per body link, moved from world poses.

Each link with visuals is a frame node ``/<body>/<link>`` placed in map; its shapes are
children at their URDF origins, so a new world state only moves the frames.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from functools import lru_cache
from typing import Any

import numpy as np
import trimesh
import viser

from robocram.tf import Pose
from robocram.viewer.errors import ViewerUnknownKey
from robocram.viewer.visual_parts import Rgba, VisualPart, visual_parts
from robocram.world import World

ROOT = "__root__"  # node name of a body's root frame


def wxyz(pose: Pose) -> tuple[float, float, float, float]:
    """Our (x, y, z, w) quaternion in viser's (w, x, y, z) order."""
    x, y, z, w = pose.orientation
    return (w, x, y, z)


@lru_cache(maxsize=256)
def _mesh(filename: str, scale: tuple[float, float, float]) -> trimesh.Trimesh:
    mesh = trimesh.load(filename, force="mesh")
    assert isinstance(mesh, trimesh.Trimesh)  # force="mesh" merges scenes into one mesh
    return mesh.apply_scale(np.asarray(scale))


class WorldView:
    """The bodies of one world as viser scene nodes; ``show(world)`` moves them."""

    def __init__(self, server: viser.ViserServer, world: World) -> None:
        self.server = server
        self.bodies: dict[str, Any] = {}
        self.frames: dict[tuple[str, str], Any] = {}  # (body, link or ROOT) -> frame handle
        for obj in world.objects():
            self.bodies[obj.name] = server.scene.add_frame(f"/{obj.name}", show_axes=False)
        for i, part in enumerate(visual_parts(world)):
            self._add_part(i, part)
        self.show(world)

    def _frame(self, body: str, link: str) -> str:
        key = (body, link)
        if key not in self.frames:
            name = f"/{body}/{link}"
            self.frames[key] = self.server.scene.add_frame(name, show_axes=False)
        return f"/{body}/{link}"

    def _add_part(self, i: int, part: VisualPart) -> None:
        frame = self._frame(part.body, part.link or ROOT)
        name, geometry = f"{frame}/part{i}", part.geometry
        place: dict[str, Any] = {
            "position": part.origin.position,
            "wxyz": wxyz(part.origin),
            "cast_shadow": False,  # shadow maps cost most in software WebGL (headless, Docker)
            "receive_shadow": False,
        }
        color = _rgb(part.color)
        scene = self.server.scene
        if geometry.kind == "box":
            scene.add_box(name, color=color, dimensions=geometry.size, **place)
        elif geometry.kind == "cylinder":
            scene.add_cylinder(
                name, radius=geometry.radius, height=geometry.length, color=color, **place
            )
        elif geometry.kind == "sphere":
            scene.add_icosphere(name, radius=geometry.radius, color=color, **place)
        else:
            mesh = _mesh(geometry.filename, tuple(geometry.scale))
            scene.add_mesh_simple(
                name, np.asarray(mesh.vertices), np.asarray(mesh.faces), color=color, **place
            )

    def show(self, world: World) -> None:
        """Move every frame to where the world has it now (one atomic update)."""
        with self.server.atomic():
            for (body, link), handle in self.frames.items():
                pose = world.pose(body) if link == ROOT else world.link_pose(body, link)
                handle.position = pose.position
                handle.wxyz = wxyz(pose)

    def set_visible(self, body: str, visible: bool) -> None:
        """Show or hide ``body`` (all its links)."""
        if body not in self.bodies:
            raise ViewerUnknownKey(f"no body {body!r} in the view; bodies: {sorted(self.bodies)}")
        self.bodies[body].visible = visible

    @contextmanager
    def hidden(self, body: str) -> Iterator[None]:
        """Hide ``body`` inside the block."""
        self.set_visible(body, False)
        try:
            yield
        finally:
            self.set_visible(body, True)


def _rgb(color: Rgba) -> tuple[int, int, int]:
    r, g, b, _ = color
    return (round(r * 255), round(g * 255), round(b * 255))
