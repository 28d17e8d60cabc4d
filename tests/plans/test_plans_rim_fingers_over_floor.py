"""A hand whose fingers reach past its tool frame takes a bowl's rim raised over its floor.

TALOS's curling fingers reach 42.8 mm past its tool frame. At the rim grasp, 2 cm under
the kitchen bowl's rim, the single inner finger meets the bowl's floor as it closes
(2 mm under it open) while the two outer ones are still 29 mm or more off the wall: every
grip met the bowl on one side only. Its rim grasps come again last, raised until the
fingers keep 1 cm over a floor as thick as the wall (14.8 mm): crouched 0.25 m (its legs
bent, soles kept: ``kinematics.crouch``, set rather than moved) 0.45 m in front of the
bowl in its open drawer, the left hand grips the wall there and lifts the bowl out.
Judged on PyBullet's own state: the bowl's base position once lifted; the hands that
keep their grasps (the PR2's, Boxy's, HSR's, Fetch's: their fingers reach 19 mm past
their tool frames at most) are read from the grasp model.
"""

from __future__ import annotations

import math

import pybullet
import pytest

from robocram.designators import an
from robocram.grasping.grasp_model import grasps
from robocram.grasping.hand import hand_of
from robocram.grasping.object_grasps import object_shape
from robocram.kinematics.crouch import crouched
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.robots.draft.stance import legs
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from tests.talos_open_drawer import DRAWER, talos_kitchen_drawer_open

DEPTH = 0.25  # [m] the crouch
BACK = 0.45  # [m] the stand before the bowl (stands.REACH_DISTANCES)
SHOULDER = 0.1575  # [m] TALOS's left shoulder, left of its base's middle


def test_talos_lifts_the_bowl_out_of_its_drawer_by_the_rim_raised_over_its_floor() -> None:
    scene, _, _ = talos_kitchen_drawer_open()
    world, robot = scene.world, scene.robot
    try:
        bowl = world.pose("bowl-1")
        desc = world.robot(robot).description
        hand = hand_of(desc, "left")
        assert hand.pads_behind == pytest.approx(-0.0428, abs=5e-4)
        shape = object_shape(world, world.object("bowl-1"))
        rims = grasps(shape, hand, ("rim",))
        raised = [g for g in rims if g.raised > 0.0]
        assert len(raised) == 8 and rims[-8:] == raised  # a side each, both turns; last
        assert shape.wall is not None
        floor = shape.low[2] + shape.wall + 0.01  # a floor as thick as the wall, 1 cm over it
        for grasp in raised:
            assert grasp.tool.position[2] + hand.pads_behind == pytest.approx(floor, abs=1e-9)
            assert grasp.raised == pytest.approx(0.0148, abs=5e-4)
        hands = [arm.end_effector_link for arm in desc.arms.values()]
        feet = [leg.foot for leg in legs(desc.model, hands)]
        bent = crouched(desc.model, feet, world.joint_states(robot), DEPTH)
        height = world.pose(robot).position[2] - DEPTH
        x, y, _ = bowl.position
        stand = (x + SHOULDER, y - BACK, height)
        world.set_pose(robot, Pose(stand, quat.from_euler(0.0, 0.0, math.pi / 2)))
        world.set_joint_states(robot, bent)
        seen = an.object(type="bowl", name="bowl-1", pose=PoseStamped.from_pose("map", bowl))
        with simulated_robot(world, robot):
            held = pick_up_object(seen, arm="left", out_of=("kitchen", DRAWER))
        lifted, _ = pybullet.getBasePositionAndOrientation(
            world.object("bowl-1").body_id, physicsClientId=world.physics.client()
        )
        assert held.grasp == "rim" and held.object_name == "bowl-1"
        assert lifted[2] - bowl.position[2] > 0.2  # out of the drawer, over its front
        gripped_at = held.grasp_pose.pose.position[2] - bowl.position[2]
        assert gripped_at == pytest.approx(raised[0].tool.position[2], abs=0.003)  # raised
    finally:
        world.close()
