"""TALOS crouches: its root goes straight down, its soles stay where they stood.

Judged on raw PyBullet (its own forward kinematics of the loaded URDF), apart from the
pinocchio model the crouch is solved on. Why: TALOS holds the bowl drawer's handle from
the front only with its body 0.15 m lower (issue 37, ``handle_hold_probe.py --lower``).
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.kinematics.crouch import CrouchUnreachable, crouched
from robocram.robot_check import description_from
from robocram.robots.draft.stance import legs
from robocram.tf import Pose
from robocram.world import RobotObject, World
from tests.bullet_links import link_frame

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"


@pytest.fixture(scope="module")
def talos() -> Iterator[tuple[World, RobotObject]]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with World() as world:
            world.bodies.add_floor()
            yield world, world.add_robot(description_from(str(TALOS)), Pose((0.0, 0.0, 1.0)))


def _feet(robot: RobotObject) -> list[str]:
    desc = robot.description
    return [leg.foot for leg in legs(desc.model, [a.end_effector_link for a in desc.arms.values()])]


@pytest.mark.parametrize("depth", [0.15, 0.25])
def test_talos_crouches_its_root_straight_down_with_its_soles_where_they_stood(
    talos: tuple[World, RobotObject], depth: float
) -> None:
    world, robot = talos
    client, body = world.physics.client(), world.object(robot.name).body_id
    feet = _feet(robot)
    assert sorted(feet) == ["left_sole_link", "right_sole_link"]
    standing = world.joint_states(robot.name)
    start = world.pose(robot.name)
    before = {f: link_frame(body, client, f) for f in feet}
    root = np.asarray(pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0])
    values = crouched(robot.description.model, feet, standing, depth)
    try:
        down = Pose((start.position[0], start.position[1], start.position[2] - depth))
        world.set_pose(robot.name, Pose(down.position, start.orientation))
        world.set_joint_states(robot.name, values)
        lowered = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0]
        assert np.allclose(np.asarray(lowered) - root, (0.0, 0.0, -depth), atol=1e-9)
        for foot, (at, turned) in before.items():
            now, now_turned = link_frame(body, client, foot)
            assert np.linalg.norm(now - at) < 1e-4  # [m]: the sole did not slide or lift
            assert np.abs(now_turned - turned).max() < 1e-4  # nor tilt
        for i in range(pybullet.getNumJoints(body, physicsClientId=client)):
            info = pybullet.getJointInfo(body, i, physicsClientId=client)
            if info[1].decode() in values:  # every leg joint within PyBullet's limits
                value = pybullet.getJointState(body, i, physicsClientId=client)[0]
                assert abs(value - values[info[1].decode()]) < 1e-9
                assert info[8] - 1e-9 <= value <= info[9] + 1e-9
        assert values["leg_left_4_joint"] > 0.5 and values["leg_right_4_joint"] > 0.5
    finally:
        world.set_pose(robot.name, start)
        world.set_joint_states(robot.name, standing)


def test_talos_crouch_is_a_continuous_way_down(talos: tuple[World, RobotObject]) -> None:
    """Down 0-30 cm a centimetre at a time, every leg joint turns one way only and each
    centimetre turns them less than the one before (the knee straight at first: 0.34 rad,
    then 0.14, ..., 0.035): one branch, no jump, a way a timed trajectory can follow."""
    world, robot = talos
    standing = world.joint_states(robot.name)
    model, feet = robot.description.model, _feet(robot)
    ways = [crouched(model, feet, standing, cm / 100) for cm in range(31)]
    steps = [max(abs(a[j] - b[j]) for j in a) for a, b in zip(ways, ways[1:], strict=False)]
    assert all(later <= earlier + 1e-3 for earlier, later in zip(steps, steps[1:], strict=False))
    for joint in ways[0]:
        turns = np.diff([way[joint] for way in ways])
        assert (turns >= -1e-6).all() or (turns <= 1e-6).all(), joint


def test_too_deep_a_crouch_names_the_foot_and_asks_less(
    talos: tuple[World, RobotObject],
) -> None:
    world, robot = talos
    with pytest.raises(CrouchUnreachable, match="ask a smaller depth") as raised:
        crouched(robot.description.model, _feet(robot), world.joint_states(robot.name), 1.5)
    assert raised.value.foot in ("left_sole_link", "right_sole_link")
