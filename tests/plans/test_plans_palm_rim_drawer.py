"""The TIAGo's palm hand takes the bowl out of the kitchen's open drawer by its rim.

Flat over the rim, the Hey5's wrist met the bowl and its forearm the drawer's front from
every stand (issue 37); its rim grasps tilted about the held wall reach in from above.
The drawer is opened by setting its joint, the bowl moved with it, so only the pick-up
runs. The bowl's lift out is judged on PyBullet's own boxes.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.plans import install_actions, pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from tests.bullet_links import link_indices

TIAGO = "examples/robots/tiago.py"
DRAWER = "drawer_unit_drawer_3"
OPEN = 0.4  # [m] the drawer pulled out along the map's -y, as opening it does
STAND_Y = 1.01  # [m] where fetching put the TIAGo, facing the drawer (north)


@pytest.fixture()
def scene() -> Iterator[KitchenScene]:
    made = kitchen_scene(TIAGO)
    install_actions(made.world.kb)
    yield made
    made.world.close()


def test_the_tiago_lifts_the_bowl_out_of_the_open_drawer_by_its_rim(scene: KitchenScene) -> None:
    world = scene.world
    world.set_joint_states("kitchen", {f"{DRAWER}_joint": OPEN})
    x, y, z = world.pose("bowl-1").position
    world.set_pose("bowl-1", Pose((x, y - OPEN, z)))
    world.set_pose(scene.robot, Pose((x, STAND_Y, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2)))
    with simulated_robot(world, scene.robot):
        held = pick_up_object("bowl-1", out_of=("kitchen", DRAWER))
    assert held.grasp == "rim"
    assert world.bodies.attached_to("bowl-1") is not None
    client = world.physics.client()
    kitchen = world.object("kitchen").body_id
    drawer = pybullet.getAABB(
        kitchen, link_indices(kitchen, client)[DRAWER], physicsClientId=client
    )
    bowl = pybullet.getAABB(world.object("bowl-1").body_id, physicsClientId=client)
    assert bowl[0][2] > drawer[1][2]  # its bottom over the drawer's sides: lifted out
    middle = ((bowl[0][0] + bowl[1][0]) / 2, (bowl[0][1] + bowl[1][1]) / 2)
    assert math.dist(middle, (x, y - OPEN)) < 0.03  # lifted straight up, not dragged
