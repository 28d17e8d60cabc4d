"""A planned joint moves its mimic followers' links too: checks and travel bounds see them.

The HSR's head rides on ``torso_lift_joint``, which mimics ``arm_lift_joint`` at half its
value; the PR2's right finger follows its left.
"""

from __future__ import annotations

import numpy as np
import pytest

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.travel_bound import TravelBound
from robocram.world import RobotHandle, World


def test_the_hsr_lift_moves_its_head_at_half_its_speed() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("hsrb")
        moving = BulletScene(RobotHandle.of(world, "hsrb"), ("arm_lift_joint",)).moving_links
        assert {"arm_lift_link", "torso_lift_link", "head_pan_link", "head_tilt_link"} <= set(
            moving
        )
        bound = TravelBound.of(RobotHandle.of(world, "hsrb"), ("arm_lift_joint",))
        assert bound.link_lever["head_tilt_link"][0] == pytest.approx(0.5)
        assert bound.link_lever["arm_lift_link"][0] == pytest.approx(1.0)
        assert bound.mimicked
        before = world.link_pose("hsrb", "head_tilt_link").position[2]
        world.set_joint_states("hsrb", {"arm_lift_joint": 0.2})
        risen = world.link_pose("hsrb", "head_tilt_link").position[2] - before
        assert risen == pytest.approx(0.1, abs=1e-6)  # what the bound says: 0.5 per metre


def test_the_pr2_right_finger_moves_with_the_left_finger_joint() -> None:
    with World() as world:
        world.bodies.add_floor()
        world.add_robot("pr2")
        joints = ("r_gripper_l_finger_joint",)
        moving = set(BulletScene(RobotHandle.of(world, "pr2"), joints).moving_links)
        assert {"r_gripper_r_finger_link", "r_gripper_r_finger_tip_link"} <= moving
        bound = TravelBound.of(RobotHandle.of(world, "pr2"), joints)
        tip = bound.link_lever["r_gripper_r_finger_tip_link"][0]
        start = np.array(world.link_pose("pr2", "r_gripper_r_finger_tip_link").position)
        world.set_joint_states("pr2", {joints[0]: 0.1})
        moved = np.linalg.norm(
            world.link_pose("pr2", "r_gripper_r_finger_tip_link").position - start
        )
        assert 0.0 < moved <= tip * 0.1  # the tip's frame moves within its bound
