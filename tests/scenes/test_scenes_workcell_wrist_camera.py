"""A five-joint arm's wrist camera finds and fetches things its workcell's table frame hides.

The SO-101 (``examples/robots``) cannot turn its wrist camera to its table's frame, 7.5 cm
right of the mug (its wrist meets its shoulder), nor to the bowl 0.15 m right of its
arm's plane; the search and the fetch look round those points on the surface, and the
fetch opens the jaw that hides the mug. PyBullet judges: where the mug and the bowl end up.
"""

from __future__ import annotations

import math
from pathlib import Path

import pybullet

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.robot_check import description_from
from robocram.scenes import workcell_scene, workcell_spots

SO101 = Path(__file__).resolve().parents[2] / "examples" / "robots" / "so101.py"
PLACED = 0.02  # [m] an item put down lies this near its spot


def test_a_wrist_camera_that_cannot_look_at_the_tables_frame_still_carries_both() -> None:
    scene = workcell_scene(description_from(str(SO101)))
    world = scene.world
    try:
        client = world.physics.client()
        spots = workcell_spots(scene)
        with simulated_robot(world, scene.robot):
            for kind, item in (("mug", "mug-1"), ("bowl", "bowl-1")):
                perform(an.action(type="transporting", object=kind, target=spots[item]))
        for item in ("mug-1", "bowl-1"):
            body = scene.items[item].body_id
            (x, y, _), _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
            sx, sy, _ = spots[item].position
            assert math.hypot(x - sx, y - sy) < PLACED, item
    finally:
        world.close()
