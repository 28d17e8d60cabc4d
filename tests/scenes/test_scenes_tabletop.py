"""The tabletop scene is placed from the robot's description, never from its name."""

from __future__ import annotations

import dataclasses

import pytest

from robocram.robots import load_description
from robocram.scenes import UnfitRobotError, tabletop_placement, tabletop_scene
from robocram.world import World


@pytest.mark.parametrize(
    ("robot", "arm", "height", "mug_xy"),
    [
        ("pr2", "right", 0.616, (0.587, -0.150)),  # 0.15 m past its 0.337 m base, panning arm
        ("hsrb", "arm", 0.455, (0.457, 0.078)),  # in the plane of its arm (no pan joint)
        ("boxy", "right", 0.641, (1.214, -0.113)),  # 0.65 of the 0.99 m arm ahead of it
    ],
)
def test_placement_follows_reach_and_footprint(
    robot: str, arm: str, height: float, mug_xy: tuple[float, float]
) -> None:
    scene = tabletop_scene(robot)
    world = scene.world
    assert world.pose("mug-1").position == pytest.approx((*mug_xy, height), abs=1e-3)
    assert world.aabb("table")[1][2] == pytest.approx(height, abs=1e-3)
    assert scene.look_target.position == pytest.approx((*mug_xy, height), abs=1e-3)
    assert tabletop_placement(world, robot).arm == arm
    table_front = world.aabb("table")[0][0]
    assert world.contacts.link_aabb(robot, "base_link")[1][0] < table_front  # the base clears it
    world.close()


def test_a_renamed_robot_gets_the_same_scene() -> None:
    pr2 = load_description("pr2")
    clone = dataclasses.replace(pr2, name="my_pr2")
    scene = tabletop_scene(clone)
    assert scene.robot == "my_pr2"
    assert scene.world.pose("mug-1").position == pytest.approx((0.587, -0.150, 0.616), abs=1e-3)
    scene.world.close()


def test_a_taller_torso_raises_the_table_by_half_its_travel() -> None:
    pr2 = load_description("pr2")
    assert pr2.model is not None and pr2.torso_joint is not None
    torso = pr2.model.joints[pr2.torso_joint]
    assert torso.upper is not None
    longer = dataclasses.replace(torso, upper=torso.upper + 0.2)
    model = dataclasses.replace(pr2.model, joints={**pr2.model.joints, torso.name: longer})
    tall = dataclasses.replace(pr2, name="tall_pr2", model=model)
    with World() as world:
        world.add_robot(tall)
        place = tabletop_placement(world, "tall_pr2")
    assert place.table_height == pytest.approx(0.616 + 0.1, abs=1e-3)


def test_a_robot_without_a_gripper_arm_is_unfit() -> None:
    with World() as world, pytest.raises(UnfitRobotError) as info:
        tabletop_scene("quadrotor", world)
    assert info.value.robot == "quadrotor"
    assert "no arm with joints and a gripper" in str(info.value)
