"""The knife and the sponge are picked up from a table, resting on it.

``add_tool_object(..., on=height)`` puts a thing's bottom on the surface: the knife's frame
is its handle's middle and the sponge's its middle, so put at the table's height they lay
half in the table, and every grasp had the fingers in it (the "known limit" this
replaces). Judged by raw PyBullet: resting, the thing's bottom is on the table top to a
millimetre and nothing of it is in the table; picked up, its bottom is 2 cm over the table
at least and a finger of the robot touches it.
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose

LIFTED = 0.02  # [m] the picked thing's bottom at least this far over the table
GRIPPED = 0.005  # [m] a finger at most this far from it


@pytest.mark.parametrize("robot", ["pr2", "hsrb"])
@pytest.mark.parametrize("tool", ["knife", "sponge"])
def test_a_tool_resting_on_the_table_is_picked_up(robot: str, tool: str) -> None:
    scene = tabletop_scene(robot)
    world = scene.world
    world.remove("mug-1")
    world.remove("bottle-1")
    x, y, _ = scene.look_target.pose.position
    cid = world.physics.client()
    table = world.object("table").body_id
    top = pybullet.getAABB(table, -1, physicsClientId=cid)[1][2]
    name = f"{tool}-1"
    body = add_tool_object(world, name, tool, Pose((x, y, 0.0)), on=top).body_id
    bottom = pybullet.getAABB(body, -1, physicsClientId=cid)[0][2]
    assert bottom == pytest.approx(top, abs=0.001)
    into = pybullet.getClosestPoints(body, table, 0.0, physicsClientId=cid)
    assert min((p[8] for p in into), default=0.0) > -0.0005
    with simulated_robot(world, scene.robot):
        perform(an.action(type="picking-up", object=an.object(name=name)))
    assert pybullet.getAABB(body, -1, physicsClientId=cid)[0][2] > top + LIFTED
    robot_body = world.object(scene.robot)
    fingers = {
        robot_body.link_index[link]
        for arm in world.robot(scene.robot).description.arms.values()
        for link in arm.gripper_links
    }
    near = pybullet.getClosestPoints(robot_body.body_id, body, GRIPPED, physicsClientId=cid)
    assert any(p[3] in fingers for p in near)
