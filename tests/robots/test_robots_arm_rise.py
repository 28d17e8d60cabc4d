"""The rise at an arm's shoulder: what lies along its first joint's axis reaches no farther out.

A hand-made arm: a vertical pan, its lift joint 0.10 m above it and 0.03 m aside, an upper
arm of 0.20 m and a forearm of 0.15 m. Its stretched reach counts the 0.104 m first
segment; from the top of the rise it reaches 0.03 + 0.20 + 0.15 m (worked out by hand).
"""

from __future__ import annotations

import math

import pytest

from robocram.robots.arm_envelope import arm_reach
from robocram.robots.arm_rise import arm_rise
from robocram.robots.description import ArmDescription
from robocram.robots.robot_model import RobotModel

URDF = """<robot name="riser">
  <link name="base"/><link name="turret"/><link name="upper"/><link name="fore"/>
  <link name="wrist"/>
  <joint name="pan" type="revolute"><parent link="base"/><child link="turret"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="lift" type="revolute"><parent link="turret"/><child link="upper"/>
    <origin xyz="0 0.03 0.10"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
    <origin xyz="0.20 0 0"/><axis xyz="0 1 0"/><limit lower="-3" upper="3" effort="1" velocity="1"/>
  </joint>
  <joint name="tip" type="fixed"><parent link="fore"/><child link="wrist"/>
    <origin xyz="0.15 0 0"/></joint>
</robot>"""

ARM = ArmDescription(
    name="arm", end_effector_link="wrist", tool_frame="wrist", joints=("pan", "lift", "elbow")
)


def test_the_rise_along_a_vertical_pan_is_taken_off_the_reach_its_sideways_part_kept() -> None:
    model = RobotModel.from_string(URDF)
    shape = arm_rise(model, ARM)
    assert shape.rise == pytest.approx((0.0, 0.0, 0.10), abs=1e-9)
    assert shape.reach == pytest.approx(0.03 + 0.20 + 0.15, abs=1e-9)
    assert arm_reach(model, ARM) == pytest.approx(math.hypot(0.03, 0.10) + 0.35, abs=1e-9)


def test_an_arm_whose_first_joint_slides_has_no_rise() -> None:
    model = RobotModel.from_string(
        URDF.replace('name="pan" type="revolute"', 'name="pan" type="prismatic"')
    )
    shape = arm_rise(model, ARM)
    assert shape.rise == (0.0, 0.0, 0.0)
    assert shape.reach == pytest.approx(arm_reach(model, ARM))
