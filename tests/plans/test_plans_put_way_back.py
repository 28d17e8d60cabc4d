"""An open hand left low in a drawer by a put goes back out the way it came in: Boxy's
bowl let go in its drawer in household 17 (session 27), judged by raw PyBullet (the hand's
link pose, the robot's closest points, the bowl's pose)."""

from __future__ import annotations

import math

import pybullet

from robocram.plans.pick_object import Held
from robocram.plans.place_object import _out_the_way_in
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose, PoseStamped

# where clearing household 17 stood Boxy to put bowl-1 back into its opened drawer
BASE = Pose(
    (1.1034638363249705, 0.38634793291679753, 0.0),
    (0.0, 0.0, 0.20793873407689306, 0.9781418521208972),
)
LET_GO = {  # its torso and right arm as the hand let the bowl go, come in on another branch
    "triangle_base_joint": -0.4290020705136443,
    "right_arm_0_joint": -1.6532334461538063,
    "right_arm_1_joint": 1.8156276540252485,
    "right_arm_2_joint": 1.577734013128272,
    "right_arm_3_joint": 1.011395851770608,
    "right_arm_4_joint": -2.4002841195524725,
    "right_arm_5_joint": 1.0042865329990716,
    "right_arm_6_joint": 1.0097095260962052,
    "right_gripper_base_gripper_left_joint": -0.0545,
    "right_gripper_joint": 0.109,
}
START = Pose(  # the hand's tool frame before the put, over the drawer's front (map)
    (2.315232753753662, 0.7219899296760559, 0.891991376876831),
    (0.653285199589285, 0.2704958593775801, -0.6532829346128035, 0.270687726727416),
)
BOWL = Pose(  # let go in the drawer
    (2.2603089486845414, 0.7775470504726264, 0.6013239264535938),
    (8.11926187614012e-05, 3.7109160832480444e-05, -0.38250411948065877, 0.9239537816422393),
)
DRAWER_JOINT = "east_drawers_2_drawer_3_joint"
OPENED = 0.4  # [m] how far clearing had pulled the drawer out
TOOL = "right_standard_gripper_tool_frame"


def test_boxy_takes_its_open_hand_out_of_the_drawer_the_way_it_came_in() -> None:
    scene = breakfast_scene("boxy")
    world = scene.world
    cid = world.physics.client()
    try:
        kitchen, robot = world.object("kitchen"), world.object(scene.robot)
        world.set_joint_states("kitchen", {DRAWER_JOINT: OPENED})
        world.set_pose(scene.robot, BASE)
        world.set_joint_states(scene.robot, LET_GO)
        world.set_pose("bowl-1", BOWL)
        bowl = world.object("bowl-1").body_id
        lay = pybullet.getBasePositionAndOrientation(bowl, physicsClientId=cid)[0]
        was = PoseStamped.from_pose("map", START)
        with simulated_robot(world, scene.robot):
            assert _out_the_way_in(Held("right", "rim", "bowl-1", TOOL, was, was, Pose()), [START])
        tool = pybullet.getLinkState(robot.body_id, robot.link_index[TOOL], physicsClientId=cid)
        assert math.dist(tool[4], START.position) < 0.005  # back where it came in from
        assert not pybullet.getClosestPoints(
            robot.body_id, kitchen.body_id, 0.0, physicsClientId=cid
        )
        assert not pybullet.getContactPoints(robot.body_id, bowl, physicsClientId=cid)
        now = pybullet.getBasePositionAndOrientation(bowl, physicsClientId=cid)[0]
        assert math.dist(lay, now) < 0.002  # left lying where it was let go
    finally:
        world.close()
