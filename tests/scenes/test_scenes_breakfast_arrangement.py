"""A household's own arrangement of the breakfast kitchen: the knowledge and the items
move together, so a plan reading the usual places finds them where they are."""

from __future__ import annotations

from dataclasses import replace

import pybullet
import pytest

from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene

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
