"""A grasp roll whose way back is blocked leaves the robot where its motions got.

After a roll on a handle failed, the part and the robot go back by checked motions; where
that was blocked, the joints and the base used to be set back, a jump no robot can make
(Boxy's breakfast: 11 at the fridge's door, found by the trace audit). Here the parked
place of the PR2's left hand is taken by a box: the way back is blocked, and the arm must
stay out where it was, the box untouched (raw PyBullet).
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.projection import ProjectedRobot
from robocram.projection.articulation import _back_to_start, _Held
from robocram.scenes import kitchen_scene
from robocram.tf import Pose

DRAWER = "drawer_unit_drawer_3"
OUT = {"l_shoulder_lift_joint": -0.1, "l_elbow_flex_joint": -0.6, "l_shoulder_pan_joint": 0.4}


def test_a_blocked_way_back_leaves_the_arm_out_not_set_into_the_box() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    try:
        desc = world.robot("pr2").description
        world.set_joint_states("pr2", dict(desc.arms["left"].parking))
        parked = world.joint_states("pr2")
        base = world.pose("pr2")
        palm = world.link_pose("pr2", "l_gripper_palm_link").position
        world.add_box("crate", (0.06, 0.06, 0.06), palm)  # where the parked hand would be
        world.set_joint_states("pr2", OUT)
        cid = world.physics.client()
        robot_body, crate = world.object("pr2").body_id, world.object("crate").body_id
        assert not pybullet.getClosestPoints(robot_body, crate, 0.0, physicsClientId=cid)
        out = world.joint_states("pr2")
        robot = ProjectedRobot.of(world, "pr2")
        held = _Held("left", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", Pose(), Pose())
        _back_to_start(robot, held, 0.0, base, parked)
        now = world.joint_states("pr2")
        for joint in OUT:  # not set back to the parked values inside the crate
            assert now[joint] == pytest.approx(out[joint], abs=1e-6), joint
            assert abs(now[joint] - parked[joint]) > 0.05, joint
        assert not pybullet.getClosestPoints(robot_body, crate, 0.0, physicsClientId=cid)
        assert world.pose("pr2").position == pytest.approx(base.position, abs=1e-9)
    finally:
        world.close()
