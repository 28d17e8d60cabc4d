"""A small arm whose second joint rises over its pan gets its mug where it reaches.

The SO-100 (example-robot-data, drafted): its shoulder_lift sits 0.10 m above its
shoulder_pan, and the scene put the mug 0.65 of a reach counting that rise ahead, its
grasps 3-37 mm beyond its wrist. The mug now comes in until the grasping wrist is within
``PAST_RISE_SHARE`` of the reach from the lift joint. Judged by PyBullet: the distance from
the top of the rise (raw link states) to the wrist's spot, and the mug lifted off the table.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pybullet

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robots import draft_description, example_robot_data_folder
from robocram.scenes import tabletop_scene
from robocram.scenes.placement import PAST_RISE_SHARE, WRIST_BELOW_SHOULDER

SO100 = "so_arm_description/urdf/so100.urdf"
FOREARMS = 0.311  # [m] the lift joint to the wrist, stretched (the URDF's origins, by hand)
LIFTED = 0.03  # [m] the mug rises at least this much


def test_the_so100s_mug_lies_within_reach_past_its_rise_and_it_lifts_it(tmp_path: Path) -> None:
    module = tmp_path / "so100.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        urdf = example_robot_data_folder() / SO100
        module.write_text(draft_description(urdf).source(module), "utf-8")
        scene = tabletop_scene(str(module))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        links = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        pan = pybullet.getLinkState(body, links["shoulder"], physicsClientId=client)[4]
        lift = pybullet.getLinkState(body, links["upper_arm"], physicsClientId=client)[4]
        mug_id = world.object("mug-1").body_id
        start, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        wrist = (start[0], start[1], pan[2] - WRIST_BELOW_SHOULDER)
        top = (pan[0], pan[1], lift[2])  # the pan's axis is vertical: the top of the rise
        across = math.hypot(lift[0] - pan[0], lift[1] - pan[1])
        assert math.dist(top, wrist) <= PAST_RISE_SHARE * (FOREARMS + across) + 1e-3
        assert start[0] - pan[0] < 0.24  # 0.27 before: 3-37 mm beyond its wrist
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        end, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        assert end[2] > start[2] + LIFTED
    finally:
        world.close()
