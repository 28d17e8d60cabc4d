"""mimic_followers: followers take multiplier * master + offset, transitively."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.robots import DescriptionError, RobotModel, load_description, mimic_followers
from robocram.robots.errors import DanglingMimicWarning

DATA = Path(__file__).parents[2] / "src" / "robocram" / "robots" / "data"

CHAIN_URDF = """<robot name="chain"><link name="a"/><link name="b"/><link name="c"/><link name="d"/>
  <joint name="master" type="revolute"><parent link="a"/><child link="b"/>
    <limit lower="-1" upper="1"/></joint>
  <joint name="middle" type="revolute"><parent link="b"/><child link="c"/>
    <limit lower="-3" upper="3"/><mimic joint="master" multiplier="2" offset="0.1"/></joint>
  <joint name="last" type="revolute"><parent link="c"/><child link="d"/>
    <limit lower="-3" upper="3"/><mimic joint="middle" multiplier="-1"/></joint>
</robot>"""


def test_pr2_gripper_fingers_follow_the_left_finger_joint() -> None:
    pr2 = load_description("pr2")
    assert pr2.model is not None
    values = mimic_followers(pr2.model, {"r_gripper_l_finger_joint": 0.4, "torso_lift_joint": 0.1})
    assert values["r_gripper_r_finger_joint"] == pytest.approx(0.4)
    assert values["r_gripper_l_finger_tip_joint"] == pytest.approx(0.4)
    assert values["r_gripper_r_finger_tip_joint"] == pytest.approx(0.4)
    assert values["r_gripper_r_parallel_root_joint"] == pytest.approx(-0.4)
    assert values["torso_lift_joint"] == 0.1
    assert not any(name.startswith("l_gripper") for name in values)


def test_followers_of_followers_and_offsets() -> None:
    model = RobotModel.from_string(CHAIN_URDF)
    assert mimic_followers(model, {"master": 0.5}) == pytest.approx(
        {"master": 0.5, "middle": 1.1, "last": -1.1}
    )


def test_follower_set_against_its_master_is_an_error() -> None:
    model = RobotModel.from_string(CHAIN_URDF)
    assert mimic_followers(model, {"master": 0.5, "middle": 1.1})["last"] == pytest.approx(-1.1)
    with pytest.raises(DescriptionError, match="'middle' mimics 'master' and must be 1.1"):
        mimic_followers(model, {"master": 0.5, "middle": 0.0})


def test_unknown_joint_suggests_the_right_name() -> None:
    model = RobotModel.from_string(CHAIN_URDF)
    with pytest.raises(
        DescriptionError, match="joint 'mastr' not in <string>; did you mean 'master'"
    ):
        mimic_followers(model, {"mastr": 0.0})


def test_mimic_of_a_missing_joint_is_read_as_a_free_joint_with_a_warning() -> None:
    """Issue 37: Alex's hands publish mimics of joints their URDF lacks; PyBullet and the
    other readers load them, so robocram does too, naming the culprit and its fix."""
    xml = CHAIN_URDF.replace('<mimic joint="master"', '<mimic joint="mastr"')
    with pytest.warns(DanglingMimicWarning, match="mimics 'mastr'; did you mean 'master'"):
        model = RobotModel.from_string(xml)
    assert all(j.mimic is None or j.mimic.joint in model.joints for j in model.joints.values())
    assert not any(j.mimic is not None and j.mimic.joint == "mastr" for j in model.joints.values())


@pytest.mark.skipif(not (DATA / "hsrb.urdf").is_file(), reason="the HSR model is not written yet")
def test_hsr_torso_follows_half_the_arm_lift() -> None:
    model = RobotModel.from_file(DATA / "hsrb.urdf")
    values = mimic_followers(model, {"arm_lift_joint": 0.4})
    assert values["torso_lift_joint"] == pytest.approx(0.2)
