"""The drafted Stretch beside the opened fridge, its arm across the shelf at the milk:
household seed 0's second stand for the milk (``benchmarks/activity_bench.py``), shared by
the tests of a pick's way out and of its stand on the approach line."""

from __future__ import annotations

from pathlib import Path

from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.scenes.environment_scene import EnvironmentScene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
DOOR_OPEN = {"fridge_door_joint": 1.4}  # [rad] as the household's opening left it
STAND = Pose((1.326, 1.843, 0.0), quat.from_euler(0.0, 0.0, -1.720))  # beside the fridge
MILK_Y = 2.0579  # [m] seed 0's milk, 8 mm deeper than its spot (map)
LOOKING = {"joint_head_pan": -1.805, "joint_head_tilt": -0.334}  # at the milk, as it found it


def stretch_at_the_milk() -> EnvironmentScene:
    """The breakfast scene with the Stretch standing at the milk, as household 0 left it."""
    scene = breakfast_scene(STRETCH)
    world = scene.world
    world.set_joint_states("kitchen", DOOR_OPEN)
    milk_at = world.pose("milk-1")
    x, _, z = milk_at.position
    world.set_pose("milk-1", Pose((x, MILK_Y, z), milk_at.orientation))
    world.set_pose(scene.robot, STAND)
    world.set_joint_states(scene.robot, LOOKING)
    return scene
