"""The ``reachable`` validator holds the hand on the object to the pick's depth bound.

The pick moves its open hand to the grasp letting it into the object at most 5 mm
(``motion.hand_contact``); a validator letting it in at any depth took stands where
every IK solution of the pick was then refused (the TIAGo's thumb 6.5 mm in the mug).
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.costmaps.pick_reach import HAND_DEPTH, touched_objects
from robocram.costmaps.stand_reach import PALM_IK_RESTARTS, _restarts
from robocram.costmaps.validators import STAND_IK_RESTARTS
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.world import RobotObject, World
from robocram.world.pybullet_backend import pybullet

SIDE = 0.02  # [m] the test block's edge


@pytest.fixture(scope="module")
def scene() -> Iterator[TabletopScene]:
    built = tabletop_scene("pr2")
    yield built
    built.world.close()


def _raw_depth(world: World, robot: RobotObject, link: str, block: str) -> float:
    """How deep [m] ``link`` is in ``block``, by PyBullet's closest points."""
    body, index = robot.locate(robot.link_index[link])
    points = pybullet.getClosestPoints(
        world.object(block).body_id, body, 0.0, linkIndexB=index,
        physicsClientId=world.physics.client(),
    )  # fmt: skip
    return max((-p[8] for p in points), default=0.0)


def _block_at_depth(world: World, robot: RobotObject, link: str, depth: float) -> float:
    """Put the block on ``link`` from above, nearest ``depth`` [m] into it; its raw depth."""
    low, high = world.contacts.link_aabb(robot, link)
    x, y = (low[0] + high[0]) / 2, (low[1] + high[1]) / 2
    tried = []
    for step in range(40):  # lower the block in 0.5 mm steps from just over the link
        z = high[2] + SIDE / 2 - 0.0005 * step
        world.set_pose("block", ((x, y, z), (0.0, 0.0, 0.0, 1.0)))
        tried.append((abs(_raw_depth(world, robot, link, "block") - depth), z))
    z = min(tried)[1]
    world.set_pose("block", ((x, y, z), (0.0, 0.0, 0.0, 1.0)))
    return _raw_depth(world, robot, link, "block")


def test_the_bound_is_the_picks() -> None:
    assert HAND_DEPTH == HAND_CONTACT_DEPTH


def test_the_hand_may_touch_the_object_only_within_the_bound(scene: TabletopScene) -> None:
    world = scene.world
    robot = world.robot(scene.robot)
    arm = next(iter(robot.description.arms))
    spec = robot.description.arms[arm]
    assert spec.gripper is not None
    world.set_joint_states(robot, spec.gripper.at(1.0))  # open, as the pick has it
    tops = {link: world.contacts.link_aabb(robot, link)[1][2] for link in spec.gripper_links}
    finger = max(tops, key=lambda link: tops[link])  # the block from above meets it first
    world.add_box("block", (SIDE, SIDE, SIDE))
    first = spec.joints[0]
    nudged = {first: world.joint_states(robot)[first] + 1e-6}  # the arm's links are checked
    stand = world.pose(robot)
    try:
        shallow = _block_at_depth(world, robot, finger, 0.002)
        assert 0.0 < shallow < HAND_DEPTH - 0.001
        assert touched_objects(world, robot, arm, stand, nudged, True, "block") == []
        deep = _block_at_depth(world, robot, finger, 0.009)
        assert deep > HAND_DEPTH + 0.002
        assert touched_objects(world, robot, arm, stand, nudged, True, "block") == ["block"]
        assert touched_objects(world, robot, arm, stand, nudged, True) == []  # no object named
        assert touched_objects(world, robot, arm, stand, nudged, True, "mug-1") == []  # another
    finally:
        world.remove("block")


def test_a_palm_hands_grasps_get_more_ik_restarts_when_a_stand_is_judged() -> None:
    world = World()
    try:
        tiago = world.add_robot("examples/robots/tiago.py")
        pr2 = world.add_robot("pr2", pose=((3.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
        assert _restarts(tiago, "arm", STAND_IK_RESTARTS) == PALM_IK_RESTARTS
        assert _restarts(pr2, "left", STAND_IK_RESTARTS) == STAND_IK_RESTARTS  # as before
        assert PALM_IK_RESTARTS > STAND_IK_RESTARTS
    finally:
        world.close()
