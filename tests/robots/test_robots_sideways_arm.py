"""An arm on the side of a long base works to that side (issue 37, item 4).

Its shoulder turns all round, so its wrist gets ahead of the shoulder as often as beside
it; but ahead it stays over the base, where no table can stand. The working direction
counts only wrist positions clear of the body's footprint (``robots/body_clearance.py``).
"""

from __future__ import annotations

import math

import pytest

from robocram.robots import ArmDescription, RobotModel
from robocram.robots.arm_envelope import working_yaw

LINK = '<link name="{0}"/>'
JOINT = (
    '<joint name="{0}" type="revolute"><parent link="{1}"/><child link="{2}"/>'
    '<origin xyz="{3}"/><axis xyz="{4}"/>'
    '<limit lower="-3.1" upper="3.1" velocity="1" effort="1"/></joint>'
)
CHAIN = (  # (joint, parent, child, origin, axis): a 0.6 m arm, its pan axis vertical
    ("pan", "base_link", "shoulder", "0 {y} 0.3", "0 0 1"),
    ("lift", "shoulder", "upper", "0 0 0.1", "0 1 0"),
    ("elbow", "upper", "fore", "0.3 0 0", "0 1 0"),
    ("wrist_1", "fore", "w1", "0.3 0 0", "0 1 0"),
    ("wrist_2", "w1", "w2", "0 0 0", "0 0 1"),
    ("wrist_3", "w2", "hand", "0 0 0", "1 0 0"),
)


def _robot(shoulder_y: float) -> RobotModel:
    base = (
        '<link name="base_link"><collision><origin xyz="0 0 0.15"/>'
        '<geometry><box size="1.2 0.5 0.3"/></geometry></collision></link>'
    )
    links = "".join(LINK.format(c) for _, _, c, _, _ in CHAIN)
    joints = "".join(
        JOINT.format(j, p, c, origin.format(y=shoulder_y), axis) for j, p, c, origin, axis in CHAIN
    )
    return RobotModel.from_string(f'<robot name="side">{base}{links}{joints}</robot>')


def _yaw(model: RobotModel) -> float:
    joints = tuple(j for j, *_ in CHAIN)
    return working_yaw(model, ArmDescription("arm", "hand", "hand", joints=joints))


def test_an_arm_on_the_right_side_of_a_long_base_works_to_the_right() -> None:
    assert _yaw(_robot(-0.2)) == pytest.approx(-math.pi / 2)


def test_on_the_left_side_it_works_to_the_left() -> None:
    assert _yaw(_robot(0.2)) == pytest.approx(math.pi / 2)
