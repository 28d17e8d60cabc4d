"""What stopped the breakfast of the drafted Fetch, Boxy and the drafted Stretch, each on
its smallest case, judged by raw PyBullet (joint values, contacts, positions).
"""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pybullet
import pytest

import robocram.plans.two_armed_trips as trips
from robocram.designators import a, an
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import park_arms
from robocram.plans.bringing import Visit, find, find_in_place, usual_place
from robocram.plans.container_access import close_again, open_from_front
from robocram.plans.deliver import deliver
from robocram.plans.fetch import fetch
from robocram.plans.table_arrangement import STANDARD_SETTING, spots, table_with_seats
from robocram.plans.table_trips import TableSetting
from robocram.plans.torso_up import navigate_torso_up
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

fetch_plan = importlib.import_module("robocram.plans.fetch")  # the package names its function
gripper = importlib.import_module("robocram.projection.gripper")
FETCH = str(Path(__file__).resolve().parents[1] / "data" / "fetch" / "fetch.py")
STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
BOWLS = "drawer_unit_drawer_3"
TABLE_TOP = 0.75  # [m] the kitchen table's top
# the Fetch as it stood after putting the second bowl into its drawer when clearing: the
# base turned to the drawer's corner, the open hand 10 cm over the bowl it let go
FETCH_AFTER_PUTTING = Pose((-1.01825, 1.24766, 0.041), (0.0, 0.0, 0.92232, 0.38644))
FETCH_ARM_IN_DRAWER = {
    "torso_lift_joint": 0.17755,
    "head_pan_joint": -0.02673,
    "head_tilt_joint": 0.72137,
    "shoulder_pan_joint": 0.29157,
    "shoulder_lift_joint": -0.68386,
    "upperarm_roll_joint": 2.74001,
    "elbow_flex_joint": -1.35145,
    "forearm_roll_joint": -2.76771,
    "wrist_flex_joint": 0.97773,
    "wrist_roll_joint": -0.82251,
    "r_gripper_finger_joint": 0.05,
    "l_gripper_finger_joint": 0.05,
}
CUPS = "east_drawers_1_drawer_3"  # a household's cups drawer (activity_bench seeds 4 and 5)
# the Fetch as it stood after putting the second cup back into that drawer, opened 0.4 m:
# the base at the drawer's front corner, turned 41 degrees to it, the open hand in it
FETCH_BESIDE_CUPS = Pose((1.81380, 1.29116, 0.041), (0.0, 0.0, 0.35968, 0.93308))
FETCH_HAND_IN_CUPS = {
    "torso_lift_joint": 0.17745,
    "head_pan_joint": -0.03274,
    "head_tilt_joint": 0.81499,
    "shoulder_pan_joint": 0.53043,
    "shoulder_lift_joint": -0.62294,
    "upperarm_roll_joint": -7.31917,
    "elbow_flex_joint": 1.69038,
    "forearm_roll_joint": 4.06521,
    "wrist_flex_joint": -1.06972,
    "wrist_roll_joint": 6.15626,
    "r_gripper_finger_joint": 0.05,
    "l_gripper_finger_joint": 0.05,
}
FETCH_PARKED = {
    "shoulder_pan_joint": 0.105,
    "shoulder_lift_joint": 1.198,
    "upperarm_roll_joint": 1.458,
    "elbow_flex_joint": -2.155,
    "forearm_roll_joint": -2.039,
    "wrist_flex_joint": 1.604,
    "wrist_roll_joint": 0.162,
}


