"""Limits are checked when a description loads: the URDF's rates, the description's
acceleration limits and joint values (issue 42, weak: limits in a URDF or description)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from robocram.robots import (
    DescriptionCheckError,
    JointValueError,
    LimitValueError,
    RobotDescription,
    UrdfError,
    load_description,
)
from robocram.robots.limit_check import MIN_RATE_LIMIT

FULL = 'velocity="1" effort="1"'


def two_joint_urdf(folder: Path, limit: str = FULL) -> Path:
    """``base`` - lift (prismatic) - ``post`` - spin (continuous) - ``top``."""
    path = folder / "lift.urdf"
    path.write_text(
        '<robot name="lift"><link name="base"/><link name="post"/><link name="top"/>'
        '<joint name="lift_joint" type="prismatic"><parent link="base"/><child link="post"/>'
        f'<axis xyz="0 0 1"/><limit lower="0" upper="0.5" {limit}/></joint>'
        '<joint name="spin_joint" type="continuous"><parent link="post"/><child link="top"/>'
        '<axis xyz="0 0 1"/></joint></robot>',
        "utf-8",
    )
    return path


def test_a_full_description_loads(tmp_path: Path) -> None:
    desc = RobotDescription("lift", two_joint_urdf(tmp_path), base_frame="base")
    loaded = load_description(
        RobotDescription(
            "lift", desc.urdf, base_frame="base", acceleration_limits={"lift_joint": 0.3}
        )
    )
    assert loaded.acceleration_limits == {"lift_joint": 0.3}


@pytest.mark.parametrize(
    ("limit", "missing"), [('effort="1"', "velocity"), ('velocity="1"', "effort")]
)
def test_a_joint_without_a_rate_is_refused_naming_it(
    tmp_path: Path, limit: str, missing: str
) -> None:
    desc = RobotDescription("lift", two_joint_urdf(tmp_path, limit), base_frame="base")
    with pytest.raises(UrdfError, match=rf"prismatic joint 'lift_joint' has no {missing} limit"):
        load_description(desc)


def test_a_velocity_limit_of_1e_300_is_refused_naming_the_bound(tmp_path: Path) -> None:
    desc = RobotDescription(
        "lift", two_joint_urdf(tmp_path, 'velocity="1e-300" effort="1"'), base_frame="base"
    )
    with pytest.raises(UrdfError, match=r"'lift_joint' has velocity limit 1e-300, below 1e-06"):
        load_description(desc)


@pytest.mark.parametrize("value", [0.0, -1.0, math.nan, math.inf, 1e-300])
def test_an_unusable_acceleration_limit_is_refused(tmp_path: Path, value: float) -> None:
    desc = RobotDescription(
        "lift",
        two_joint_urdf(tmp_path),
        base_frame="base",
        acceleration_limits={"lift_joint": value},
    )
    with pytest.raises(LimitValueError) as caught:
        load_description(desc)
    assert caught.value.joint == "lift_joint" and caught.value.bound == MIN_RATE_LIMIT
    assert "MIN_RATE_LIMIT" in str(caught.value)


def test_a_misspelled_joint_in_acceleration_limits_is_refused(tmp_path: Path) -> None:
    desc = RobotDescription(
        "lift", two_joint_urdf(tmp_path), base_frame="base", acceleration_limits={"lift_jiont": 1.0}
    )
    with pytest.raises(DescriptionCheckError, match=r"'lift_jiont' .*did you mean 'lift_joint'"):
        load_description(desc)


def test_an_infinite_value_of_a_continuous_joint_is_refused(tmp_path: Path) -> None:
    desc = RobotDescription(
        "lift", two_joint_urdf(tmp_path), base_frame="base", neck_parking={"spin_joint": math.inf}
    )
    with pytest.raises(JointValueError, match=r"value inf for joint 'spin_joint'"):
        load_description(desc)
