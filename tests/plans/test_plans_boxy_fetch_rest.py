"""Boxy takes a cup out of its drawer when the first stands' tries all failed to lift it
out (session 24, household seed 2), judged by raw PyBullet (the cup above the drawer)."""

from __future__ import annotations

from dataclasses import replace

import pybullet

from robocram.designators import an
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.bringing import Visit, find, usual_place
from robocram.plans.fetch import fetch
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene

CUPS = "cutlery_unit_drawer_4"
CUP_X = -0.2276  # [m] cup-1 along its drawer's x in seed 2 (its usual spot jittered)


def test_boxy_takes_cup_1_from_a_stand_after_its_three_tries() -> None:
    places = [replace(p, xy=(CUP_X, p.xy[1])) if p.name == "cup-1" else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene("boxy", places=places)
    world = scene.world
    cid = world.physics.client()
    log = AttemptLog()
    try:
        with simulated_robot(world, scene.robot):
            cup = an.object(type="cup", name="cup-1")
            seen, opened = find(cup, Visit(usual_place("cup")), log)
            held = fetch(seen, log=log, opened=opened)
        assert held.object_name == "cup-1"
        tried = [a for a in log.of("fetch") if type(a.failure).__name__ == "PickUpUnreachable"]
        assert len(tried) >= 3  # the three tries ran out before the stand that took it
        kitchen = world.object("kitchen")
        top = pybullet.getAABB(kitchen.body_id, kitchen.link_index[CUPS], cid)[1][2]
        low = pybullet.getAABB(world.object("cup-1").body_id, physicsClientId=cid)[0][2]
        assert low > top  # lifted out of its drawer
    finally:
        world.close()
