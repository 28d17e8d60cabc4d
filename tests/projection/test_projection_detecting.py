"""``detecting`` in the kitchen: the pose perceived, an occluded mug, a mug out of view."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.designators import ObjectDesignator, a, an
from robocram.execution import perform
from robocram.execution.failures import PerceptionObjectNotFound
from robocram.plans.search import search
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat


@pytest.fixture(scope="module", params=["pr2", "hsrb", "boxy"])
def scene(request: pytest.FixtureRequest) -> Iterator[KitchenScene]:
    built = kitchen_scene(request.param)
    yield built
    built.world.close()


def _detect() -> ObjectDesignator:
    found = perform(a.motion(type="detecting", object=an.object(type="mug")))
    assert isinstance(found, ObjectDesignator)
    return found


def test_detecting_gives_the_mug_and_its_pose(scene: KitchenScene) -> None:
    world = scene.world
    with world.snapshots.stored_state(), simulated_robot(world, scene.robot):
        search("mug")
        found = _detect()
        assert found.get("name") == "mug-1"
        in_map = world.pose(scene.robot) * found.get("pose").pose
        truth = world.pose("mug-1")
        assert math.dist(in_map.position, truth.position) < 1e-6  # [m]
        assert abs(quat.angle_between(in_map.orientation, truth.orientation)) < 1e-6


def test_an_occluded_mug_is_not_detected(scene: KitchenScene) -> None:
    world = scene.world
    with world.snapshots.stored_state(), simulated_robot(world, scene.robot):
        search("mug")
        camera = np.asarray(world.view.camera(scene.robot).pose.position)
        mug = np.asarray(world.pose("mug-1").position)
        between = camera + 0.5 * (mug - camera)
        screen = world.add_box("screen", (0.3, 0.3, 0.3), Pose(tuple(between.tolist())))
        try:
            assert [o.name for o in world.view.occluding_objects(scene.robot, "mug-1")] == [
                "screen"
            ]
            with pytest.raises(PerceptionObjectNotFound):
                _detect()
        finally:
            world.remove(screen)
        assert _detect().get("name") == "mug-1"  # seen again once the screen is gone


def test_a_mug_out_of_view_is_not_detected(scene: KitchenScene) -> None:
    world = scene.world
    with world.snapshots.stored_state(), simulated_robot(world, scene.robot):
        search("mug")
        stand = world.pose(scene.robot)
        turned = stand * Pose((0.0, 0.0, 0.0), quat.from_euler(0.0, 0.0, math.pi))
        world.set_pose(scene.robot, turned)  # the mug is now behind the robot
        assert world.view.visibility_fraction(scene.robot, "mug-1") == 0.0
        with pytest.raises(PerceptionObjectNotFound):
            _detect()
