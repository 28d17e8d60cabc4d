"""A tool action whose path stops short fails typed, never with a quiet partial result.

The HSR holds its tools in the same grips as the PR2 (``tool_setup.py`` reads each hand's
axes from its kinematics) and follows tool paths with base and arm together; a thin post
stands where each path goes, so each stops short, from every stand tried. Judged by raw
PyBullet: the spoon and the cup stay in the hand, the cup upright (the tilt's reached
part is undone), no slice is made; the failure names the post where it stopped there.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.plans.tool_failures import ToolPathIncomplete
from robocram.projection import simulated_robot
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose

sys.path.insert(0, str(Path(__file__).resolve().parent))
from tool_setup import ToolScene, tool_scene  # noqa: E402

UPRIGHT = 0.05  # [rad] the cup's axis within this of the vertical


def _tilt(scene: ToolScene, name: str) -> float:
    client = scene.world.physics.client()
    body = scene.world.object(name).body_id
    _, orientation = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    up = pybullet.getMatrixFromQuaternion(orientation)[8]
    return math.acos(max(-1.0, min(1.0, up)))


def _held(scene: ToolScene, name: str) -> bool:
    """Whether the hand's links touch ``name`` (raw contact query, 2 mm)."""
    client = scene.world.physics.client()
    robot = scene.world.robot(scene.robot).body_id
    body = scene.world.object(name).body_id
    return bool(pybullet.getClosestPoints(robot, body, 0.002, physicsClientId=client))


def test_a_stir_the_arm_cannot_follow_fails_naming_how_far_it_got() -> None:
    scene = tool_scene("hsrb", "spoon")
    x, y, h = scene.spot
    add_tool_object(scene.world, "bowl-1", "bowl", Pose((x, y, h)))
    scene.world.add_box("post", (0.01, 0.01, 0.3), (x + 0.06, y, h + 0.15))  # in the spiral
    with (
        simulated_robot(scene.world, scene.robot),
        pytest.raises(ToolPathIncomplete) as failure,
    ):
        perform(an.action(type="mixing", container="bowl-1", tool="spoon-1"))
    assert failure.value.action == "mixing"
    assert failure.value.fraction is not None and failure.value.fraction < 0.9
    assert failure.value.needed == pytest.approx(0.9)
    assert "post" in str(failure.value.stopped_by)
    assert _held(scene, "spoon-1")


def test_a_pour_that_cannot_tilt_fails_and_leaves_the_cup_upright() -> None:
    scene = tool_scene("hsrb", "cup")
    x, y, h = scene.spot
    add_tool_object(scene.world, "bowl-1", "bowl", Pose((x + 0.05, y - 0.1, h)))
    scene.world.add_box("post", (0.01, 0.01, 0.3), (x + 0.05, y - 0.1, h + 0.3))  # over it
    with (
        simulated_robot(scene.world, scene.robot),
        pytest.raises(ToolPathIncomplete) as failure,
    ):
        perform(an.action(type="pouring", source="cup-1", target="bowl-1", amount=60))
    assert failure.value.action == "pouring" and failure.value.fraction is not None
    assert failure.value.fraction < 0.9
    assert _tilt(scene, "cup-1") < UPRIGHT
    assert _held(scene, "cup-1")


def test_a_cut_that_makes_no_slice_fails() -> None:
    scene = tool_scene("hsrb", "knife")
    x, y, h = scene.spot
    add_tool_object(scene.world, "bread-1", "bread", Pose((x, y, h + 0.04)))
    scene.world.add_box("post", (0.3, 0.015, 0.015), (x, y + 0.05, h + 0.12))  # on the saw line
    with (
        simulated_robot(scene.world, scene.robot),
        pytest.raises(ToolPathIncomplete) as failure,
    ):
        perform(an.action(type="cutting", object="bread-1", tool="knife-1", slices=4))
    assert failure.value.action == "cutting" and failure.value.needed == pytest.approx(0.9)
    assert failure.value.fraction is not None and failure.value.fraction < 0.9
    assert "post" in str(failure.value.stopped_by)
    assert not scene.world.objects("bread_slice")
    assert "bread-1" in {o.name for o in scene.world.objects()}
