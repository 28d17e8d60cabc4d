"""``facing`` turns the base in place towards a point; ``carrying`` tucks in what is held.

Judged by raw PyBullet: the base's heading and place, the arm's joints, where the mug is.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.plans.errors import PlanSetupError
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene


@pytest.fixture(scope="module")
def pr2() -> Iterator[TabletopScene]:
    scene = tabletop_scene("pr2")
    yield scene
    scene.world.close()


def _base(scene: TabletopScene) -> tuple[float, float, float]:
    """The base's (x, y, yaw) [m, m, rad] as PyBullet has it."""
    world = scene.world
    position, orientation = pybullet.getBasePositionAndOrientation(
        world.object(scene.robot).body_id, physicsClientId=world.physics.client()
    )
    yaw = pybullet.getEulerFromQuaternion(orientation)[2]
    return position[0], position[1], yaw


def test_facing_turns_the_base_where_it_stands(pr2: TabletopScene) -> None:
    x, y, yaw = _base(pr2)
    left = (x - 2.0 * math.sin(yaw), y + 2.0 * math.cos(yaw), 0.8)  # 2 m to its left
    with simulated_robot(pr2.world, pr2.robot):
        perform(an.action(type="facing", target=left))
    nx, ny, nyaw = _base(pr2)
    assert math.hypot(nx - x, ny - y) == pytest.approx(0.0, abs=0.01)
    assert math.remainder(nyaw - yaw - math.pi / 2, 2 * math.pi) == pytest.approx(0.0, abs=0.02)
    with simulated_robot(pr2.world, pr2.robot):
        perform(
            an.action(type="facing", target=(x + 2.0 * math.cos(yaw), y + 2.0 * math.sin(yaw), 0.8))
        )


def test_carrying_tucks_the_held_mug_in_and_needs_something_held(pr2: TabletopScene) -> None:
    world = pr2.world
    with simulated_robot(world, pr2.robot):
        with pytest.raises(PlanSetupError, match="holds nothing"):
            perform(an.action(type="carrying"))
        perform(an.action(type="looking", target=pr2.look_target))
        mug = perform(an.action(type="detecting", object=an.object(type="mug")))
        held = perform(an.action(type="picking-up", object=mug))
        carried = perform(an.action(type="carrying"))
    assert carried.held == {held.arm: "mug-1"}
    desc = world.robot(pr2.robot).description
    body = world.object(pr2.robot).body_id
    names = {
        pybullet.getJointInfo(body, i, physicsClientId=world.physics.client())[1].decode(): i
        for i in range(pybullet.getNumJoints(body, physicsClientId=world.physics.client()))
    }
    for joint, value in desc.arms[held.arm].parking.items():
        now = pybullet.getJointState(body, names[joint], physicsClientId=world.physics.client())[0]
        off = math.remainder(now - value, 2 * math.pi)
        assert off == pytest.approx(0.0, abs=0.01), joint
    mug, _ = pybullet.getBasePositionAndOrientation(
        world.object("mug-1").body_id, physicsClientId=world.physics.client()
    )
    tool = world.link_pose(pr2.robot, desc.arms[held.arm].tool_frame).position
    assert math.dist(mug, tool) < 0.15  # still in the hand, tucked in with it
