"""Mimic joints at the URDF door: no loops, factors within a bound (issue 42, weak: mimics)."""

from __future__ import annotations

import pytest

from robocram.robots import RobotModel, UrdfError
from robocram.robots.robot_model import MIMIC_BOUND


def _urdf(first_mimic: str, second_mimic: str) -> str:
    return (
        '<robot name="fingers"><link name="palm"/><link name="left"/><link name="right"/>'
        '<joint name="left_joint" type="revolute"><parent link="palm"/><child link="left"/>'
        f'<limit lower="-1" upper="1" velocity="1" effort="1"/>{first_mimic}</joint>'
        '<joint name="right_joint" type="revolute"><parent link="palm"/><child link="right"/>'
        f'<limit lower="-1" upper="1" velocity="1" effort="1"/>{second_mimic}</joint></robot>'
    )


def test_a_follower_of_a_master_loads() -> None:
    model = RobotModel.from_string(_urdf("", '<mimic joint="left_joint" multiplier="-1"/>'))
    assert model.joints["right_joint"].mimic is not None


def test_joints_mimicking_each_other_are_refused_naming_them() -> None:
    text = _urdf('<mimic joint="right_joint"/>', '<mimic joint="left_joint"/>')
    with pytest.raises(UrdfError, match=r"loop \('left_joint' -> 'right_joint' -> 'left_joint'\)"):
        RobotModel.from_string(text)


def test_a_joint_mimicking_itself_is_refused() -> None:
    with pytest.raises(UrdfError, match=r"loop \('left_joint' -> 'left_joint'\)"):
        RobotModel.from_string(_urdf('<mimic joint="left_joint"/>', ""))


@pytest.mark.parametrize("factor", ['multiplier="1e308"', 'offset="-1e300"'])
def test_a_huge_mimic_factor_is_refused_naming_the_bound(factor: str) -> None:
    with pytest.raises(UrdfError) as caught:
        RobotModel.from_string(_urdf("", f'<mimic joint="left_joint" {factor}/>'))
    assert "joint 'right_joint' mimics 'left_joint'" in str(caught.value)
    assert f"{MIMIC_BOUND:g} (MIMIC_BOUND)" in str(caught.value)
