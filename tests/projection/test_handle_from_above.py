"""A drawer's handle no grasp from the front holds is taken from above.

Centauro's arms reach the kitchen drawer's handle, 0.58 m under its shoulders, only
pointing down, and its ball hand fits between the handle and the counter's top over it
only slanted: every grasp from the front failed and the bowl's drawer stayed shut. The
hand now comes down onto the handle, 45 degrees first, and pulls it along the drawer's
way out, and closes it so. The drawer's travel is read from PyBullet itself, the hand's
slant from the tool frame's pose once it has backed off the handle along its approach.
"""

from __future__ import annotations

import math
import warnings

import pybullet
import pytest

from robocram.motion.part_path import PITCHES, from_above
from robocram.projection import ProjectedRobot
from robocram.projection.articulation import approach_axis, move_part
from robocram.robots import example_robot_data_folder, load_description
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from tests.drafts import drafted

URDF = example_robot_data_folder() / "centauro_description" / "urdf" / "centauro.urdf"
DRAWER = "drawer_unit_drawer_3"  # the bowl's drawer, its handle 0.75 m up
FACING_NORTH = quat.from_euler(0.0, 0.0, math.pi / 2)


def test_the_turned_frame_points_up_and_keeps_the_bar_across() -> None:
    frame = from_above(Pose(), PITCHES[-1])
    assert quat.rotate(frame.orientation, (1.0, 0.0, 0.0)) == pytest.approx((0, 0, 1), abs=1e-9)
    assert quat.rotate(frame.orientation, (0.0, 1.0, 0.0)) == pytest.approx((0, 1, 0), abs=1e-9)


def test_centauro_opens_the_bowls_drawer_pulling_its_handle_from_above() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = kitchen_scene(load_description(drafted(URDF).description))
    world = scene.world
    try:
        desc = world.robot(scene.robot).description
        for arm in desc.arms.values():
            world.set_joint_states(scene.robot, dict(arm.parking))
        z = world.pose(scene.robot).position[2]
        handle_x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
        world.set_pose(scene.robot, Pose((handle_x + 0.17, 0.96, z), FACING_NORTH))  # left arm
        robot = ProjectedRobot.of(world, scene.robot)
        result = move_part(robot, "left", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.4)
        assert result.reached == pytest.approx(0.4, abs=1e-9)
        kitchen, cid = world.object("kitchen"), world.physics.client()
        joint = kitchen.joint_index[f"{DRAWER}_joint"]
        assert pybullet.getJointState(kitchen.body_id, joint, cid)[0] == pytest.approx(
            0.4, abs=0.01
        )
        # the hand backed off the handle along its approach, as it held it: slanted down
        tool = world.link_pose(scene.robot, desc.arms["left"].tool_frame).orientation
        down = quat.rotate(tool, tuple(approach_axis(robot, "left")))
        assert math.degrees(math.asin(-down[2])) == pytest.approx(45.0, abs=5.0)
        # closing takes the handle as opening did, from above first
        move_part(robot, "left", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.0)
        closed = pybullet.getJointState(kitchen.body_id, joint, cid)[0]
        assert closed == pytest.approx(0.0, abs=0.01)
    finally:
        world.close()
