"""Gripper descriptions: parallel defaults from limits, declared multi-finger hands, bad values."""

from __future__ import annotations

from dataclasses import replace

import pytest

from robocram.logic import KnowledgeBase
from robocram.robots import (
    ArmDescription,
    GripperDescription,
    GripperDescriptionError,
    GripperJoint,
    JointValueError,
    RobotDescription,
    install_description,
    link_pose,
    load_description,
)
from robocram.robots.builtin import builtin_description
from robocram.robots.example_robot_data import example_robot_data_folder

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")
ALLEGRO = example_robot_data_folder() / "allegro_hand_description" / "urdf"
# Index, middle and ring fingers curl at joints 1-3, the thumb at 13-15 (12 turns it in).
CURLS = tuple(f"joint_{i}.0" for i in (1, 2, 3, 5, 6, 7, 9, 10, 11, 13, 14, 15))
TIPS = ("link_3.0_tip", "link_7.0_tip", "link_11.0_tip", "link_15.0_tip")


def allegro(gripper: GripperDescription | None) -> RobotDescription:
    """The Allegro hand as a robot whose only "arm" is the hand (no arm joints)."""
    hand = ArmDescription(
        name="hand",
        end_effector_link="palm_link",
        tool_frame="palm_link",
        base_link="palm_link",
        gripper=gripper,
        parking={},
    )
    return RobotDescription(
        "allegro", ALLEGRO / "allegro_right_hand.urdf", base_frame="palm_link", arms={"hand": hand}
    )


def curled(fraction: float) -> GripperDescription:
    """Every curl joint flat (open, 0 rad) or at ``fraction`` of 1.1 rad (closed)."""
    joints = [GripperJoint(name, open=0.0, closed=1.1 * fraction) for name in CURLS]
    return GripperDescription((GripperJoint("joint_12.0", open=0.3, closed=1.2), *joints))


@pytest.mark.parametrize(
    ("robot", "arm", "joint", "opened", "closed", "widest"),
    [
        ("pr2", "right", "r_gripper_l_finger_joint", 0.548, 0.0, 0.094),
        ("hsrb", "arm", "hand_motor_joint", 1.24, -0.798, 0.130),
        ("boxy", "left", "left_gripper_joint", 0.109, 0.0065, 0.1025),
    ],
)
def test_parallel_grippers_open_at_upper_and_close_at_lower_limits(
    robot: str, arm: str, joint: str, opened: float, closed: float, widest: float
) -> None:
    gripper = load_description(robot).arms[arm].gripper
    assert gripper is not None and gripper.names == (joint,)
    assert (gripper.joints[0].open, gripper.joints[0].closed) == pytest.approx((opened, closed))
    assert gripper.max_opening == pytest.approx(widest, abs=1e-3)
    assert gripper.fraction_of((opened + closed) / 2) == pytest.approx(0.5)


def test_the_widest_opening_is_a_fact_plans_can_read() -> None:
    kb = KnowledgeBase()
    install_description(kb, "pr2")
    answer = kb.first("gripper_max_opening(pr2, left, W)")
    assert answer is not None and answer["W"] == pytest.approx(0.094, abs=1e-3)


def test_a_declared_hand_moves_every_finger_and_derives_fingers_and_opening() -> None:
    hand = load_description(allegro(curled(1.0))).arms["hand"]
    assert hand.gripper is not None and hand.gripper_joints == ("joint_12.0", *CURLS)
    assert set(TIPS) <= set(hand.gripper_links)  # the links the finger joints move
    assert "palm_link" in hand.hand_links and set(TIPS) <= set(hand.hand_links)
    half = hand.gripper.at(0.5)
    assert half["joint_2.0"] == pytest.approx(0.55) and half["joint_12.0"] == pytest.approx(0.75)
    model = load_description(allegro(curled(1.0))).model
    thumb_to_index = [
        link_pose(model, "link_15.0_tip", hand.gripper.at(f)).distance_to(
            link_pose(model, "link_3.0_tip", hand.gripper.at(f))
        )
        for f in (0.0, 1.0)
    ]
    assert thumb_to_index[1] > thumb_to_index[0]  # opening spreads thumb and index apart
    assert hand.gripper.max_opening is not None
    assert hand.gripper.max_opening >= thumb_to_index[1] - thumb_to_index[0] - 1e-9


