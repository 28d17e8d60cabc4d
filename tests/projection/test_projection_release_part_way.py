"""A hand that lets go where opening fully is blocked opens part way.

Putting a bowl down in a seeded household (activity_bench seed 23), the PR2's wrist was
flexed so far back that its fully open finger met its own forearm: the put failed in
every turn, and the table was set 6 of 7. Here a block stands where the PR2's left
fingertip is when fully open; the hand holds a small box. Opening lets the box go with
the fingers part way open, and raw PyBullet finds the fingers clear of the block. An
empty hand, opening for a grasp, still fails: part way may be too narrow for the grasp.
"""

from __future__ import annotations

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import GripperPathBlocked
from robocram.projection import ProjectedRobot
from robocram.projection.gripper import close_gripper, gripper_of, open_gripper
from robocram.scenes import kitchen_scene

TIP = "l_gripper_l_finger_tip_link"
OUT = 0.02  # [m] the block's middle beyond the fully open fingertip's frame


def test_a_holding_hand_opens_part_way_where_opening_fully_is_blocked() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    try:
        robot = ProjectedRobot.of(world, "pr2")
        desc = world.robot("pr2").description
        world.set_joint_states("pr2", dict(desc.arms["left"].parking))
        open_gripper(robot, "left")
        wide = np.array(world.link_pose("pr2", TIP).position)
        close_gripper(robot, "left")
        shut = np.array(world.link_pose("pr2", TIP).position)
        out = (wide - shut) / np.linalg.norm(wide - shut)  # the way the fingertip opens
        spot = tuple(float(v) for v in wide + OUT * out)
        world.add_box("block", (0.02, 0.02, 0.02), spot)  # in the open fingertip's way
        with pytest.raises(GripperPathBlocked):  # empty: no part-way opening for a grasp
            open_gripper(robot, "left")
        palm = world.link_pose("pr2", "l_gripper_palm_link").position
        world.add_box("pea", (0.005, 0.005, 0.005), (palm[0], palm[1], palm[2] - 0.3))
        world.attach("pea", "pr2", desc.arms["left"].end_effector_link)
        master = gripper_of(robot, "left").joints[0]
        closed = world.joint_states("pr2")[master.name]
        open_gripper(robot, "left")
        now = world.joint_states("pr2")[master.name]
        span = master.open - master.closed
        assert 0.15 <= (now - closed) / span < 1.0  # opened part of the way
        assert world.bodies.attached_to("pea") is None  # let go
        cid = world.physics.client()
        robot_body, block = world.object("pr2").body_id, world.object("block").body_id
        assert not pybullet.getClosestPoints(robot_body, block, 0.0, physicsClientId=cid)
    finally:
        world.close()
