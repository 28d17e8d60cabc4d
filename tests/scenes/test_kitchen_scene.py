"""The kitchen: as rich as the anchors' kitchens, facts that match its URDF, items in place."""

from __future__ import annotations

import importlib.util
import math
import sys
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

import pytest

from robocram.scenes import kitchen_scene, kitchen_urdf
from robocram.scenes.kitchen_scene import kitchen_description
from robocram.world import World

TOOLS = Path(__file__).resolve().parents[2] / "tools"


def _generator() -> ModuleType:
    sys.path.insert(0, str(TOOLS))
    try:
        spec = importlib.util.spec_from_file_location(
            "make_kitchen_urdf", TOOLS / "make_kitchen_urdf.py"
        )
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules["make_kitchen_urdf"] = module  # dataclasses look their module up
        spec.loader.exec_module(module)
        return module
    finally:
        sys.path.remove(str(TOOLS))


def test_the_shipped_urdf_is_what_the_generator_writes() -> None:
    urdf, _ = _generator().build()
    assert (kitchen_urdf().parent / "kitchen.urdf").read_text("utf-8") == urdf


def test_the_drafted_facts_are_the_ones_the_generator_meant() -> None:
    """The kitchen's facts are drafted from its URDF: the same 113 the generator knows."""
    _, meant = _generator().build()
    clauses = {line for line in meant.splitlines() if line and not line.startswith("%")}
    drafted = kitchen_description().facts().splitlines()
    semantic = {line for line in drafted if not line.startswith("usual_location(")}
    assert len(clauses) == 113  # 5 surfaces; 27 containers, 4 facts each
    assert semantic == clauses
    assert not (kitchen_urdf().parent / "kitchen.pl").exists()  # no hand-written facts left


def test_as_many_drawers_and_doors_as_the_anchors_kitchen() -> None:
    joints = ET.parse(kitchen_urdf()).getroot().findall("joint")
    kinds = [j.get("type") for j in joints]
    assert kinds.count("prismatic") >= 16  # PyCRAM's kitchen: 16 prismatic, 9 revolute
    assert kinds.count("revolute") >= 9


@pytest.fixture(scope="module")
def pr2_kitchen() -> Iterator[World]:
    scene = kitchen_scene("pr2")
    yield scene.world
    scene.world.close()


def test_the_room_is_six_by_five_metres(pr2_kitchen: World) -> None:
    walls = [
        pr2_kitchen.contacts.link_aabb("kitchen", f"wall_{s}")
        for s in ("north", "south", "east", "west")
    ]
    low = [min(w[0][i] for w in walls) for i in range(3)]
    high = [max(w[1][i] for w in walls) for i in range(3)]
    assert high[0] - low[0] == pytest.approx(6.2, abs=0.01)  # 6 m inside, 0.1 m walls
    assert high[1] - low[1] == pytest.approx(5.2, abs=0.01)


def test_every_container_opens_by_its_joint_and_moves_its_handle(pr2_kitchen: World) -> None:
    world = pr2_kitchen
    containers = list(world.kb.query("container(kitchen, L, J, H), container_kind(kitchen, L, K)"))
    assert len(containers) == 27
    with world.snapshots.stored_state():
        for c in containers:
            before = world.link_pose("kitchen", c["H"]).position
            upper = world.bodies.joint_limits("kitchen", c["J"]).upper
            world.set_joint_states("kitchen", {c["J"]: upper})
            moved = math.dist(before, world.link_pose("kitchen", c["H"]).position)
            if c["K"] == "drawer":
                assert moved == pytest.approx(upper, abs=1e-6), c["J"]
            else:  # a door's handle swings on a circle about the hinge: a chord > 0.5 m
                assert moved > 0.5, c["J"]


def test_items_rest_where_the_kb_says_they_are_kept(pr2_kitchen: World) -> None:
    world = pr2_kitchen
    usual = {a["T"]: a["L"] for a in world.kb.query("usual_location(T, kitchen, L)")}
    assert usual["bowl"] == "drawer_unit_drawer_3"
    assert usual["mug"] == "counter_top_north"
    for obj in world.objects():
        if obj.type in usual:
            touching = world.contacts.contact_points(
                obj, "kitchen", link_b=usual[obj.type], distance=0.005
            )
            assert touching, f"{obj.name} does not rest on {usual[obj.type]}"
    with world.snapshots.stored_state():
        world.physics.simulate(0.5)
        assert world.physics.stable()


def test_surfaces_face_up_at_counter_and_table_height(pr2_kitchen: World) -> None:
    world = pr2_kitchen
    tops = {
        a["L"]: world.contacts.link_aabb("kitchen", a["L"])[1][2]
        for a in world.kb.query("supporting_surface(kitchen, L)")
    }
    assert tops["counter_top_north"] == pytest.approx(0.85, abs=2e-3)
    assert tops["counter_top_east"] == pytest.approx(0.85, abs=2e-3)
    assert tops["table_top"] == pytest.approx(0.75, abs=2e-3)


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_the_robot_starts_free_in_the_middle(robot: str) -> None:
    scene = kitchen_scene(robot)
    assert scene.world.contacts.collisions(scene.robot, ignore=["floor"]) == []
    assert scene.world.pose(scene.robot).position[:2] == pytest.approx((-0.8, 0.2))
    scene.world.close()