def test_the_fetch_parks_its_hand_out_of_an_open_drawer_it_stands_at() -> None:
    scene = breakfast_scene(FETCH)
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_joint_states("kitchen", {f"{BOWLS}_joint": 0.4})
        world.set_pose(scene.robot, FETCH_AFTER_PUTTING)
        world.set_joint_states(scene.robot, FETCH_ARM_IN_DRAWER)
        kitchen, robot = world.object("kitchen"), world.object(scene.robot)
        drawer = kitchen.link_index[BOWLS]
        world.set_joint_states(scene.robot, FETCH_PARKED)
        pybullet.performCollisionDetection(cid)
        # parked where it stands, the forearm would be in the drawer
        assert pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, linkIndexB=drawer, physicsClientId=cid
        )
        world.set_joint_states(scene.robot, FETCH_ARM_IN_DRAWER)
        with simulated_robot(world, scene.robot):
            park_arms()
        for joint, parked in FETCH_PARKED.items():
            value = pybullet.getJointState(robot.body_id, robot.joint_index[joint], cid)[0]
            off = math.remainder(value - parked, 2 * math.pi)  # the wrist rolls on and on
            assert off == pytest.approx(0.0, abs=0.01), joint
        opened = pybullet.getJointState(kitchen.body_id, kitchen.joint_index[f"{BOWLS}_joint"], cid)
        assert opened[0] == pytest.approx(0.4, abs=0.005)  # not pushed by the arm
        assert not pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid
        )
    finally:
        world.close()


def test_boxy_sees_the_milk_under_the_fridge_shelf_from_farther_back_and_takes_it() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        milk = world.object("milk-1").body_id
        low_before, _ = pybullet.getAABB(milk, physicsClientId=cid)
        with simulated_robot(world, scene.robot):
            found = find_in_place(an.object(type="milk"), Visit(usual_place("milk")), AttemptLog())
            assert found is not None
            seen, opened = found
            base, _ = pybullet.getBasePositionAndOrientation(
                world.object(scene.robot).body_id, physicsClientId=cid
            )
            x, y, _ = world.pose("milk-1").position
            stand = opened.stand.pose.position
            # its camera, 1.45 m and more over the floor, saw under the shelf from farther back
            farther = math.hypot(base[0] - x, base[1] - y)
            assert farther > math.hypot(stand[0] - x, stand[1] - y) + 0.1
            fetch(seen, opened=opened)
        low, _ = pybullet.getAABB(milk, physicsClientId=cid)
        assert low[2] > low_before[2] + 0.01  # lifted off the shelf
        hand = pybullet.getClosestPoints(
            world.object(scene.robot).body_id, milk, 0.005, physicsClientId=cid
        )
        assert hand  # in the hand, lifted with it
    finally:
        world.close()


def test_boxy_puts_a_spoon_its_parked_hand_holds_askew_down_flat() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            visit = Visit(usual_place("spoon"))
            seen, opened = find(an.object(type="spoon"), visit, AttemptLog())
            held = fetch(seen, opened=opened)
            park_arms()  # the spoon hangs askew
            name = held.object_name
            _, q = pybullet.getBasePositionAndOrientation(world.object(name).body_id, cid)
            up = quat.rotate(q, (0.0, 0.0, 1.0))
            assert up[2] < math.cos(math.radians(30.0))  # tilted more than 30 degrees
            spot = (-0.56, -1.15, TABLE_TOP)
            where = a.location(on=("kitchen", "table_top"), for_=name, at=spot, size=0.3)
            deliver(held, where, held.arm)
        body = world.object(name).body_id
        low, _ = pybullet.getAABB(body, physicsClientId=cid)
        assert low[2] == pytest.approx(TABLE_TOP, abs=0.01)  # on the table
        _, q = pybullet.getBasePositionAndOrientation(body, cid)
        assert quat.rotate(q, (0.0, 0.0, 1.0))[2] > math.cos(math.radians(3.0))  # lying flat
        assert not pybullet.getClosestPoints(
            world.object(scene.robot).body_id, body, 0.005, physicsClientId=cid
        )  # let go
    finally:
        world.close()


