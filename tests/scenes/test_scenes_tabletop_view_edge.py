"""A camera that cannot aim at a table under the hand sees the mug in its view's lower part.

TALOS (examples/robots/talos.py): its head tilts 45 degrees down at most, so the scene
raised its table to 1.325 m for the optical axis to meet the mug, and both arms missed
the grasps from above by 3-6 cm at their joint limits, the wrist over the shoulder. The
table now stays at its usual height, the camera looks farther out and the mug lies nearer,
in the lower part of the view. Judged by PyBullet: the table's top (its box's bounds), the
shoulder and the camera (raw link states), and the mug lifted off the table.
"""

from __future__ import annotations

import math
from pathlib import Path

import pybullet

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"
LIFTED = 0.03  # [m] the mug rises at least this much
HAND_AND_GRASP = 0.215 + 0.05  # [m] TALOS's wrist over its tool frame, a top grasp's height
TILT_DOWN = math.radians(45.0)  # TALOS's head_1_joint: 0.785 rad down at most


def _link_position(body: int, client: int, link: str) -> tuple[float, float, float]:
    for index in range(pybullet.getNumJoints(body, physicsClientId=client)):
        if pybullet.getJointInfo(body, index, physicsClientId=client)[12].decode() == link:
            state = pybullet.getLinkState(body, index, physicsClientId=client)
            return (state[4][0], state[4][1], state[4][2])
    raise AssertionError(f"no link {link}")


def test_talos_sees_its_mug_below_its_view_axis_and_lifts_it() -> None:
    scene = tabletop_scene(str(TALOS))
    world = scene.world
    try:
        client, body = world.physics.client(), world.object(scene.robot).body_id
        table = world.object("table").body_id
        top = pybullet.getAABB(table, physicsClientId=client)[1][2]
        shoulder = _link_position(body, client, "arm_right_1_link")
        camera = _link_position(body, client, "rgbd_optical_frame")
        mug_id = world.object("mug-1").body_id
        start, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        assert top + HAND_AND_GRASP < shoulder[2]  # the wrist below the shoulder: 1.325 m before
        assert abs(start[2] - top) < 0.01
        look = scene.look_target.position
        down_to_look = math.atan2(camera[2] - look[2], look[0] - camera[0])
        down_to_mug = math.atan2(camera[2] - start[2], start[0] - camera[0])
        assert down_to_look <= TILT_DOWN + 0.02  # the axis can be aimed there
        assert down_to_mug > TILT_DOWN  # the mug lies below what the axis reaches
        with simulated_robot(world, scene.robot):
            pick_up(scene.look_target)
        end, _ = pybullet.getBasePositionAndOrientation(mug_id, physicsClientId=client)
        assert end[2] > start[2] + LIFTED
    finally:
        world.close()
