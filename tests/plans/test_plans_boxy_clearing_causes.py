"""What stopped Boxy's clearing in session 24, on its smallest case, judged by raw PyBullet
(the milk's bounds against the fridge's, what holds it, the door's joint).
"""

from __future__ import annotations

import pybullet
import pytest

from robocram.plans.clearing_table import clear_table
from robocram.plans.table_arrangement import STANDARD_SETTING, spots, table_with_seats
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import FRIDGE_UPPER_SHELF, breakfast_scene
from robocram.tf import Pose

TABLE_TOP = 0.75  # [m] the kitchen table's top


def test_boxy_puts_the_milk_from_its_table_spot_back_under_the_fridge_shelf() -> None:
    """Taken from above on the table, no hand put the carton under the shelf; it is put
    down again and taken from the side."""
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            table = table_with_seats(None)
            spot = next(s for s in spots(table, 2, STANDARD_SETTING, ("milk",)) if s.type == "milk")
            x, y, _ = spot.pose.position
            low, _ = world.aabb("milk-1")
            lift = world.pose("milk-1").position[2] - low[2]
            world.set_pose("milk-1", Pose((x, y, TABLE_TOP + lift + 0.001), spot.pose.orientation))
            done = clear_table(objects=["milk-1"])
        assert set(done.returned) == {"milk-1"}
        kitchen = world.object("kitchen")
        fridge_low, fridge_high = pybullet.getAABB(
            kitchen.body_id, kitchen.link_index["fridge_body"], cid
        )
        low, high = pybullet.getAABB(world.object("milk-1").body_id, physicsClientId=cid)
        for axis in (0, 1):  # inside the fridge's walls
            assert fridge_low[axis] < low[axis] and high[axis] < fridge_high[axis]
        assert high[2] < fridge_low[2] + FRIDGE_UPPER_SHELF  # under the upper shelf
        assert low[2] > TABLE_TOP + 0.2  # on the shelf below it, not on the floor
        held = pybullet.getContactPoints(
            world.object(scene.robot).body_id, world.object("milk-1").body_id, physicsClientId=cid
        )
        assert not held  # let go
        door = pybullet.getJointState(
            kitchen.body_id, kitchen.joint_index["fridge_door_joint"], cid
        )
        assert door[0] == pytest.approx(0.0, abs=0.01)  # closed again
    finally:
        world.close()
