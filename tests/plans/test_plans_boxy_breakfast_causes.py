"""What stopped Boxy's breakfast in session 23, each on its smallest case, judged by raw
PyBullet (the bowl's bounds, the fingers' contacts).
"""

from __future__ import annotations

import math

import pybullet
import pytest

from robocram.designators import an
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.bringing import Visit, find, usual_place
from robocram.plans.fetch import fetch
from robocram.plans.pick_object import Held, pick_up_object
from robocram.plans.table_arrangement import STANDARD_SETTING, spots, table_with_seats
from robocram.plans.table_trips import TableSetting, deliver_to_spot
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import World

BOWLS = "drawer_unit_drawer_3"
TABLE_TOP = 0.75  # [m] the kitchen table's top
# facing the opened bowls' drawer, the base's middle in line with bowl-1's rim nearer
# the drawer's middle (the bowl 0.75 m ahead, the rim 8 cm to its left)
BOXY_AT_RIM = Pose((-1.358, 1.01, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))


def _drawer_top(world: World) -> float:
    """[m] the top of the bowls' drawer, by PyBullet."""
    kitchen = world.object("kitchen")
    cid = world.physics.client()
    return float(pybullet.getAABB(kitchen.body_id, kitchen.link_index[BOWLS], cid)[1][2])


def _fetched_bowl(log: AttemptLog) -> Held:
    """bowl-1 found where it is kept (its drawer opened) and fetched, as setting does."""
    seen, opened = find(an.object(type="bowl", name="bowl-1"), Visit(usual_place("bowl")), log)
    return fetch(seen, log=log, opened=opened)


def test_boxys_hand_closed_round_a_bowls_thin_rim_holds_the_bowl() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_joint_states("kitchen", {f"{BOWLS}_joint": 0.4})
        for name in ("bowl-1", "bowl-2"):  # out with the drawer
            x, y, z = world.pose(name).position
            world.set_pose(name, Pose((x, y - 0.4, z)))
        world.set_pose(scene.robot, BOXY_AT_RIM)
        bowl = world.object("bowl-1").body_id
        with simulated_robot(world, scene.robot):
            at = world.pose("bowl-1")
            seen = an.object(
                type="bowl", name="bowl-1", pose=PoseStamped("map", at.position, at.orientation)
            )
            # its fingers stop 6.5 mm apart, round a 6 mm wall the rim grasp puts 1 mm off
            # their middle: one finger touches the wall, the other does not, fully closed
            held = pick_up_object(seen, arm="left", out_of=("kitchen", BOWLS))
        assert held.grasp == "rim"
        low, _ = pybullet.getAABB(bowl, physicsClientId=cid)
        assert low[2] > _drawer_top(world)  # lifted out of the drawer with the hand
        robot = world.object(scene.robot)
        fingers = {
            robot.link_index[f"left_gripper_finger_{side}_link"] for side in ("left", "right")
        }
        near = {
            p[3] for p in pybullet.getClosestPoints(robot.body_id, bowl, 0.005, physicsClientId=cid)
        }
        assert fingers <= near  # both fingers at the wall, within the hand's 5 mm bound
    finally:
        world.close()


def test_boxy_takes_the_bowl_beside_the_drawers_wall_facing_its_far_rim() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        bowl = world.object("bowl-1").body_id
        with simulated_robot(world, scene.robot):
            held = _fetched_bowl(AttemptLog())
        assert held.object_name == "bowl-1"
        low, _ = pybullet.getAABB(bowl, physicsClientId=cid)
        assert low[2] > _drawer_top(world)  # out of the drawer
        x, y, _ = pybullet.getBasePositionAndOrientation(
            world.object(scene.robot).body_id, physicsClientId=cid
        )[0]
        bx, by, _ = pybullet.getBasePositionAndOrientation(bowl, physicsClientId=cid)[0]
        # the base's middle in line with the bowl's rim nearer the drawer's middle, not
        # with the bowl's (the arm lifts a rim in front of the base's middle only)
        assert x == pytest.approx(bx - 0.078, abs=0.01)
        assert 0.7 < by - y < 0.9
    finally:
        world.close()


def test_boxy_puts_the_bowl_it_holds_before_its_chest_on_the_table_from_a_reach_stand() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        bowl = world.object("bowl-1").body_id
        with simulated_robot(world, scene.robot):
            done = TableSetting(table_with_seats(None))
            bowls = [s for s in spots(done.table, 2, STANDARD_SETTING, ()) if s.type == "bowl"]
            spot = bowls[1]  # the far setting's (the near one takes it held so)
            held = _fetched_bowl(done.log)
            # carried before its chest, every stand holding it so over the spot put the
            # other, parked hand into the table; a stand the arm reaches the spot from does
            deliver_to_spot(held, spot, done)
        low, _ = pybullet.getAABB(bowl, physicsClientId=cid)
        assert low[2] == pytest.approx(TABLE_TOP, abs=0.01)  # on the table
        x, y, _ = pybullet.getBasePositionAndOrientation(bowl, cid)[0]
        assert math.hypot(x - spot.pose.position[0], y - spot.pose.position[1]) < 0.15
        assert not pybullet.getClosestPoints(
            world.object(scene.robot).body_id, bowl, 0.005, physicsClientId=cid
        )  # let go
    finally:
        world.close()
