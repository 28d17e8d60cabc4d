"""A drive blocked only by an empty hand still round what it just put down lifts that hand
and drives again (Boxy's household seed 48, session 29: cup-1 just put at its seat, cup-2
held out, every stand for cup-2's seat refused). The situation is rebuilt from the state
the household left (tests/data/boxy_cup_put.json); the outcome is judged by raw PyBullet."""

from __future__ import annotations

import pybullet
import pytest

from robocram.execution.failures import NavigationPathBlocked
from robocram.plans.basic_actions import navigate
from robocram.plans.empty_hand_up import navigate_empty_hand_up
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.world import World
from tests.plans.household_state import rebuilt, saved_pose

LEFT_FINGERS = ("left_gripper_finger_left_link", "left_gripper_finger_right_link")


def _scene() -> tuple[World, str, Pose]:
    """The breakfast kitchen with Boxy, the table and its hands as the household had them;
    the stand the drives went to."""
    household = rebuilt("boxy", "boxy_cup_put.json")
    return household.world, household.robot, saved_pose(household.state["stand"])


def _bullet_pose(world: World, body: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    position, orientation = pybullet.getBasePositionAndOrientation(
        world.object(body).body_id, physicsClientId=world.physics.client()
    )
    return tuple(position), tuple(orientation)


def _lowest(world: World, body: str, links: tuple[str, ...]) -> float:
    """The lowest point [m] of ``links``' bounding boxes by PyBullet."""
    uid, cid = world.object(body).body_id, world.physics.client()
    index = {
        pybullet.getJointInfo(uid, j, physicsClientId=cid)[12].decode(): j
        for j in range(pybullet.getNumJoints(uid, physicsClientId=cid))
    }
    return min(pybullet.getAABB(uid, index[link], physicsClientId=cid)[0][2] for link in links)


def _top(world: World, body: str) -> float:
    uid, cid = world.object(body).body_id, world.physics.client()
    return float(pybullet.getAABB(uid, -1, physicsClientId=cid)[1][2])


def test_boxy_lifts_the_hand_that_put_cup_1_down_and_drives_to_cup_2s_stand() -> None:
    world, robot, stand = _scene()
    try:
        cup = _bullet_pose(world, "cup-1")
        target = PoseStamped.from_pose("map", stand)
        with simulated_robot(world, robot):
            with pytest.raises(NavigationPathBlocked) as blocked:
                navigate(target)  # as before: the open left fingers meet cup-1
            assert blocked.value.colliding == ["cup-1"]
            assert set(blocked.value.robot_links or ()) <= set(LEFT_FINGERS)
            assert blocked.value.robot_links
            navigate_empty_hand_up(target)
        (x, y, _), _ = _bullet_pose(world, robot)
        assert abs(x - stand.position[0]) < 0.01 and abs(y - stand.position[1]) < 0.01
        # cup-1 stayed where it was put, and the fingers are above it now
        now = _bullet_pose(world, "cup-1")
        assert max(abs(a - b) for a, b in zip(now[0], cup[0], strict=True)) < 1e-3
        assert _lowest(world, robot, LEFT_FINGERS) > _top(world, "cup-1")
        # cup-2 is still in the right hand
        assert world.bodies.attachments(robot).get("cup-2") == "right_arm_7_link"
    finally:
        world.close()
