"""A thing a fetch ran dry on is taken again only where no other of its kind is seen:
the next trip takes the other bowl (the HSR's household 9 tried bowl-2 twice and never
bowl-1). Judged by raw PyBullet: the thing chosen lies in the drawer looked into."""

from __future__ import annotations

import pybullet

from robocram.plans.attempt_log import AttemptLog
from robocram.plans.bringing import Visit, find, usual_place, wanted_object
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene


def test_a_bowl_that_could_not_be_fetched_is_taken_after_the_other() -> None:
    scene = breakfast_scene("pr2")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            place = usual_place("bowl")
            assert place is not None
            visit, log = Visit(place), AttemptLog()
            chosen = []
            for later in ([], ["bowl-1"], ["bowl-2"], ["bowl-1", "bowl-2"]):
                seen, inside = find(wanted_object("bowl"), visit, log, later=later)
                assert inside is not None and inside.container.link == place.link
                chosen.append(str(seen.get("name")))
        assert chosen[1] != "bowl-1" and chosen[2] != "bowl-2"  # the other, where seen
        assert chosen[0] == chosen[3]  # all of them ran dry: the first seen, as before
        assert set(chosen[1:3]) == {"bowl-1", "bowl-2"}
        kitchen = world.object("kitchen")
        drawer = kitchen.link_index[place.link]
        low, high = pybullet.getAABB(kitchen.body_id, drawer, physicsClientId=cid)
        for name in set(chosen):
            x, y, z = pybullet.getBasePositionAndOrientation(
                world.object(name).body_id, physicsClientId=cid
            )[0]
            assert low[0] <= x <= high[0] and low[1] <= y <= high[1]  # in the drawer
    finally:
        world.close()
