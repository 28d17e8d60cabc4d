"""The mug's handle faces the shoulder of an arm whose hand takes the handle only.

Baxter's hand opens 42 mm, the mug's body is 88 mm wide: it takes the handle only, and with
the handle to the left its right arm put its elbow into the torso (zoo33). PyBullet judges:
the mug's box reaches past its axis towards the shoulder (the handle) and not to the left;
the PR2's hand, wide enough for the body, keeps the handle to the left.
"""

from __future__ import annotations

import math
from pathlib import Path

import pybullet

from robocram.robot_check import description_from
from robocram.scenes import tabletop_scene
from robocram.world import World

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"
HANDLE = 0.02  # [m] the handle sticks out of the body by more than this


def _reach(world: World, name: str, side: tuple[float, float]) -> float:
    """How far [m] the mug's box reaches from its axis along the map's ``side``, raw."""
    client, body = world.physics.client(), world.object(name).body_id
    low, high = pybullet.getAABB(body, physicsClientId=client)
    axis, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    return max(
        (high[i] - axis[i]) * side[i] if side[i] > 0 else (low[i] - axis[i]) * side[i]
        for i in (0, 1)
        if side[i] != 0.0
    )


def test_a_hand_taking_the_handle_only_finds_it_facing_its_shoulder() -> None:
    scene = tabletop_scene(description_from(str(EXAMPLES / "baxter.py")))
    world = scene.world
    try:
        client = world.physics.client()
        robot = world.object(scene.robot).body_id
        mount = next(
            i
            for i in range(pybullet.getNumJoints(robot, physicsClientId=client))
            if pybullet.getJointInfo(robot, i, physicsClientId=client)[12] == b"right_arm_mount"
        )
        shoulder = pybullet.getLinkState(robot, mount, physicsClientId=client)[4]
        body = world.object("mug-1").body_id
        axis, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
        toward = (shoulder[0] - axis[0], shoulder[1] - axis[1])
        length = math.hypot(*toward)
        low, high = pybullet.getAABB(body, physicsClientId=client)
        radius = min(high[0] - axis[0], axis[1] - low[1], high[1] - axis[1])  # the body
        # the box reaches past the body towards the shoulder's side: -x, the robot's side
        assert toward[0] / length < -0.9
        assert _reach(world, "mug-1", (-1.0, 0.0)) > radius + HANDLE
        assert _reach(world, "mug-1", (0.0, 1.0)) < radius + HANDLE  # not to the left
    finally:
        world.close()


def test_a_hand_wide_enough_for_the_body_keeps_the_handle_to_the_left() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    try:
        body = world.object("mug-1").body_id
        client = world.physics.client()
        axis, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
        low, _ = pybullet.getAABB(body, physicsClientId=client)
        radius = axis[0] - low[0]
        assert _reach(world, "mug-1", (0.0, 1.0)) > radius + HANDLE
        assert _reach(world, "mug-1", (-1.0, 0.0)) < radius + HANDLE
    finally:
        world.close()
