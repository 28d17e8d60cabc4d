"""A palm hand (TIAGo's Hey5) holds the mug against its palm, the fingers round it."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pybullet
import pytest

from robocram.grasping import hand_of, object_shape
from robocram.grasping.grasp_model import grasps
from robocram.robots import load_description
from robocram.world import World
from tests.bullet_links import link_frame, link_indices

TIAGO = "examples/robots/tiago.py"
FAR = ((5.0, 5.0, 0.0), (0.0, 0.0, 0.0, 1.0))


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    world = World()
    world.add_robot(TIAGO)
    world.add_item("mug-1", "mug", FAR)
    yield world
    world.close()


def _closest(world: World, link: str, reach: float = 0.05) -> float:
    """The distance [m] from the robot's ``link`` to the mug, by PyBullet (below 0: in it)."""
    client = world.physics.client()
    robot = world.object("tiago").body_id
    points = pybullet.getClosestPoints(
        robot, world.object("mug-1").body_id, reach,
        linkIndexA=link_indices(robot, client)[link], physicsClientId=client,
    )  # fmt: skip
    return min((p[8] for p in points), default=reach)


def test_the_hey5_is_a_palm_hand_and_parallel_grippers_are_not() -> None:
    hand = hand_of(load_description(TIAGO), "arm")
    assert hand.palm is not None
    # the fingers point along the tool's x and curl towards its z (the palm faces z)
    assert hand.palm.along == pytest.approx((1.0, 0.0, 0.0), abs=0.08)
    assert hand.palm.curl == pytest.approx((0.0, 0.0, 1.0), abs=0.02)
    assert hand.approach == hand.palm.curl  # a grasp comes in palm first
    assert hand_of(load_description("pr2"), "left").palm is None


def test_the_hands_safety_box_does_not_collide(world: World) -> None:
    client = world.physics.client()
    robot = world.object("tiago").body_id
    box = link_indices(robot, client)["hand_safety_box"]
    assert not pybullet.getCollisionShapeData(robot, box, physicsClientId=client)


def test_the_hey5_takes_the_mug_by_its_handle_its_fingers_too_short_for_the_body(
    world: World,
) -> None:
    hand = hand_of(world.robot("tiago").description, "arm")
    assert hand.palm is not None
    # 9 cm fingers reach half round a body 2 x 9 / pi = 5.7 cm wide: not the 88 mm mug
    assert hand.palm.wraps == pytest.approx(0.057, abs=0.003)
    names = {g.name for g in grasps(object_shape(world, world.object("mug-1")), hand)}
    assert names == {"handle"}


def test_the_handle_grasp_puts_the_bar_on_the_palm_clear_of_the_open_fingers(
    world: World,
) -> None:
    desc = world.robot("tiago").description
    arm = desc.arms["arm"]
    assert arm.gripper is not None
    world.set_joint_states("tiago", arm.gripper.at(1.0))
    grasp = grasps(object_shape(world, world.object("mug-1")), hand_of(desc, "arm"))[0]
    body = world.object("tiago").body_id
    position, rotation = link_frame(body, world.physics.client(), arm.tool_frame)
    tool = np.eye(4)
    tool[:3, :3], tool[:3, 3] = rotation, position
    mug = tool @ np.linalg.inv(grasp.tool.matrix())
    try:
        world.set_pose("mug-1", (tuple(mug[:3, 3]), _quaternion(mug[:3, :3])))
        assert _closest(world, "hand_palm_link") == pytest.approx(0.0, abs=0.004)
        fingers = [link for link in arm.hand_links if link in arm.gripper_links]
        assert min(_closest(world, link) for link in fingers) > -0.001
    finally:
        world.set_pose("mug-1", FAR)


def _quaternion(rotation: np.ndarray) -> tuple[float, float, float, float]:
    w = np.sqrt(max(0.0, 1.0 + np.trace(rotation))) / 2
    x = (rotation[2, 1] - rotation[1, 2]) / (4 * w)
    y = (rotation[0, 2] - rotation[2, 0]) / (4 * w)
    z = (rotation[1, 0] - rotation[0, 1]) / (4 * w)
    return (float(x), float(y), float(z), float(w))
