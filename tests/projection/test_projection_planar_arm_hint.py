"""A planar arm that misses with its base still is told to reach with its base (base_in_ik).

Stretch's arm moves in its base's y-z plane: a target ahead of the base (+x) is off it. The
failure used to advise "turn or move the base"; the next step is to let IK move it.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from pathlib import Path

import pytest

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.projection import ProjectedRobot
from robocram.projection.arm import move_tcp
from robocram.robots import LoadedDescription, load_description
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

STRETCH = Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py"
DOWN = quat.from_euler(0.0, math.pi / 2, 0.0)
OFF_THE_PLANE = Pose((0.35, -0.45, 0.6), DOWN)  # 35 cm ahead of the arm's plane


def _stretch(base_in_ik: bool | None) -> LoadedDescription:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        desc = load_description(str(STRETCH))
    arm = dataclasses.replace(desc.arms["arm"], base_in_ik=base_in_ik)
    return dataclasses.replace(desc, arms={"arm": arm})


def test_a_planar_arm_without_its_base_is_told_to_use_it() -> None:
    with World() as world:
        world.bodies.add_floor()
        robot = ProjectedRobot.of(world, world.add_robot(_stretch(False)).name)
        with pytest.raises(ManipulationPoseUnreachable) as failure:
            move_tcp(robot, "arm", OFF_THE_PLANE, collision_mode="allow_all")
    text = str(failure.value)
    assert "thin slice" in text and "base_in_ik=True" in text
    assert "turn or move" not in text
    assert "move the base at least" not in text


def test_with_its_base_the_planar_arm_reaches_it() -> None:
    with World() as world:
        world.bodies.add_floor()
        robot = ProjectedRobot.of(world, world.add_robot(_stretch(None)).name)
        reached = move_tcp(robot, "arm", OFF_THE_PLANE, collision_mode="allow_all")
        assert reached.distance_to(OFF_THE_PLANE) < 0.01
        assert world.pose(robot.name).position[0] > 0.1  # the base drove ahead
