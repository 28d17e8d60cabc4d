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
from robocram.scenes import tabletop_scene
from robocram.scenes.placement import WRIST_BELOW_SHOULDER
from tests.so100_rise import drafted_so100, rise

LIFTED = 0.03  # [m] the mug rises at least this much


def test_the_so100s_mug_lies_within_reach_past_its_rise_and_it_lifts_it(tmp_path: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(drafted_so100(tmp_path))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        pan, top, room = rise(body, client)
        mug_id = world.object("mug-1").body_id
        start, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        wrist = (start[0], start[1], pan[2] - WRIST_BELOW_SHOULDER)
        assert math.dist(top, wrist) <= room + 1e-3
        assert start[0] - pan[0] < 0.24  # 0.27 before: 3-37 mm beyond its wrist
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        end, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        assert end[2] > start[2] + LIFTED
    finally:
        world.close()
