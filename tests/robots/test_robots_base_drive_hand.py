"""A lone arm ending in a hand of several fingers is drafted fixed; a second arm is not a
finger (zoo13: the Panda's two fingers made it a mobile base with a doubt)."""

from __future__ import annotations

import pytest

from robocram.robots.draft.base_drive import find_base_drive
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.robot_model import RobotModel

BOX = '<collision><geometry><box size="{s} {s} 0.1"/></geometry></collision>'


def _urdf(branch_length: float, mount: float = 0.2) -> str:
    """A mount, three revolute joints in a chain, then two branches ``branch_length``
    [m] long off the last link (each a prismatic and a revolute joint)."""
    links = [f'<link name="mount">{BOX.format(s=mount)}</link>']
    joints = []
    parent = "mount"
    for i in range(3):
        links.append(f'<link name="l{i}">{BOX.format(s=0.05)}</link>')
        joints.append(
            f'<joint name="j{i}" type="revolute"><parent link="{parent}"/>'
            f'<child link="l{i}"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>'
            '<limit lower="-2" upper="2" effort="1" velocity="1"/></joint>'
        )
        parent = f"l{i}"
    for side, y in (("a", 0.03), ("b", -0.03)):
        links += [f'<link name="{side}1"/>', f'<link name="{side}2"/>']
        joints.append(
            f'<joint name="{side}_slide" type="prismatic"><parent link="{parent}"/>'
            f'<child link="{side}1"/><origin xyz="0 {y} 0.05"/><axis xyz="0 1 0"/>'
            '<limit lower="0" upper="0.04" effort="1" velocity="1"/></joint>'
        )
        joints.append(
            f'<joint name="{side}_tip" type="revolute"><parent link="{side}1"/>'
            f'<child link="{side}2"/><origin xyz="0 0 {branch_length}"/><axis xyz="1 0 0"/>'
            '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
        )
    return f'<?xml version="1.0"?><robot name="r">{"".join(links + joints)}</robot>'


def _drive(urdf: str) -> tuple[str, str]:
    drive = find_base_drive(ModelTree(RobotModel.from_string(urdf)))
    return drive.base_type, drive.why


def test_one_chain_ending_in_a_hands_fingers_is_a_fixed_arm() -> None:
    kind, why = _drive(_urdf(branch_length=0.05))
    assert kind == "fixed"
    assert "one chain of 3 joints ending in a hand of 2 fingers" in why


@pytest.mark.parametrize(
    ("branch_length", "mount"),
    [
        (0.5, 0.2),  # two arms off a torso: a second arm is no finger
        (0.05, 0.6),  # a hand's fingers, but on a platform: a mobile base undriven
    ],
)
def test_two_arms_or_a_wide_platform_stay_holonomic(branch_length: float, mount: float) -> None:
    kind, why = _drive(_urdf(branch_length, mount))
    assert kind == "holonomic"
    assert "the default" in why


def _on_a_pedestal(stand: str) -> str:
    """Two arms off a torso (no lone arm), the torso rigid on a link named ``stand``."""
    urdf = _urdf(branch_length=0.5)
    extra = (
        f'<link name="{stand}">{BOX.format(s=0.6)}</link><joint name="stand_fixed" '
        f'type="fixed"><parent link="mount"/><child link="{stand}"/></joint></robot>'
    )
    return urdf.replace("</robot>", extra)


def test_a_robot_on_a_pedestal_is_fixed_unless_a_link_says_mobile_base() -> None:
    """Baxter stands on its ``pedestal``; a link named like a mobile base overrides it."""
    kind, why = _drive(_on_a_pedestal("pedestal"))
    assert kind == "fixed"
    assert "stands on pedestal" in why
    assert _drive(_on_a_pedestal("pedestal_mobile_base"))[0] == "holonomic"
