"""A thing out of the view by geometry is taken where it was seen, from nearer the grasp.

TALOS's camera sees the kitchen's counter mug only from 0.6 m back or more, where its arm
does not reach it; from the near stand 0.45 m back (the right shoulder in line with the
mug), its head stopped at its tilt limit has the mug under the view's lower edge. There
the usual pre-grasps and lifts (0.1 m over the handle) put the upper arm into the wall
cupboard over the counter; the nearer ones (3.5 cm over, lifted 1.5 cm) do not. Judged on
PyBullet's own state: the camera frame's angles, the mug's base height, the closest points
between the robot and the kitchen.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.designators import an
from robocram.execution.failures import PtuGoalNotReached
from robocram.knowledge.grasp_predicates import ObjectGrasp
from robocram.plans.basic_actions import look_lowering
from robocram.plans.grasp_failures import PickUpUnreachable
from robocram.plans.known_robot import current_robot
from robocram.plans.nearer_pre_grasp import NEARER_LIFT_SHARE, NEARER_SHARE, nearer_pre_grasp
from robocram.plans.out_of_view_reach import (
    ASIDE,
    NEAR_DISTANCES,
    SQUARED_DISTANCES,
    near_stands,
    out_of_view,
)
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from tests.bullet_links import link_frame

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"
FETCH_STAND = (-1.231, 1.344)  # [m] map: the kitchen fetch's last usual stand
LIFT = 0.10  # [m] the grasp model's usual lift


@pytest.fixture(scope="module")
def scene() -> Iterator[KitchenScene]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the draft's doubts
        made = kitchen_scene(str(TALOS))
    yield made
    made.world.close()


def _near_right_stand(scene: KitchenScene, mug: PoseStamped) -> Pose:
    """The near stand of the right arm, nearest first, from the fetch's last stand; on the
    robot's feet as the scene stood it."""
    world, robot = scene.world, scene.robot
    height = world.pose(robot).position[2]
    world.set_pose(robot, Pose((*FETCH_STAND, height), quat.from_euler(0.0, 0.0, math.pi / 2)))
    with simulated_robot(world, robot):
        stands = [pose for pose, arm in near_stands(current_robot(), mug, None) if arm == "right"]
    x, y, _ = stands[0].position
    return Pose((x, y, height), stands[0].orientation)


def test_near_stand_has_the_mug_out_of_view_and_takes_it_from_nearer(
    scene: KitchenScene,
) -> None:
    world, robot = scene.world, scene.robot
    cid = world.physics.client()
    mug = world.pose("mug-1")
    where = PoseStamped("map", mug.position, mug.orientation)
    stand = _near_right_stand(scene, where)
    assert math.hypot(
        stand.position[0] - mug.position[0], stand.position[1] - mug.position[1]
    ) == pytest.approx(math.hypot(NEAR_DISTANCES[0], 0.1575), abs=0.01)
    world.set_pose(robot, stand)
    body = world.object(robot).body_id
    with simulated_robot(world, robot):
        with pytest.raises(PtuGoalNotReached) as looked:
            look_lowering(where)
        assert out_of_view(looked.value)
        camera = world.robot(robot).description.cameras[0]
        position, rotation = link_frame(body, cid, camera.frame)
        _, y, z = rotation.T @ (np.asarray(mug.position) - position)
        assert math.atan2(y, z) > camera.vertical_fov / 2  # under the view's lower edge
        blind = an.object(type="mug", name="mug-1", pose=where)
        with pytest.raises(PickUpUnreachable):
            pick_up_object(blind, arm="right")  # the usual pre-grasps and lifts
        held = pick_up_object(blind, arm="right", nearer=True)
    assert held.grasp == "handle"
    mug_body = world.object("mug-1").body_id
    lifted = pybullet.getBasePositionAndOrientation(mug_body, physicsClientId=cid)[0]
    assert lifted[2] - mug.position[2] == pytest.approx(NEARER_LIFT_SHARE * LIFT, abs=0.005)
    kitchen = world.object("kitchen").body_id
    assert not pybullet.getClosestPoints(body, kitchen, 0.0, physicsClientId=cid)
    fingers = pybullet.getClosestPoints(body, mug_body, 0.005, physicsClientId=cid)
    assert fingers  # the hand holds it


def test_after_the_near_stands_come_stands_squared_to_the_counter(scene: KitchenScene) -> None:
    """From the fetch's last stand (off square), the right arm's stands after the near ones
    face the north counter squarely (map yaw 90 degrees), each distance out of the counter
    in line with the mug's and 0.15 m to either side (a B1's hips pass between handles)."""
    world, robot = scene.world, scene.robot
    mug = world.pose("mug-1")
    where = PoseStamped("map", mug.position, mug.orientation)
    height = world.pose(robot).position[2]
    world.set_pose(robot, Pose((*FETCH_STAND, height), quat.from_euler(0.0, 0.0, math.pi / 2)))
    with simulated_robot(world, robot):
        stands = [pose for pose, arm in near_stands(current_robot(), where, None) if arm == "right"]
    squared = stands[len(NEAR_DISTANCES) :]
    assert len(squared) == len(SQUARED_DISTANCES) * len(ASIDE)
    first = squared[0].position
    for k, pose in enumerate(squared):
        assert quat.to_euler(pose.orientation)[2] == pytest.approx(math.pi / 2, abs=1e-6)
        distance, aside = SQUARED_DISTANCES[k // len(ASIDE)], ASIDE[k % len(ASIDE)]
        assert mug.position[1] - pose.position[1] == pytest.approx(distance, abs=1e-6)
        assert pose.position[0] - first[0] == pytest.approx(aside, abs=1e-6)


def test_nearer_pre_grasp_keeps_the_approach_and_a_drawers_lift() -> None:
    turned = quat.from_euler(0.0, math.pi / 2, 0.0)
    grasp = PoseStamped("map", (1.0, 2.0, 0.9), turned)
    choice = ObjectGrasp(
        "mug-1",
        "talos",
        "right",
        "handle",
        grasp,
        PoseStamped("map", (1.0, 2.1, 1.0), turned),  # 0.1 m back and over
        PoseStamped("map", (1.0, 2.0, 1.0), turned),
    )
    near = nearer_pre_grasp(choice)
    assert near.pre_grasp.position == pytest.approx(
        (1.0, 2.0 + 0.1 * NEARER_SHARE, 0.9 + 0.1 * NEARER_SHARE)
    )
    assert near.lift.position == pytest.approx((1.0, 2.0, 0.9 + 0.1 * NEARER_LIFT_SHARE))
    assert near.pre_grasp.orientation == turned and near.grasp_pose == grasp
    kept = nearer_pre_grasp(choice, lift_share=1.0)
    assert kept.lift.position == pytest.approx(choice.lift.position)
