"""The checker's semantic checks: each broken description names its fault and the fix."""

from __future__ import annotations

import math
import warnings
from dataclasses import replace

import pytest

from robocram.robots import (
    DescriptionCheckError,
    DescriptionWarning,
    FrameSpec,
    JointValueError,
    RobotDescription,
    load_description,
)
from robocram.robots.builtin import builtin_description
from robocram.tf import Pose


def pr2() -> RobotDescription:
    return builtin_description("pr2")


def fault_of(desc: RobotDescription) -> str:
    with pytest.raises(DescriptionCheckError) as info:
        load_description(desc)
    assert len(info.value.problems) == 1
    return str(info.value)


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy", "quadrotor"])
def test_builtin_robots_pass_every_check_without_warnings(robot: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", DescriptionWarning)
        assert load_description(robot).findings == ()


def test_a_tool_frame_pointing_back_at_the_wrist_is_a_fault() -> None:
    desc = pr2()
    backwards = FrameSpec(
        "r_backwards", "r_gripper_tool_frame", Pose.from_xyz_rpy((0, 0, 0), (0, 0, math.pi))
    )
    right = replace(desc.arms["right"], tool_frame="r_backwards")
    text = fault_of(replace(desc, arms={**desc.arms, "right": right}, extra_frames=(backwards,)))
    assert "arms['right'].tool_frame: 'r_backwards' has x pointing 180 deg off" in text
    assert "which is its -x axis" in text and "turn the tool frame so that its x is" in text


def test_a_tool_frame_with_z_as_approach_names_z() -> None:
    desc = pr2()
    z_ahead = FrameSpec(
        "r_z_ahead", "r_gripper_tool_frame", Pose.from_xyz_rpy((0, 0, 0), (0, math.pi / 2, 0))
    )
    right = replace(desc.arms["right"], tool_frame="r_z_ahead")
    text = fault_of(replace(desc, arms={**desc.arms, "right": right}, extra_frames=(z_ahead,)))
    assert "which is its +z axis" in text  # pitch +90 deg turns x down and z ahead


def test_a_camera_facing_backwards_is_a_fault() -> None:
    desc = replace(pr2(), neck_parking={"head_pan_joint": 3.0, "head_tilt_joint": 0.0})
    text = fault_of(desc)
    assert "cameras[0].frame: 'wide_stereo_optical_frame' looks 172 deg away" in text
    assert "fix neck_parking to face ahead" in text


def test_a_camera_body_frame_is_warned_about() -> None:
    desc = pr2()
    body = replace(desc.cameras[0], frame="wide_stereo_link")
    with pytest.warns(DescriptionWarning, match="'wide_stereo_link' looks along its x"):
        loaded = load_description(replace(desc, cameras=(body,)))
    assert [f.subject for f in loaded.findings] == ["cameras[0].frame"]
    assert "optical frame (z forward, x right, y down)" in loaded.findings[0].fix


def test_swapped_camera_heights_are_a_fault() -> None:
    camera = replace(pr2().cameras[0], minimal_height=1.58, maximal_height=1.27)
    text = fault_of(replace(pr2(), cameras=(camera,)))
    assert "minimal_height 1.58 m is above maximal_height 1.27 m; swap them" in text


def test_a_head_joint_named_as_torso_is_a_fault() -> None:
    text = fault_of(replace(pr2(), torso_joint="head_tilt_joint"))
    assert "torso_joint: 'head_tilt_joint' does not move the base of arm 'left'" in text
    assert "name the prismatic joint that lifts the arms" in text


def test_a_parking_pose_beyond_the_limits_names_the_joint_and_limits() -> None:
    desc = pr2()
    right = replace(desc.arms["right"], parking={"r_shoulder_lift_joint": 2.0})
    with pytest.raises(JointValueError, match=r"'r_shoulder_lift_joint' is outside its limits"):
        load_description(replace(desc, arms={**desc.arms, "right": right}))


def test_camera_heights_come_from_the_torso_limits() -> None:
    camera = replace(pr2().cameras[0], minimal_height=None, maximal_height=None)
    loaded = load_description(replace(pr2(), cameras=(camera,)))
    # the hand-measured 1.27 m and 1.58 m of the built-in description, to 0.2 mm
    assert loaded.cameras[0].height_range() == pytest.approx((1.270, 1.580), abs=2e-4)


def test_hand_links_default_to_the_wrist_and_everything_below() -> None:
    desc = pr2()
    right = replace(desc.arms["right"], hand_links=())
    hand = load_description(replace(desc, arms={**desc.arms, "right": right})).arms["right"]
    assert hand.hand_links[0] == "r_wrist_roll_link"
    assert {"r_gripper_palm_link", "r_gripper_l_finger_tip_link", "r_gripper_tool_frame"} <= set(
        hand.hand_links
    )
    assert "r_forearm_link" not in hand.hand_links


def test_what_plans_need_and_is_left_empty_is_warned_about_and_listed() -> None:
    desc = pr2()
    right = replace(desc.arms["right"], gripper_joints=(), parking={})
    with pytest.warns(DescriptionWarning) as caught:
        loaded = load_description(replace(desc, arms={**desc.arms, "right": right}, cameras=()))
    subjects = [f.subject for f in loaded.findings]
    assert subjects == ["arms['right']", "arms['right'].parking", "cameras"]
    assert len(caught) == 3
    assert "no gripper: picking up with it fails; give gripper_joints" in str(caught[0].message)


def test_a_loaded_description_passed_on_is_not_warned_about_again() -> None:
    desc = replace(pr2(), cameras=())
    with pytest.warns(DescriptionWarning):
        loaded = load_description(desc)
    with warnings.catch_warnings():
        warnings.simplefilter("error", DescriptionWarning)
        again = load_description(loaded)  # what a scene does before World.add_robot
    assert again.findings == loaded.findings and len(again.findings) == 1


def test_warnings_are_logged_too(caplog: pytest.LogCaptureFixture) -> None:
    with pytest.warns(DescriptionWarning), caplog.at_level("WARNING", logger="robocram.robots"):
        load_description(replace(pr2(), cameras=()))
    assert [r.getMessage() for r in caplog.records] == [
        "robot 'pr2': cameras: none: looking and detecting fail; give a CameraDescription "
        "for the camera's optical frame"
    ]
