"""A household's own arrangement of the breakfast kitchen: the knowledge and the items
move together, so a plan reading the usual places finds them where they are."""

from __future__ import annotations

import math
from dataclasses import replace

import pybullet
import pytest

from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene
from robocram.scenes.errors import SceneError

STOVE_DRAWER = "stove_unit_drawer_2"


def test_bowls_kept_in_another_drawer_are_there_and_the_knowledge_says_so() -> None:
    kept = [replace(p, link=STOVE_DRAWER) if p.kind == "bowl" else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene("pr2", kept=kept)
    world = scene.world
    try:
        usual = {a["T"]: a["L"] for a in world.kb.query("usual_location(T, kitchen, L)")}
        assert usual["bowl"] == STOVE_DRAWER
        assert usual["cup"] == "cutlery_unit_drawer_4"  # the rest as the default kitchen keeps it
        spots = list(world.kb.query(f"usual_spot(bowl, kitchen, {STOVE_DRAWER}, X, Y)"))
        assert sorted((s["X"], s["Y"]) for s in spots) == [(-0.26, -0.12), (-0.26, 0.12)]
        cid = world.physics.client()
        kitchen = world.object("kitchen")
        low, high = pybullet.getAABB(
            *kitchen.locate(kitchen.link_index[STOVE_DRAWER]), physicsClientId=cid
        )
        for name in ("bowl-1", "bowl-2"):
            a, b = pybullet.getAABB(world.object(name).body_id, physicsClientId=cid)
            assert all(low[i] <= a[i] and b[i] <= high[i] for i in range(2)), name
            assert a[2] == pytest.approx(low[2], abs=0.03)  # on the drawer's floor
    finally:
        world.close()


def test_a_knife_laid_through_a_drawer_front_is_refused_and_laid_along_it_fits() -> None:
    """The east drawers face west: a knife square to the map lies along such a drawer's
    depth and its tip goes through the front. Placed so, a physics step shot it 8 cm
    into the drawer, onto the spoons; now the scene refuses it, naming the fix."""
    east = "east_drawers_3_drawer_3"
    knife = next(p for p in BREAKFAST_PLACES if p.kind == "knife")
    with pytest.raises(SceneError, match=f"knife-1 .* inside kitchen/{east}; .*turn it"):
        breakfast_scene("pr2", kept=[replace(knife, link=east)])
    scene = breakfast_scene("pr2", kept=[replace(knife, link=east, yaw=math.pi / 2)])
    world = scene.world
    try:
        cid = world.physics.client()
        body = world.object("knife-1").body_id
        low, high = pybullet.getAABB(body, physicsClientId=cid)
        assert high[1] - low[1] == pytest.approx(0.22, abs=0.01)  # along the width (map y)
        assert not pybullet.getClosestPoints(body, world.object("kitchen").body_id, 0.0,
                                             physicsClientId=cid)  # fmt: skip
    finally:
        world.close()


def test_nothing_of_the_default_breakfast_starts_inside_anything() -> None:
    scene = breakfast_scene("pr2")
    world = scene.world
    try:
        cid = world.physics.client()
        bodies = {o.name: o.body_id for o in world.objects()}
        for item in scene.items:
            for name, body in bodies.items():
                if name == item:
                    continue
                points = pybullet.getClosestPoints(bodies[item], body, 0.0, physicsClientId=cid)
                assert min((p[8] for p in points), default=0.0) > -0.001, (item, name)
    finally:
        world.close()