def test_boxy_closes_the_bowls_drawer_from_where_it_backed_off_pulling_it() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        kitchen = world.object("kitchen")
        joint = kitchen.joint_index[f"{BOWLS}_joint"]
        with simulated_robot(world, scene.robot):
            opened = Visit(usual_place("bowl")).open(AttemptLog())
            assert opened is not None
            assert pybullet.getJointState(kitchen.body_id, joint, cid)[0] == pytest.approx(
                0.4, abs=0.01
            )
            # its wide base backed off as it pulled: where it opened from, the drawer is now
            assert opened.reached is not None
            assert opened.reached.distance_to(opened.stand.pose) > 0.3
            close_again(opened)
        assert pybullet.getJointState(kitchen.body_id, joint, cid)[0] == pytest.approx(
            0.0, abs=0.01
        )
        assert not pybullet.getClosestPoints(
            world.object(scene.robot).body_id,
            kitchen.body_id,
            0.0,
            linkIndexB=kitchen.link_index[BOWLS],
            physicsClientId=cid,
        )
    finally:
        world.close()


def test_the_stretch_takes_a_bowl_from_the_table_looking_ahead_to_reach() -> None:
    scene = breakfast_scene(STRETCH)
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            table = table_with_seats(None)
            setting = next(s for s in spots(table, 2, STANDARD_SETTING, ()) if s.type == "bowl")
            x, y, _ = setting.pose.position
            low, _ = world.aabb("bowl-1")
            lift = world.pose("bowl-1").position[2] - low[2]
            world.set_pose(
                "bowl-1", Pose((x, y, TABLE_TOP + lift + 0.001), setting.pose.orientation)
            )
            point = world.pose("bowl-1").position
            fetch(an.object(type="bowl", name="bowl-1", pose=PoseStamped("map", point)))
        low, _ = pybullet.getAABB(world.object("bowl-1").body_id, physicsClientId=cid)
        assert low[2] > TABLE_TOP + 0.02  # lifted off the table
        head = world.object(scene.robot)
        tilt = pybullet.getJointState(head.body_id, head.joint_index["joint_head_tilt"], cid)[0]
        assert tilt == pytest.approx(0.0, abs=0.05)  # it looked ahead: the lift passes the head
    finally:
        world.close()


BOXY_TORSO = "triangle_base_joint"
# in front of the opened bowls' drawer, the left arm 0.85 m from the far bowl
BOXY_AT_DRAWER = Pose((-1.328, 0.91, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))


def test_boxy_raises_its_lowered_torso_to_stand_at_the_opened_drawer() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_joint_states("kitchen", {f"{BOWLS}_joint": 0.4})
        world.set_joint_states(scene.robot, {BOXY_TORSO: -0.586})  # lowered, as to look in
        robot, kitchen = world.object(scene.robot), world.object("kitchen")
        start = world.pose(scene.robot)
        world.set_pose(scene.robot, BOXY_AT_DRAWER)
        pybullet.performCollisionDetection(cid)
        met = pybullet.getClosestPoints(robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid)
        # lowered, the arms' shoulders meet the drawer there; the base does not
        links = {index: name for name, index in robot.link_index.items()}
        assert met
        assert all("arm" in links.get(p[3], "base") for p in met)
        world.set_pose(scene.robot, start)
        with simulated_robot(world, scene.robot):
            navigate_torso_up(BOXY_AT_DRAWER)
        position, _ = pybullet.getBasePositionAndOrientation(robot.body_id, cid)
        assert position[0] == pytest.approx(-1.328, abs=0.01)
        assert position[1] == pytest.approx(0.91, abs=0.01)
        torso = pybullet.getJointState(robot.body_id, robot.joint_index[BOXY_TORSO], cid)[0]
        assert torso > -0.586 + 0.1  # raised
        assert not pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid
        )
    finally:
        world.close()


