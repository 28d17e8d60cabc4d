"""A neck arm that is the manipulator looks as an arm's camera does: the Donbot's.

The Donbot's camera rides its UR5's wrist; the draft described the UR5 twice, as its
arm and as a neck arm carrying the camera (since zoo7, once: the arm carries the camera,
``test_robots_draft_wrist_camera.py``). Looked as a neck, it turned the camera where
the arm was parked, beside its base, whose body hid the tabletop mug: the pick-up failed
at detecting. It looks from a viewing pose its body does not hide now. Judged in a raw
PyBullet: rays from the camera to the mug's middle meet the mug first.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet

from robocram.projection.neck import look_at
from robocram.projection.projected_robot import ProjectedRobot
from robocram.robots.looking_means import looking_means
from robocram.scenes import tabletop_scene
from tests.drafts import drafted_module

DONBOT = Path(__file__).resolve().parents[1] / "data" / "zoo" / "iai_donbot" / "iai_donbot.urdf"


def test_the_donbots_wrist_camera_looks_at_the_mug_past_its_own_base(tmp_path: Path) -> None:
    module = tmp_path / "iai_donbot.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(DONBOT, module)
        scene = tabletop_scene(str(module))
    world = scene.world
    try:
        robot = ProjectedRobot.of(world, scene.robot)
        means = looking_means(robot.description)
        assert means is not None and (means.kind, means.arm) == ("arm", "arm")
        look_at(robot, scene.look_target.position)
        client = world.physics.client()
        camera = robot.description.cameras[0].frame
        eye = world.link_pose(scene.robot, camera).position
        mug = next(o for o in world.objects() if o.name.startswith("mug"))
        low, high = world.aabb(mug.name)
        middle = tuple((a + b) / 2 for a, b in zip(low, high, strict=True))
        hit = pybullet.rayTest(eye, middle, physicsClientId=client)[0]
        assert hit[0] == mug.body_id, (hit, mug.body_id)
    finally:
        world.close()