def test_given_max_opening_is_kept() -> None:
    hand = load_description(allegro(replace(curled(1.0), max_opening=0.15))).arms["hand"]
    assert hand.gripper is not None and hand.gripper.max_opening == 0.15


def test_open_equal_to_closed_names_the_joint_and_the_fix() -> None:
    same = GripperDescription((GripperJoint("joint_1.0", open=0.3, closed=0.3),))
    with pytest.raises(GripperDescriptionError, match=r"'joint_1.0' is open and closed at") as info:
        load_description(allegro(same))
    assert info.value.arm == "hand" and "give different open and closed" in str(info.value)


def test_a_value_beyond_the_limits_is_a_joint_value_error() -> None:
    far = GripperDescription((GripperJoint("joint_1.0", open=0.0, closed=3.0),))
    with pytest.raises(JointValueError, match="joint_1.0") as info:
        load_description(allegro(far))
    assert info.value.upper == pytest.approx(1.61)


def test_a_negative_max_opening_is_refused() -> None:
    with pytest.raises(GripperDescriptionError, match=r"max_opening -0.1 is no positive"):
        load_description(allegro(replace(curled(1.0), max_opening=-0.1)))


def test_a_misspelt_gripper_joint_gets_a_suggestion() -> None:
    typo = GripperDescription((GripperJoint("joint_1.O", open=0.0, closed=1.0),))
    with pytest.raises(Exception, match=r"'joint_1.O' .*did you mean 'joint_1.0'"):
        load_description(allegro(typo))


def test_gripper_joints_that_contradict_the_gripper_are_refused() -> None:
    desc = builtin_description("pr2")
    right = replace(
        desc.arms["right"],
        gripper=GripperDescription((GripperJoint("r_gripper_l_finger_joint", 0.5, 0.0),)),
        gripper_joints=("r_gripper_r_finger_joint",),
    )
    with pytest.raises(GripperDescriptionError, match="give only ArmDescription.gripper"):
        load_description(replace(desc, arms={**desc.arms, "right": right}))


TIAGO = example_robot_data_folder() / "tiago_description" / "robots" / "tiago.urdf"


def _tiago(gripper: GripperDescription) -> RobotDescription:
    arm = ArmDescription(
        name="arm",
        end_effector_link="arm_7_link",
        tool_frame="arm_7_link",
        base_link="torso_lift_link",
        gripper=gripper,
        parking={},
    )
    return RobotDescription("tiago", TIAGO, base_frame="base_footprint", arms={"arm": arm})


def test_a_curling_hand_finds_its_joints_at_load() -> None:
    """The TIAGo's Hey5: 29 joints straight at 0 curl to their upper limits, thumb first."""
    gripper = load_description(_tiago(GripperDescription.curling())).arms["arm"].gripper
    assert gripper is not None and len(gripper.joints) == 29
    assert gripper.joints[0] == GripperJoint(
        "hand_thumb_abd_joint", 0.0, pytest.approx(1.5708, abs=1e-4)
    )
    assert all(j.open == 0.0 and 0.78 < j.closed < 1.58 for j in gripper.joints)
    assert "hand_index_flex_3_joint" in gripper.names
    assert gripper.max_opening == pytest.approx(0.1224, abs=1e-3)


def test_a_curling_hand_without_curling_joints_says_to_list_them() -> None:
    """The Panda's fingers slide (prismatic): nothing curls."""
    arm = ArmDescription(
        name="arm",
        end_effector_link="panda_link7",
        tool_frame="panda_link7",
        base_link="panda_link0",
        gripper=GripperDescription.curling(),
        parking={},
    )
    panda = example_robot_data_folder() / "panda_description" / "urdf" / "panda.urdf"
    desc = RobotDescription("panda", panda, base_frame="panda_link0", arms={"arm": arm})
    with pytest.raises(GripperDescriptionError, match=r"curling\(\) found no joint") as info:
        load_description(desc)
    assert "GripperJoint(name, open=..., closed=...)" in str(info.value)
