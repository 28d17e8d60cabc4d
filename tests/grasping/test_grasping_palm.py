"""A palm hand (TIAGo's Hey5) holds the mug against its palm, the fingers round it."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pybullet
import pytest

from robocram.grasping import hand_of, object_shape, palm_hold
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


def test_the_handle_from_above_leaves_the_open_hand_clear_of_the_body(world: World) -> None:
    """The open thumb lay across the mug 6.5 mm below its rim, or a finger over it: closing,
    it met the mug on one side only. The grasps kept leave every link of the open hand out
    of the mug (PyBullet's closest points, the mug put where each grasp has it)."""
    desc = world.robot("tiago").description
    arm = desc.arms["arm"]
    assert arm.gripper is not None
    world.set_joint_states("tiago", arm.gripper.at(1.0))
    shape = object_shape(world, world.object("mug-1"))
    above = [g for g in grasps(shape, hand_of(desc, "arm")) if g.approach == (0.0, 0.0, -1.0)]
    assert above  # the handle from above is still offered
    body = world.object("tiago").body_id
    position, rotation = link_frame(body, world.physics.client(), arm.tool_frame)
    tool = np.eye(4)
    tool[:3, :3], tool[:3, 3] = rotation, position
    try:
        for grasp in above:
            mug = tool @ np.linalg.inv(grasp.tool.matrix())
            world.set_pose("mug-1", (tuple(mug[:3, 3]), _quaternion(mug[:3, :3])))
            assert min(_closest(world, link) for link in arm.hand_links) > -0.001
    finally:
        world.set_pose("mug-1", FAR)


def _quaternion(rotation: np.ndarray) -> tuple[float, float, float, float]:
    w = np.sqrt(max(0.0, 1.0 + np.trace(rotation))) / 2
    x = (rotation[2, 1] - rotation[1, 2]) / (4 * w)
    y = (rotation[0, 2] - rotation[2, 0]) / (4 * w)
    z = (rotation[1, 0] - rotation[0, 1]) / (4 * w)
    return (float(x), float(y), float(z), float(w))


def _contacts(world: World, bar: str, links: list[str]) -> list[tuple[float, np.ndarray]]:
    """(distance [m], normal on the bar) of each of ``links`` within 5 mm of ``bar``."""
    client = world.physics.client()
    robot = world.object("tiago").body_id
    indices = link_indices(robot, client)
    found = []
    for link in links:
        for point in pybullet.getClosestPoints(
            robot, world.object(bar).body_id, 0.005,
            linkIndexA=indices[link], physicsClientId=client,
        ):  # fmt: skip
            found.append((float(point[8]), np.asarray(point[7])))
    return found


def test_a_palm_hand_holds_a_handle_bar_on_its_palm_the_fingers_closing_round_it(
    world: World,
) -> None:
    desc = world.robot("tiago").description
    arm = desc.arms["arm"]
    assert arm.gripper is not None
    hold, palm = palm_hold(desc, "arm", 0.01), hand_of(desc, "arm").palm
    assert hold is not None and palm is not None
    approach, middle = hold
    assert approach == pytest.approx((0.0, 0.0, 1.0), abs=0.02)  # the palm first
    across = np.asarray(palm.across)  # the bar lies along the row, the fingers across it
    body = world.object("tiago").body_id
    position, rotation = link_frame(body, world.physics.client(), arm.tool_frame)
    frame = np.column_stack([np.cross(across, approach), across, approach])
    centre = position + rotation @ np.asarray(middle)
    bar = world.add_box("bar", (0.02, 0.14, 0.02), (tuple(centre), _quaternion(rotation @ frame)))
    links = list(arm.hand_links)
    try:
        world.set_joint_states("tiago", arm.gripper.at(1.0))
        assert _closest_to(world, bar.name, "hand_palm_link") == pytest.approx(0.002, abs=0.002)
        assert min(d for d, _ in _contacts(world, bar.name, links)) > -0.001
        squeezed = False
        for fraction in np.linspace(1.0, 0.0, 41).tolist():  # close until a finger is 4 mm in
            world.set_joint_states("tiago", arm.gripper.at(fraction))
            touching = _contacts(world, bar.name, links)
            if min((d for d, _ in touching), default=1.0) < -0.004:
                break
            normals = [n for _, n in touching]
            squeezed |= any(float(a @ b) < -0.3 for a in normals for b in normals)
        assert squeezed  # pressed from opposite sides (the palm and the curled fingers)
    finally:
        world.set_joint_states("tiago", arm.gripper.at(1.0))
        world.remove(bar.name)


def _closest_to(world: World, name: str, link: str) -> float:
    client = world.physics.client()
    robot = world.object("tiago").body_id
    points = pybullet.getClosestPoints(
        robot, world.object(name).body_id, 0.05,
        linkIndexA=link_indices(robot, client)[link], physicsClientId=client,
    )  # fmt: skip
    return min((p[8] for p in points), default=0.05)
