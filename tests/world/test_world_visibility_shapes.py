"""Rays against a lone body from its collision shapes agree with Bullet's own ray tests."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import Camera, World
from robocram.world import visibility as vis
from robocram.world.shape_rays import lone_body

TILTED = quat.from_euler(0.3, -0.2, 0.9)
# item kind (catalogue) or shape, and where it stands: rotated, so frames matter
BODIES = ("mug", "cup", "cereal_box", "milk", "bowl", "sphere")
CAMERAS = (
    Pose.from_xyz_rpy((-1.2, 0.2, 1.4), (-math.pi / 2 - 0.7, 0, -math.pi / 2)),
    Pose.from_xyz_rpy((0.1, -1.0, 0.8), (-math.pi / 2 - 0.3, 0, 0.1)),
)


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        for index, kind in enumerate(BODIES):
            pose = Pose((10.0 * index, 0.0, 0.5), TILTED)
            if kind == "sphere":
                w.bodies.add_sphere(kind, 0.12, pose)
            else:
                w.add_item(kind, kind, pose)
        yield w


def _agreement(world: World, name: str, camera: Camera) -> tuple[float, int]:
    """Share of a 24 x 24 ray grid on which the model and Bullet agree; Bullet's hits."""
    obj = world.object(name)
    tangents = vis._tangent_grid(world, camera, obj, 24)
    assert tangents is not None
    with vis.isolated(world, obj):
        bullet = np.array(vis._first_hits(world, camera.shifted(vis.ISOLATION_OFFSET), tangents))
    starts, ends = camera.ray_ends(tangents)
    length = np.linalg.norm(ends - starts, axis=1)
    lone = lone_body(world, obj)
    assert lone is not None
    ours = np.isfinite(lone.first_hit(starts, (ends - starts) / length[:, None], length))
    hits = bullet == obj.body_id
    return float(np.mean(ours == hits)), int(hits.sum())


@pytest.mark.parametrize("name", BODIES)
@pytest.mark.parametrize("view", range(len(CAMERAS)))
def test_lone_rays_agree_with_bullet(world: World, name: str, view: int) -> None:
    index = BODIES.index(name)
    shift = (10.0 * index, 0.0, 0.0)
    camera = Camera(CAMERAS[view]).shifted(shift)
    agree, hits = _agreement(world, name, camera)
    assert hits > 100  # the grid lies over the object: most rays meet it
    assert agree >= 0.98  # only rays grazing the outline may differ


def test_mug_hulls_are_closed_solids(world: World) -> None:
    lone = lone_body(world, world.object("mug"))
    assert lone is not None
    assert len(lone.pieces) == 6  # the body and five parts of the handle, as pybullet has them
    for piece, _ in lone.pieces:
        normals = piece.planes[:, :3]
        assert np.allclose(np.linalg.norm(normals, axis=1), 1.0)
        assert len(piece.planes) >= 4


def test_a_ray_from_inside_meets_the_body_at_once(world: World) -> None:
    centre = np.array([world.pose("milk").position])
    lone = lone_body(world, world.object("milk"))
    assert lone is not None
    t = lone.first_hit(centre, np.array([[0.0, 0.0, 1.0]]), np.array([1.0]))
    assert t[0] == 0.0


def test_unmodelled_shapes_fall_back_to_bullet() -> None:
    with World() as w:
        floor = w.bodies.add_floor()
        assert lone_body(w, floor) is None  # a plane: Bullet answers
        w.add_box("box", (0.2, 0.2, 0.2), (0, 0, 0.1))
        camera = Camera(Pose.from_xyz_rpy((0, 0, 1.0), (math.pi, 0, 0)))  # looking down
        seen = vis.ray_visibility(w, camera, floor)
        # the floor reaches far beyond the image: Bullet's lone rays meet it everywhere, the
        # camera sees the part in view, and the box hides a patch of that
        assert 0.0 < seen.fraction < 0.5
        assert seen.occluders == ("box",)


def test_an_articulated_body_is_placed_link_by_link() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    world.set_joint_states("kitchen", {"drawer_unit_drawer_3_joint": 0.25})  # a moved link
    for obj in world.objects():
        if obj.name != "kitchen":
            world.remove(obj)
    kitchen = world.object("kitchen")
    camera = Camera(Pose.from_xyz_rpy((0.0, 0.0, 1.5), (-math.pi / 2 - 0.5, 0, 0.3)))
    grid = np.linspace(-0.5, 0.5, 30)
    tangents = np.array([[x, y] for x in grid for y in grid])
    starts, ends = camera.ray_ends(tangents)
    length = np.linalg.norm(ends - starts, axis=1)
    lone = lone_body(world, kitchen)
    assert lone is not None
    ours = lone.first_hit(starts, (ends - starts) / length[:, None], length)
    hits = world.view.ray_cast_batch([tuple(s) for s in starts], [tuple(e) for e in ends])
    bullet = np.array([h.distance if h is not None else np.inf for h in hits])
    assert np.mean(np.isfinite(ours) == np.isfinite(bullet)) >= 0.98
    both = np.isfinite(ours) & np.isfinite(bullet)
    assert np.median(np.abs(ours[both] - bullet[both])) < 1e-3  # [m] where they meet it
    world.close()
