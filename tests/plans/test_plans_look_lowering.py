"""Looking down at a counter with the torso left up: an HSR's lift, raised by an earlier
reach, carries its parked hand twice as fast as its head, so the head turned down at the
mug meets the hand (8 of 50 kitchen mug fetches failed so). The head looks ahead, the
torso goes down until the head can look, then it looks."""

from __future__ import annotations

import math

import pytest

from robocram.execution.failures import PtuPathBlocked
from robocram.plans.basic_actions import LOOK_HEIGHTS, look, look_lowering, park_arms
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

LIFT = "arm_lift_joint"


def test_a_look_blocked_by_the_raised_hand_lowers_the_torso_first() -> None:
    world = kitchen_scene("hsrb").world
    mug = world.pose("mug-1").position
    stand = (mug[0] - 0.14, mug[1] - 0.55)  # a fetch stand before the counter
    yaw = math.atan2(mug[1] - stand[1], mug[0] - stand[0])
    world.set_pose("hsrb", Pose((*stand, 0.0), quat.from_euler(0.0, 0.0, yaw)))
    upper = world.bodies.joint_limits("hsrb", LIFT).upper
    target = PoseStamped.from_pose("map", Pose(mug))
    with simulated_robot(world, "hsrb"):
        park_arms()
        world.set_joint_states("hsrb", {LIFT: 0.73 * upper})  # as an earlier reach left it
        with pytest.raises(PtuPathBlocked):
            look(target)
        look_lowering(target)
    lift = world.joint_states("hsrb")[LIFT]
    heights = [f * upper for f in LOOK_HEIGHTS]  # the lift's lower limit is 0
    assert any(lift == pytest.approx(h, abs=1e-6) for h in heights)
    assert lift < 0.73 * upper
    assert world.joint_states("hsrb")["head_tilt_joint"] < -0.2  # turned down at the mug
    world.close()
