"""The milk carton on the set table and back in the fridge, as raw PyBullet has them: shared
by the clearing tests of the PR2 and Boxy."""

from __future__ import annotations

import pybullet
import pytest

from robocram.plans.table_arrangement import STANDARD_SETTING, Table, spots, table_with_seats
from robocram.scenes.breakfast_scene import FRIDGE_UPPER_SHELF
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

TABLE_TOP = 0.75  # [m] the kitchen table's top


def milk_on_its_spot(world: World, turned: float = 0.0) -> tuple[Table, Pose]:
    """Stand the milk on the set table's shared spot, turned ``turned`` [rad] from it; the
    table and the pose it stands at (run inside the robot's projection: the KB's table)."""
    table = table_with_seats(None)
    spot = next(s for s in spots(table, 2, STANDARD_SETTING, ("milk",)) if s.type == "milk")
    x, y, _ = spot.pose.position
    low, _ = world.aabb("milk-1")
    lift = world.pose("milk-1").position[2] - low[2]
    orientation = quat.multiply(spot.pose.orientation, quat.from_euler(0.0, 0.0, turned))
    pose = Pose((x, y, TABLE_TOP + lift + 0.001), orientation)
    world.set_pose("milk-1", pose)
    return table, pose


def assert_milk_back_in_the_fridge(world: World, robot: str) -> None:
    """The carton stands inside the fridge's walls on the shelf under the upper one, no
    hand of ``robot`` touches it, and the door is closed again."""
    cid = world.physics.client()
    kitchen = world.object("kitchen")
    fridge_low, fridge_high = pybullet.getAABB(
        kitchen.body_id, kitchen.link_index["fridge_body"], cid
    )
    milk = world.object("milk-1").body_id
    low, high = pybullet.getAABB(milk, physicsClientId=cid)
    for axis in (0, 1):  # inside the fridge's walls
        assert fridge_low[axis] < low[axis] and high[axis] < fridge_high[axis]
    assert high[2] < fridge_low[2] + FRIDGE_UPPER_SHELF  # under the upper shelf
    assert low[2] > TABLE_TOP + 0.2  # on the shelf below it, not on the floor
    body = world.object(robot).body_id
    assert not pybullet.getContactPoints(body, milk, physicsClientId=cid)  # let go
    door = pybullet.getJointState(kitchen.body_id, kitchen.joint_index["fridge_door_joint"], cid)
    assert door[0] == pytest.approx(0.0, abs=0.01)  # closed again
