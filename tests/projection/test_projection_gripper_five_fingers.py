"""TIAGo from example-robot-data, its five-finger hand coupled in the description (no URDF
patch, no <mimic>): the unchanged pick-up plan picks the tabletop mug, gripped by contact
(a palm hand: it takes the mug by the handle, palm first, docs/grasping.md)."""

from __future__ import annotations

import math

import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.robots import (
    ArmDescription,
    CameraDescription,
    FrameSpec,
    GripperDescription,
    GripperJoint,
    PanTiltDescription,
    RobotDescription,
    example_robot_data_folder,
)
from robocram.scenes import tabletop_scene
from robocram.tf import Pose

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")
FINGERS = ("index", "middle", "ring", "little")
# The flex joints a simulator plugin couples to the three motors on the real hand.
CURLS = tuple(
    f"hand_{finger}_{kind}_{i}_joint"
    for finger in FINGERS
    for kind in ("virtual", "flex")
    for i in (1, 2, 3)
) + tuple(f"hand_thumb_{kind}_{i}_joint" for kind in ("virtual", "flex") for i in (1, 2))
ARM = tuple(f"arm_{i}_joint" for i in range(1, 8))


def tiago() -> RobotDescription:
    """TIAGo: one 7-joint arm, a lifting torso, a pan-tilt head with an Xtion."""
    folder = example_robot_data_folder()
    hand = GripperDescription(
        (GripperJoint("hand_thumb_abd_joint", open=0.0, closed=math.pi / 2),)
        + tuple(GripperJoint(j, open=0.0, closed=math.pi / 4) for j in CURLS)
    )
    # x = approach as the hand's grasping frame, 6 cm further out: between the finger tips
    tool = FrameSpec("tool_frame", "hand_grasping_frame", Pose((0.06, 0.0, 0.0)))
    parking = dict(zip(ARM, (0.2, -1.34, -0.2, 1.94, -1.57, 1.37, 0.0), strict=True))
    arm = ArmDescription(
        "arm",
        "arm_7_link",
        "tool_frame",
        base_link="torso_lift_link",
        gripper=hand,
        parking=parking,
    )
    return RobotDescription(
        "tiago",
        folder / "tiago_description" / "robots" / "tiago.urdf",
        base_frame="base_footprint",
        torso_link="torso_lift_link",
        torso_joint="torso_lift_joint",
        arms={"arm": arm},
        cameras=(
            CameraDescription("xtion_rgb_optical_frame", horizontal_fov=1.01, vertical_fov=0.79),
        ),
        pan_tilt=PanTiltDescription(pan_joint="head_1_joint", tilt_joint="head_2_joint"),
        neck_parking={"head_1_joint": 0.0, "head_2_joint": 0.0},
        extra_frames=(tool,),
        package_paths=(folder,),
    )


def test_the_unchanged_pick_up_plan_runs_on_tiago_with_its_hand() -> None:
    scene = tabletop_scene(tiago())
    world = scene.world
    placed = world.pose("mug-1").position
    with simulated_robot(world, scene.robot):
        result = pick_up(scene.look_target)
    assert result.arm == "arm" and world.bodies.attachments("tiago") == {"mug-1": "arm_7_link"}
    assert world.pose("mug-1").position[2] > placed[2] + 0.05  # lifted off the table
    hand = world.joint_states("tiago")
    curled = [hand[j] for j in CURLS]
    assert min(curled) > 0.0 and max(curled) < math.pi / 4 - 0.01  # stopped on the mug
    world.close()