def test_boxy_puts_the_tucked_bowl_down_after_the_other_hand_failed_in_the_drawer(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the other hand fails as it did before session 23: no stands facing a bowl's rim,
    # no untried stands after them (session 24), and a hand closed round its thin rim
    # holds nothing
    monkeypatch.setattr(fetch_plan, "grasp_point_stands", lambda *_args: iter(()))
    monkeypatch.setattr(fetch_plan, "_untried", lambda _stands: iter(()))
    monkeypatch.setattr(gripper, "_closed_round_thin", lambda *_args: None)
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        with simulated_robot(world, scene.robot):
            table = table_with_seats(None)
            spot = next(s for s in spots(table, 2, STANDARD_SETTING, ()) if s.type == "bowl")
            visit = Visit(usual_place("bowl"))
            done = TableSetting(table)
            seen, opened = find(an.object(type="bowl", name="bowl-2"), visit, done.log)
            held = fetch(seen, log=done.log, opened=opened)
            out = trips._tucked(held)
            other = trips.other_arm(held.arm)
            assert other is not None
            # the other hand cannot take the second bowl and is left where it last tried
            assert trips._second(spot, other, visit, done, skip={held.object_name}) is None
            assert not trips._held_out_alone(held, out, spot, done)
            visit.close(done.log)
        body = world.object("bowl-2").body_id
        low, _ = pybullet.getAABB(body, physicsClientId=cid)
        assert low[2] == pytest.approx(TABLE_TOP, abs=0.01)  # on the table
        x, y, _ = pybullet.getBasePositionAndOrientation(body, cid)[0]
        assert math.hypot(x - spot.pose.position[0], y - spot.pose.position[1]) < 0.15
        assert not pybullet.getClosestPoints(
            world.object(scene.robot).body_id, body, 0.005, physicsClientId=cid
        )  # let go
    finally:
        world.close()


def test_the_stretch_opens_the_fridge_looking_ahead_after_looking_down_into_a_drawer() -> None:
    scene = breakfast_scene(STRETCH)
    world = scene.world
    cid = world.physics.client()
    try:
        # the head as a look into the cutlery drawer left it: turned to the arm, down
        world.set_joint_states(scene.robot, {"joint_head_pan": -1.754, "joint_head_tilt": -0.819})
        with simulated_robot(world, scene.robot):
            open_from_front("fridge_body")
        kitchen = world.object("kitchen")
        door = kitchen.joint_index["fridge_door_joint"]
        assert pybullet.getJointState(kitchen.body_id, door, cid)[0] == pytest.approx(1.4, abs=0.01)
        head = world.object(scene.robot)
        tilt = pybullet.getJointState(head.body_id, head.joint_index["joint_head_tilt"], cid)[0]
        assert tilt == pytest.approx(0.0, abs=0.05)  # it looked ahead
    finally:
        world.close()


def test_the_fetch_lifts_its_hand_out_of_a_drawer_when_backing_off_a_little_did_not_help() -> None:
    scene = breakfast_scene(FETCH)
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_joint_states("kitchen", {f"{CUPS}_joint": 0.4})
        world.set_pose(scene.robot, FETCH_BESIDE_CUPS)
        world.set_joint_states(scene.robot, FETCH_PARKED)
        kitchen, robot = world.object("kitchen"), world.object(scene.robot)
        drawer = kitchen.link_index[CUPS]
        pybullet.performCollisionDetection(cid)
        # parked where it stands, the elbow would be in the drawer
        assert pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, linkIndexB=drawer, physicsClientId=cid
        )
        world.set_joint_states(scene.robot, FETCH_HAND_IN_CUPS)
        with simulated_robot(world, scene.robot):
            park_arms()
        for joint, parked in FETCH_PARKED.items():
            value = pybullet.getJointState(robot.body_id, robot.joint_index[joint], cid)[0]
            off = math.remainder(value - parked, 2 * math.pi)
            assert off == pytest.approx(0.0, abs=0.01), joint
        opened = pybullet.getJointState(kitchen.body_id, kitchen.joint_index[f"{CUPS}_joint"], cid)
        assert opened[0] == pytest.approx(0.4, abs=0.005)  # not pushed by the arm
        assert not pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid
        )
    finally:
        world.close()
