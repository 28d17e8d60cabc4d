"""A head stopped at its tilt limit above the target has looked if the target lies in the
lower part of its view.

TALOS's head tilts 45 degrees down at most and it has no torso to lower: at the stand in
front of the kitchen's north counter the fetch took (facing the counter square), the
counter's mug lies 7.1 degrees under the optical axis tilted to its limit (0.30 of the
23.4-degree half field; 7.8 with the fetch's own yaw). The look
counts as had there, and perception sees the mug; from a stand 0.45 m from the mug, where
the arm would reach it, the mug lies under the view's lower edge and the look still fails.
Where the mug lies in the view is judged on PyBullet's own link state of the camera frame.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.basic_actions import detect, look, look_lowering
from robocram.plans.tilt_limit_look import TILT_EDGE_SHARE
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.bullet_links import link_frame

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"
FETCH_STAND = (-1.231, 1.344)  # [m] map: where the kitchen fetch stood before looking


@pytest.fixture(scope="module")
def scene() -> Iterator[KitchenScene]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the draft's doubts
        made = kitchen_scene(str(TALOS))
    yield made
    made.world.close()


def _stand(world: World, robot: str, xy: tuple[float, float]) -> None:
    """Put the robot at ``xy`` facing the mug (+y), on its feet as the scene stood it."""
    height = world.pose(robot).position[2]
    world.set_pose(robot, Pose((xy[0], xy[1], height), quat.from_euler(0.0, 0.0, math.pi / 2)))


def _in_view(world: World, robot: str, target: tuple[float, float, float]) -> tuple[float, float]:
    """[rad] the target's angles off the camera's optical axis (right, down), from PyBullet's
    link state of the camera frame (optical: z forward, x right, y down)."""
    position, rotation = link_frame(
        world.object(robot).body_id,
        world.physics.client(),
        world.robot(robot).description.cameras[0].frame,
    )
    x, y, z = rotation.T @ (np.asarray(target) - position)
    return math.atan2(x, z), math.atan2(y, z)


def test_a_target_under_the_axis_tilted_to_its_limit_is_looked_at(scene: KitchenScene) -> None:
    world, robot = scene.world, scene.robot
    camera = world.robot(robot).description.cameras[0]
    tilt = world.robot(robot).description.pan_tilt
    assert tilt is not None
    mug = world.pose("mug-1").position
    target = PoseStamped("map", mug)
    _stand(world, robot, FETCH_STAND)
    with simulated_robot(world, robot):
        with pytest.raises(PtuGoalNotReached) as failed:
            look(target)  # the head stops at its tilt limit above the mug
        assert failed.value.below_tilt and failed.value.view_share is not None
        look_lowering(target)  # no torso: the mug in the lower view counts as looked at
        seen = detect("mug")
    aside, below = _in_view(world, robot, mug)
    limit = world.bodies.joint_limits(robot, tilt.tilt_joint).upper
    assert world.joint_states(robot)[tilt.tilt_joint] == pytest.approx(limit, abs=1e-3)
    assert abs(aside) < math.radians(1)
    assert 0.0 < below <= TILT_EDGE_SHARE * camera.vertical_fov / 2
    assert below == pytest.approx(math.radians(7.1), abs=math.radians(0.3))
    assert failed.value.view_share[1] * camera.vertical_fov / 2 == pytest.approx(below, abs=1e-3)
    assert seen.get("name") == "mug-1"


def test_a_target_under_the_view_still_fails_the_look(scene: KitchenScene) -> None:
    world, robot = scene.world, scene.robot
    camera = world.robot(robot).description.cameras[0]
    mug = world.pose("mug-1").position
    _stand(world, robot, (mug[0], mug[1] - 0.45))  # the arm's reach, the mug under the view
    with simulated_robot(world, robot), pytest.raises(PtuGoalNotReached) as failed:
        look_lowering(PoseStamped("map", mug))
    _, below = _in_view(world, robot, mug)
    assert failed.value.below_tilt
    assert below > camera.vertical_fov / 2  # under the view's lower edge
