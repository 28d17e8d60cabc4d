"""A pick whose every try failed leaves no hand in the drawer: it backs out to its pre-grasp.

The drafted Stretch reaches down into the opened cups' drawer for cup-2 (household seed 0
of ``benchmarks/activity_bench.py``: the cup 1 cm deeper than its spot). Its grip meets the
cup on one side only, the centred grip is blocked, and no other grasp is in reach from
this stand. The hand used to stay at the grasp, its fingers 4 mm under the drawer above;
in the household's whole setting, parking and every drive after it then ran into that
drawer and the cups and the milk were never brought. Judged on raw
PyBullet: the hand is back at its pre-grasp, clear of the drawer, and the arms park.
The retry with the hand opened part way, which now takes cup-2 from here
(``test_plans_part_way_retries.py``), is left out: this is the pick whose every try failed;
so are the tries from a stand on a side grasp's approach line that come after them
(``test_plans_pick_line_stand.py``: the arm parks and the robot drives there).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pybullet
import pytest

from robocram.plans import pick_object
from robocram.plans.basic_actions import park_arms
from robocram.plans.grasp_failures import PickUpFailed
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
CUPS = "cutlery_unit_drawer_4"
CUP_2_AT = (-0.2496, -0.18)  # [m] in the drawer: seed 0's cup-2, 1 cm deeper than its spot
CUPS_OUT = {  # the cups where the drawer, opened 0.4 m, carried them (map)
    "cup-1": (-0.0200, 1.7432, 0.6995),
    "cup-2": (-0.3800, 1.7496, 0.6995),
}
CLEAR = 0.02  # [m] the hand backed out is this far from the cups' drawer at least
STAND = Pose((-0.267, 1.196, 0.0), quat.from_euler(0.0, 0.0, -2.944))  # where it tried
OVER_THE_CUP = {  # the open hand at its first pre-grasp, over cup-2, looking down into it
    "joint_lift": 0.9294,
    **{f"joint_arm_l{i}": 0.1068 for i in range(4)},
    "joint_wrist_yaw": -1.2472,
    "joint_wrist_pitch": -1.57,
    "joint_wrist_roll": -1.0495,
    "joint_gripper_finger_right": 0.6,
    "joint_gripper_finger_left": 0.6,
    "joint_head_pan": -1.7543,
    "joint_head_tilt": -0.8191,
}


def test_a_failed_pick_takes_the_hand_out_of_the_drawer_and_the_arm_parks(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(pick_object, "_finger_caught", lambda *_: False)  # no part-way retry
    monkeypatch.setattr(pick_object, "_line_stand", lambda *_: None)  # nor a line stand's
    places = [replace(p, xy=CUP_2_AT) if p.name == "cup-2" else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene(STRETCH, places=places)
    world = scene.world
    cid = world.physics.client()
    try:
        world.set_joint_states("kitchen", {f"{CUPS}_joint": 0.4})
        for cup, at in CUPS_OUT.items():
            world.set_pose(cup, Pose(at, (0.0, 0.0, 0.0, 1.0)))
        world.set_pose(scene.robot, STAND)
        world.set_joint_states(scene.robot, OVER_THE_CUP)
        with simulated_robot(world, scene.robot), pytest.raises(PickUpFailed):
            pick_up_object("cup-2", out_of=("kitchen", CUPS))
        robot, kitchen = world.object(scene.robot), world.object("kitchen")
        lift = pybullet.getJointState(robot.body_id, robot.joint_index["joint_lift"], cid)[0]
        assert lift == pytest.approx(OVER_THE_CUP["joint_lift"], abs=0.01)  # at the pre-grasp
        pybullet.performCollisionDetection(cid)
        near = pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, CLEAR, linkIndexB=kitchen.link_index[CUPS],
            physicsClientId=cid,
        )  # fmt: skip
        assert not near  # was 4 mm: the fingers at the grasp, under the drawer above
        with simulated_robot(world, scene.robot):
            park_arms()
    finally:
        world.close()
