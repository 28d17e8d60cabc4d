"""A palm hand with no room for a fist finishes, with its fingers' hold, a closing its open
hand took only part of the way.

Armar6 opened the bowl's drawer 0.4 m holding the bar out along its fingers (its fist has
no room round it on the palm); closing it, its open hand pushed it to 0.038 m, and no hold
took it further, as the fingers' hold was tried only where nothing had moved the drawer
(issue 37, zoo29). The drawer's joint is read back from PyBullet.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.projection import ProjectedRobot, bar_opening
from robocram.projection.articulation import move_part
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from tests.drafts import drafted_module
from tests.projection.drawer_stand import DRAWER

ARMAR6 = Path(__file__).resolve().parents[1] / "data" / "zoo" / "armar6" / "armar6.urdf"
JOINT = f"{DRAWER}_joint"
STAND = (-1.31, 0.96)  # where the zoo's Armar6 opened it, facing the drawer (+y)


def test_armar6_closes_with_its_fingers_hold_what_its_open_hand_pushed_part_way(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    module = tmp_path / "armar6.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(ARMAR6, module)
        scene = kitchen_scene(str(module))
    world = scene.world
    try:
        robot = ProjectedRobot.of(world, scene.robot)
        for spec in robot.description.arms.values():
            world.set_joint_states(scene.robot, dict(spec.parking))
        z = robot.base_pose().position[2]
        world.set_pose(scene.robot, Pose((*STAND, z), quat.from_euler(0.0, 0.0, 1.5708)))
        world.set_joint_states("kitchen", {JOINT: 0.4})
        calls: list[str] = []
        found = bar_opening.fingers_hold

        def spy(*args: str, **kwargs: str) -> object:
            calls.append(args[1])
            return found(*args, **kwargs)  # type: ignore[arg-type]

        monkeypatch.setattr(bar_opening, "fingers_hold", spy)
        result = move_part(robot, "left", "kitchen", JOINT, f"{DRAWER}_handle", 0.0)
        kitchen = world.object("kitchen")
        value = pybullet.getJointState(
            kitchen.body_id, kitchen.joint_index[JOINT], physicsClientId=world.physics.client()
        )[0]
        assert value == pytest.approx(0.0, abs=1e-6)  # shut
        assert result.reached == pytest.approx(0.0, abs=1e-9)
        assert calls == ["left"]  # the fingers' hold, after the open hand's moved it part way
    finally:
        world.close()
