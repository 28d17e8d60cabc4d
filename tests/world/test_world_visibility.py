"""Visibility by rays and by renders: occlusion, image edges, occluders, and their agreement."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.tf import Pose
from robocram.world import Camera, NoCameraError, World

# Optical frame at 0.5 m height looking along +x (z forward, x right = -y world, y down).
LOOK_X = Pose.from_xyz_rpy((0, 0, 0.5), (-math.pi / 2, 0, -math.pi / 2))
CAMERA = Camera(LOOK_X, math.radians(60), math.radians(45))


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_box("target", (0.4, 0.4, 0.4), (3, 0, 0.5))
        w.add_box("wall", (0.05, 1.0, 1.0), (2, 5, 0.5))  # parked out of the way
        yield w


# (wall position or None, target position, expected fraction)
SCENES = {
    "clear": (None, (3, 0, 0.5), 1.0),
    "left half hidden": ((2, 0.5, 0.5), (3, 0, 0.5), 0.5),
    "fully hidden": ((2, 0, 0.5), (3, 0, 0.5), 0.0),
    "half out of view": (None, (3, -3 * math.tan(math.radians(30)), 0.5), 0.5),
    "behind the camera": (None, (-3, 0, 0.5), 0.0),
}


def _arrange(world: World, wall: tuple[float, ...] | None, target: tuple[float, ...]) -> None:
    world.set_pose("wall", wall if wall is not None else (2, 5, 0.5))
    world.set_pose("target", target)


@pytest.mark.parametrize("scene", SCENES)
@pytest.mark.parametrize("method", ["ray", "render"])
def test_fraction_matches_the_geometry(world: World, scene: str, method: str) -> None:
    wall, target, expected = SCENES[scene]
    _arrange(world, wall, target)
    seen = world.view.visibility_from(CAMERA, "target", method)  # type: ignore[arg-type]
    assert seen.fraction == pytest.approx(expected, abs=0.08)
    hidden_by_wall = wall is not None
    assert seen.occluders == (("wall",) if hidden_by_wall else ())


def test_ray_and_render_agree_on_every_scene(world: World) -> None:
    for wall, target, _ in SCENES.values():
        _arrange(world, wall, target)
        ray = world.view.visibility_from(CAMERA, "target", "ray").fraction
        render = world.view.visibility_from(CAMERA, "target", "render").fraction
        assert ray == pytest.approx(render, abs=0.06)


def test_visible_from_uses_the_threshold(world: World) -> None:
    _arrange(world, (2, 0.5, 0.5), (3, 0, 0.5))
    assert not world.view.visible_from(CAMERA, "target")
    assert world.view.visible_from(CAMERA, "target", threshold=0.4)
    assert world.view.visible_from(LOOK_X, "wall")  # a bare pose gets the default field of view
    before = world.pose("target")
    world.view.visibility_from(CAMERA, "target", "render")
    assert world.pose("target") == before  # the isolation trick puts it back exactly
    with pytest.raises(ValueError, match="'ray' or 'render'"):
        world.view.visibility_from(CAMERA, "target", "magic")  # type: ignore[arg-type]


def test_robot_camera_sees_through_its_description() -> None:
    with World() as world:
        world.bodies.add_floor()
        pr2 = world.add_robot("pr2")
        world.set_joint_states(pr2, {"head_tilt_joint": 0.3})
        world.add_box("shelf", (0.3, 0.3, 0.3), (2.5, 0, 0.6))
        world.add_box("screen", (0.05, 0.6, 0.6), (1.5, 0, 0.7))
        camera = world.view.camera(pr2)
        assert camera.horizontal_fov == pytest.approx(math.radians(90))
        assert not world.view.visible(pr2, "shelf")
        assert [o.name for o in world.view.occluding_objects(pr2, "shelf")] == ["screen"]
        world.remove("screen")
        assert world.view.visible(pr2, "shelf") and world.view.visible(
            pr2, "shelf", method="render"
        )
        with pytest.raises(NoCameraError, match="no camera 'thermal'; known: 'wide_stereo'"):
            world.view.camera(pr2, camera="thermal")
