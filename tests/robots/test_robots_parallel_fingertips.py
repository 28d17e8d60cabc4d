"""A parallel gripper's fingertips standing in for missing meshes reach its tool frame.

The Donbot's WSG 50 (its meshes not shipped) had a 2 cm cube at each fingertip's root,
23 mm past the guides, while its URDF's tool frame is 144 mm out: the check's grip closed
under the mug. Loading grows the boxes out to the tool frame, and the draft parks the arm
on the hand so grown. Judged in a raw PyBullet: rays from the tool frame across the
opening, 5 mm back towards the wrist, meet both fingertips, and parked with the gripper
open the fingers touch nothing.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.robot_check import description_from
from robocram.world import World
from tests.drafts import drafted_module

DONBOT = Path(__file__).resolve().parents[1] / "data" / "zoo" / "iai_donbot" / "iai_donbot.urdf"
TIPS = ("gripper_finger_left_link", "gripper_finger_right_link")


@pytest.fixture(scope="module")
def donbot(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[World, str]]:
    module = tmp_path_factory.mktemp("donbot") / "iai_donbot.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(DONBOT, module)
        with World() as world:
            yield world, world.add_robot(description_from(str(module))).name


def _links(world: World, robot: str) -> dict[str, int]:
    client, body = world.physics.client(), world.object(robot).body_id
    infos = [
        pybullet.getJointInfo(body, i, physicsClientId=client)
        for i in range(pybullet.getNumJoints(body, physicsClientId=client))
    ]
    return {info[12].decode(): info[0] for info in infos}


def test_rays_across_the_opening_at_the_tool_frame_meet_both_fingertips(
    donbot: tuple[World, str],
) -> None:
    world, robot = donbot
    arm = world.robot(robot).description.arms["arm"]
    world.set_joint_states(robot, {"gripper_joint": 0.03})  # 30 mm apart
    client, body, links = world.physics.client(), world.object(robot).body_id, _links(world, robot)
    state = pybullet.getLinkState(
        body, links[arm.tool_frame], computeForwardKinematics=True, physicsClientId=client
    )
    axes = np.array(pybullet.getMatrixFromQuaternion(state[5])).reshape(3, 3)
    x, y = axes[:, 0], axes[:, 1]
    start = np.asarray(state[4]) - 0.005 * x  # 5 mm back: the boxes end at the tool frame
    hit = set()
    for side in (1.0, -1.0):
        ray = pybullet.rayTest(start, start + side * 0.05 * y, physicsClientId=client)[0]
        assert ray[0] == body, side
        hit.add(ray[1])
        assert ray[2] * 0.05 < 0.02  # within 20 mm: the finger's inner face, 15 mm out
    assert hit == {links[tip] for tip in TIPS}


def test_parked_with_the_gripper_open_the_fingertips_touch_nothing(
    donbot: tuple[World, str],
) -> None:
    world, robot = donbot
    arm = world.robot(robot).description.arms["arm"]
    world.set_joint_states(robot, {**arm.parking, "gripper_joint": 0.109})
    client, body, links = world.physics.client(), world.object(robot).body_id, _links(world, robot)
    mine = {links[tip] for tip in TIPS} | {links["gripper_gripper_left_link"]}
    near = [
        (point[3], point[4], point[8])
        for tip in TIPS
        for point in pybullet.getClosestPoints(
            body, body, 0.0, links[tip], -1, physicsClientId=client
        )
    ]
    others = [
        pybullet.getClosestPoints(body, body, 0.0, links[tip], index, physicsClientId=client)
        for tip in TIPS
        for name, index in links.items()
        if index not in mine and name not in arm.hand_links
    ]
    assert not near, near
    assert not [p for points in others for p in points], "a fingertip touches the robot"
