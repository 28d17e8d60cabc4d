"""What a new scene would work out again, kept with the models across worlds, equals what
that scene reads afresh: the robot's link radii (against raw PyBullet bounds), the
kitchen's obstacle shapes, a travel bound; a robot in another state gets its own."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pybullet
import pytest

from robocram.grasping.hand import _read_hand, hand_of
from robocram.motion.obstacle_shapes import ObstacleShapes, obstacle_cache
from robocram.motion.travel_bound import TravelBound, _made, link_radii
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.world import RobotHandle, World

ARM = ("r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint")


@pytest.fixture(scope="module")
def scenes() -> Iterator[tuple[KitchenScene, KitchenScene, KitchenScene]]:
    made = (kitchen_scene("pr2"), kitchen_scene("pr2"), kitchen_scene("pr2"))
    yield made
    for scene in made:
        scene.world.close()


def _raw_radii(world: World, links: list[str]) -> dict[str, float]:
    """Per link: the farthest corner of its PyBullet bounds from its frame [m]."""
    cid, robot = world.physics.client(), world.object("pr2")
    radii = {}
    for link in links:
        body, index = robot.locate(robot.link_index[link])
        if index < 0:
            origin = pybullet.getBasePositionAndOrientation(body, physicsClientId=cid)[0]
        else:
            origin = pybullet.getLinkState(body, index, physicsClientId=cid)[4]
        low, high = (np.array(v) for v in pybullet.getAABB(body, index, physicsClientId=cid))
        far = np.maximum(np.abs(low - origin), np.abs(high - origin))
        radii[link] = float(np.linalg.norm(far))
    return radii


def test_link_radii_of_a_new_scene_are_its_own_bounds(scenes: tuple[KitchenScene, ...]) -> None:
    first, second, moved = (s.world for s in scenes)
    links = ["base_link", "r_upper_arm_link", "r_forearm_link", "head_tilt_link"]
    kept = second.contacts.link_radii("pr2")
    assert kept == first.contacts.link_radii("pr2")
    raw = _raw_radii(second, links)
    assert [kept[k] for k in links] == pytest.approx([raw[k] for k in links], abs=1e-9)
    # another state: read in that world, not taken from the others
    moved.set_joint_states("pr2", {"r_shoulder_pan_joint": -0.6})
    turned = moved.contacts.link_radii("pr2")
    raw = _raw_radii(moved, links)
    assert [turned[k] for k in links] == pytest.approx([raw[k] for k in links], abs=1e-9)
    assert turned["r_upper_arm_link"] != pytest.approx(kept["r_upper_arm_link"], abs=1e-4)


def test_obstacle_shapes_of_a_new_scene_are_its_own(scenes: tuple[KitchenScene, ...]) -> None:
    first, second = scenes[0].world, scenes[1].world
    kitchen_a, kitchen_b = first.object("kitchen"), second.object("kitchen")
    a = obstacle_cache(first).shapes(first, kitchen_a)
    b = obstacle_cache(second).shapes(second, kitchen_b)
    fresh = ObstacleShapes.of(second, kitchen_b)
    assert b.obj is kitchen_b and b.geometries is a.geometries  # kept, for this world
    assert b.labels == fresh.labels and len(b.labels) > 200
    assert np.array_equal(b.centres, fresh.centres) and np.array_equal(b.halves, fresh.halves)
    assert np.array_equal(b.translations, fresh.translations)


def test_a_travel_bound_of_a_new_scene_is_made_from_its_own_radii(
    scenes: tuple[KitchenScene, ...],
) -> None:
    first, second = (RobotHandle.of(s.world, "pr2") for s in scenes[:2])
    bound = TravelBound.of(second, ARM)
    assert bound is TravelBound.of(first, ARM)  # one bound for equal inputs
    fresh = _made(second, ARM, link_radii(second), {}, bound.max_link_travel, bound.max_joint_step)
    assert np.array_equal(bound.lever, fresh.lever) and bound.lever[0] > 0.5


def test_a_new_scenes_robot_takes_the_hands_read_for_an_equal_description(
    scenes: tuple[KitchenScene, ...],
) -> None:
    first, second = (s.world.robot("pr2").description for s in scenes[:2])
    assert first is not second and first == second  # each scene loads it anew
    kept = hand_of(second, "right")
    assert kept is hand_of(first, "right")
    assert kept == _read_hand(second, "right")  # what reading it for this one gives
