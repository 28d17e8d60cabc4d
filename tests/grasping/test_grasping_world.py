"""Grasps of objects in a world: hands read from robots, KB facts per type, the KB door."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.grasping import (
    GraspingError,
    catalogue_shape,
    grasp_candidates,
    hand_of,
    install_grasp_predicates,
    object_shape,
)
from robocram.logic import KnowledgeBase, Term
from robocram.robots import install_description, load_description
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped, TransformStamped, TransformTree, using_transform_tree
from robocram.tf import quaternion as quat


@pytest.fixture(scope="module")
def kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    install_grasp_predicates(scene.world.kb, scene.world)
    yield scene
    scene.world.close()


@pytest.mark.parametrize(
    ("robot", "arm", "opening"),
    [("pr2", "left", 0.0938), ("hsrb", "arm", 0.1302), ("boxy", "right", 0.1025)],
)
def test_hands_are_read_from_the_robot(robot: str, arm: str, opening: float) -> None:
    hand = hand_of(load_description(robot), arm)
    assert hand.approach == pytest.approx((1.0, 0.0, 0.0), abs=1e-6)  # wrist to tool: x
    assert hand.opening == pytest.approx((0.0, 1.0, 0.0), abs=0.01)  # fingers apart along y
    assert hand.max_opening == pytest.approx(opening, abs=1e-4)


def test_shapes_carry_the_type_facts(kitchen: KitchenScene) -> None:
    world = kitchen.world
    bowl = object_shape(world, world.object("bowl-1"))
    assert (bowl.wall, bowl.handle) == (0.006, None)
    assert bowl.size[0] == pytest.approx(0.16, abs=0.003)  # the hollow bowl, 16 cm across
    assert bowl.size[2] == pytest.approx(0.06, abs=0.005)
    mug = object_shape(world, world.object("mug-1"))
    assert (mug.wall, mug.handle) == (None, 0.012)
    assert mug.radius == pytest.approx(0.044, abs=1e-3)  # the body, not the handle
    measured = catalogue_shape("mug", "mug-1", None, 0.012)
    assert measured.low == pytest.approx(mug.low) and measured.high == pytest.approx(mug.high)


def test_a_turned_object_keeps_its_sizes(kitchen: KitchenScene) -> None:
    world = kitchen.world
    milk = world.object("milk-1")
    with world.snapshots.stored_state():
        here = world.pose(milk)
        turned = Pose(here.position, quat.from_euler(0.0, 0.0, math.pi / 4))
        world.set_pose(milk, turned)
        shape = object_shape(world, milk)
        assert world.pose(milk).angle_to(turned) < 1e-6  # put back as it was
    assert shape.size == pytest.approx((0.07, 0.07, 0.2), abs=1e-6)


def test_kb_facts_restrict_and_order_the_grasps(kitchen: KitchenScene) -> None:
    world = kitchen.world
    pr2, milk = world.robot(kitchen.robot), world.object("milk-1")
    assert {c.grasp.name for c in grasp_candidates(world, milk, pr2, "left")} == {
        "top",
        "front",
        "left",
        "right",
    }
    world.kb.consult("object_grasps(milk, [right, top]).", group="milk_grasps")
    try:
        names = [c.grasp.name for c in grasp_candidates(world, milk, pr2, "left")]
        assert names == ["right", "right", "top", "top", "top", "top"]
        answers = list(world.kb.query("object_grasp('milk-1', pr2, left, N, G, P, L)"))
        assert [a["N"] for a in answers] == names
        first = grasp_candidates(world, milk, pr2, "left")[0]
        assert answers[0]["G"] == PoseStamped.from_pose("map", first.tool)
        assert answers[0]["L"].position[2] == pytest.approx(first.tool.position[2] + 0.10)
    finally:
        world.kb.consult("", group="milk_grasps")


def test_the_kb_door_says_why_an_object_is_ungraspable(kitchen: KitchenScene) -> None:
    world = kitchen.world
    world.add_item("pot-1", "pot", Pose((0.0, 0.0, 3.0)))
    try:
        assert not world.kb.holds("object_grasp('pot-1', pr2, _, _, _, _, _)")
        answers = list(world.kb.query("object_ungraspable('pot-1', pr2, A, H, W)"))
        assert [a["A"] for a in answers] == ["left", "right"]
        assert answers[0]["H"] == pytest.approx(0.0938, abs=1e-4)
        assert answers[0]["W"] == pytest.approx(0.2 + 0.002)
    finally:
        world.remove("pot-1")


def test_without_a_world_objects_are_named_by_type_and_pose() -> None:
    desc = load_description("pr2")
    kb = KnowledgeBase()
    install_description(kb, desc)
    install_grasp_predicates(kb, description=desc)
    tree = TransformTree()
    tree.set_transform(TransformStamped.from_pose("map", desc.base_frame, Pose((0, 0, 0))))
    mug = PoseStamped("map", (0.6, 0.0, 0.7))
    with using_transform_tree(tree):
        answer = kb.first(
            "object_grasp(O, pr2, right, top, G, _, _)", O=Term("object", ("mug-1", "mug", mug))
        )
    assert answer is not None
    assert answer["G"].position == pytest.approx((0.6, 0.0, 0.763))  # 4 cm under its top


def test_a_type_outside_the_catalogue_has_no_shape_without_a_world() -> None:
    with pytest.raises(GraspingError, match="'teapot' is not in the catalogue.*bowl"):
        catalogue_shape("teapot", "teapot-1")


def test_the_reachability_costmap_checks_the_plans_grasps(kitchen: KitchenScene) -> None:
    from robocram.costmaps.grasps import grasp_point, grasp_poses

    world = kitchen.world
    pr2, mug = world.robot(kitchen.robot), world.object("mug-1")
    base = world.pose(pr2)
    plans = grasp_candidates(world, mug, pr2, "right")
    costmap = grasp_poses(world, mug, pr2.description, "right", base)
    assert len(costmap) == len(plans) > 0
    for seen_from_base, candidate in zip(costmap, plans, strict=True):
        assert (base * seen_from_base).distance_to(candidate.tool) < 1e-9
        assert (base * seen_from_base).angle_to(candidate.tool) < 1e-9
    top = next(c for c in plans if c.grasp.name == "top")
    assert grasp_point(world, mug) == pytest.approx(top.tool.position)
