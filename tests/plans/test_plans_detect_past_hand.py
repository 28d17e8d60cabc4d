"""Detecting past the robot's own hand opens only the hands that hold nothing.

A wrist camera's closed jaw can hide what it looks at, so a blocked detection opens the
grippers and looks again. It opened every gripper: Boxy's right hand let go of the cup it
carried tucked while its left fetched the second, and the cup was never set. Here the
PR2 holds the mug in one hand and its other hand stands in the camera's view of the
bottle: the view stays blocked, and the mug stays in the hand (raw PyBullet).
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.designators import a, an
from robocram.execution.failures import PerceptionBlockedByRobot
from robocram.plans import perform
from robocram.plans.detect_past_hand import detect_past_hand
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped


def test_a_blocked_view_opens_the_free_hand_and_the_held_mug_stays() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            perform(an.action(type="looking", target=scene.look_target))
            mug = perform(an.action(type="detecting", object=an.object(type="mug")))
            held = perform(an.action(type="picking-up", object=mug))
            other = "left" if held.arm == "right" else "right"
            bottle = world.pose("bottle-1").position
            perform(a.motion(type="looking", target=PoseStamped.from_pose("map", Pose(bottle))))
            camera = world.robot(scene.robot).description.cameras[0].frame
            eye = world.link_pose(scene.robot, camera).position
            mid = [e + 0.5 * (b - e) for e, b in zip(eye, bottle, strict=True)]
            tool = Pose((mid[0], mid[1], mid[2]))  # pointing ahead
            perform(
                a.motion(
                    type="moving-tcp", arm=other,
                    target=a.location(pose=PoseStamped.from_pose("map", tool)),
                )
            )  # fmt: skip
            robot = world.object(scene.robot)
            fingers = [
                robot.joint_index[j]
                for j in world.robot(scene.robot).description.arms[held.arm].gripper_joints
                if j in robot.joint_index
            ]
            assert fingers
            closed = [pybullet.getJointState(robot.body_id, i, cid)[0] for i in fingers]
            with pytest.raises(PerceptionBlockedByRobot):
                detect_past_hand(an.object(type="bottle"))
        assert world.bodies.attached_to("mug-1") is not None  # still held
        after = [pybullet.getJointState(robot.body_id, i, cid)[0] for i in fingers]
        assert after == pytest.approx(closed, abs=1e-6)  # the holding hand never opened
    finally:
        world.close()
