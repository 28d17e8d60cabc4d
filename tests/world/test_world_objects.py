"""Objects of a world: shapes, catalogue items, names, poses, rays, renders and lifetime."""

from __future__ import annotations

import struct
import zlib
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.tf import Pose
from robocram.world import (
    DuplicateObjectError,
    UnknownItemError,
    UnknownObjectError,
    World,
    WorldClosedError,
    catalogue_names,
)


@pytest.fixture
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        yield w


def test_shapes_have_their_size_and_pose(world: World) -> None:
    box = world.add_box("box", (0.2, 0.4, 0.6), Pose((1, 2, 0.3)), mass=2.0)
    ball = world.bodies.add_sphere("ball", 0.1, ((0, 0, 1), (0, 0, 0, 1)))
    can = world.bodies.add_cylinder("can", 0.05, 0.2, (3, 0, 0.1))
    low, high = world.aabb(box)
    assert np.subtract(high, low) == pytest.approx((0.2, 0.4, 0.6), abs=0.005)
    assert world.pose(ball).position == pytest.approx((0, 0, 1))
    assert np.subtract(*reversed(world.aabb(can))) == pytest.approx((0.1, 0.1, 0.2), abs=0.005)
    assert [o.name for o in world.objects(type="box")] == ["box"]
    assert not box.is_static and can.is_static


def test_catalogue_items_are_typed_and_sized(world: World) -> None:
    assert set(catalogue_names()) >= {"mug", "pot", "bottle", "bowl", "plate", "cup", "milk"}
    mug = world.add_item("mug-1", "mug", (0, 0, 0))
    cereal = world.add_item("cereal-1", "cereal", (1, 0, 0.14))
    assert (mug.type, cereal.type) == ("mug", "cereal_box")
    low, high = world.aabb(mug)
    assert high[2] - low[2] == pytest.approx(0.106, abs=0.005)  # pybullet's own mug
    mass = pybullet.getDynamicsInfo(mug.body_id, -1, physicsClientId=world.physics.client())[0]
    assert mass == pytest.approx(0.3)
    with pytest.raises(UnknownItemError, match="did you mean 'bowl'"):
        world.add_item("b", "bowel")


def test_names_are_unique_and_looked_up_with_suggestions(world: World) -> None:
    world.add_box("kitchen_table", (1, 1, 1), (0, 0, 0.5))
    with pytest.raises(DuplicateObjectError, match="kitchen_table"):
        world.add_box("kitchen_table", (1, 1, 1))
    with pytest.raises(UnknownObjectError, match="did you mean 'kitchen_table'"):
        world.pose("kitchen-table")
    world.remove("kitchen_table")
    assert "kitchen_table" not in world


def test_ray_cast_reports_the_first_body(world: World) -> None:
    box = world.add_box("box", (1, 1, 1), (2, 0, 0.5))
    hit = world.view.ray_cast((0, 0, 0.5), (5, 0, 0.5))
    assert hit is not None and hit.obj is box
    assert hit.distance == pytest.approx(1.5, abs=1e-4)
    assert hit.position == pytest.approx((1.5, 0, 0.5), abs=1e-4)
    assert world.view.ray_cast((0, 0, 2), (5, 0, 2)) is None
    down = world.view.ray_cast_batch([(0, 0, 1)], [(0, 0, -1)])[0]
    assert down is not None and down.obj.name == "floor"


def test_render_and_png(world: World, tmp_path: Path) -> None:
    world.add_box("red", (0.5, 0.5, 0.5), (2, 0, 0.25), color=(1, 0, 0, 1))
    camera = Pose.from_xyz_rpy((0, 0, 0.25), (-np.pi / 2, 0, -np.pi / 2))  # optical: z along +x
    rgb = world.view.render(camera, 64, 48)
    assert rgb.shape == (48, 64, 3) and rgb.dtype == np.uint8
    centre = rgb[24, 32]
    assert centre[0] > 100 and centre[1] < 60 and centre[2] < 60
    path = world.view.save_png(tmp_path / "scene.png", camera, 64, 48)
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", data[16:24])
    assert (width, height) == (64, 48)
    idat = data[data.index(b"IDAT") + 4 : data.index(b"IEND") - 8]
    rows = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(48, 1 + 64 * 3)
    assert np.array_equal(rows[:, 1:].reshape(48, 64, 3), rgb)


def test_closed_world_says_so() -> None:
    world = World()
    world.close()
    with pytest.raises(WorldClosedError):
        world.bodies.add_floor()
