"""Grippers follow their description: a three-finger hand without mimics opens, closes and
grips by contact; parallel grippers hold an object with their fingers on it, not closed."""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import pytest

from robocram.execution.failures import (
    GripperClosedCompletely,
    GripperGoalNotReached,
    GripperMetOneSide,
)
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.projection import ProjectedRobot
from robocram.projection.arm import move_tcp
from robocram.projection.gripper import close_gripper, grip, open_gripper, set_gripper
from robocram.robots import (
    ArmDescription,
    GripperDescription,
    GripperJoint,
    RobotDescription,
)
from robocram.robots.example_robot_data import example_robot_data_folder
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")
PALM_HEIGHT = 0.5  # [m] over the floor with the lift at 0
OPEN = {"proximal": -0.3, "distal": 0.0}  # [rad] fingers spread
CLOSED = {"proximal": 0.7, "distal": 0.7}  # [rad] fingers curled in to the centre


def _finger(i: int) -> str:
    angle = 2 * math.pi * i / 3
    x, y = 0.04 * math.cos(angle), 0.04 * math.sin(angle)
    box = (
        '<collision><origin xyz="0 0 -0.025"/>'
        '<geometry><box size="0.012 0.012 0.05"/></geometry></collision>'
    )
    limit = '<limit lower="-0.5" upper="1.2" velocity="1" effort="1"/>'
    return f"""
  <link name="f{i}_proximal">{box}</link>
  <link name="f{i}_distal">{box}</link>
  <joint name="f{i}_proximal_joint" type="revolute">
    <origin xyz="{x} {y} -0.01" rpy="0 0 {angle}"/><parent link="palm"/>
    <child link="f{i}_proximal"/><axis xyz="0 1 0"/>{limit}
  </joint>
  <joint name="f{i}_distal_joint" type="revolute">
    <origin xyz="0 0 -0.05"/><parent link="f{i}_proximal"/>
    <child link="f{i}_distal"/><axis xyz="0 1 0"/>{limit}
  </joint>"""


HAND_URDF = f"""<?xml version="1.0"?>
<robot name="claw">
  <link name="base_footprint"/>
  <link name="palm">
    <collision><geometry><box size="0.1 0.1 0.02"/></geometry></collision>
  </link>
  <link name="tool"/>
  <joint name="lift_joint" type="prismatic">
    <origin xyz="0 0 {PALM_HEIGHT}"/><parent link="base_footprint"/><child link="palm"/>
    <axis xyz="0 0 1"/><limit lower="0" upper="0.2" velocity="1" effort="1"/>
  </joint>
  <joint name="tool_joint" type="fixed">
    <origin xyz="0 0 -0.08" rpy="0 1.5707963267948966 0"/><parent link="palm"/>
    <child link="tool"/>
  </joint>
  {"".join(_finger(i) for i in range(3))}
</robot>
"""


def claw(tmp_path: Path) -> RobotDescription:
    """A one-"arm" lift with a three-finger hand whose fingers no URDF mimic couples."""
    path = tmp_path / "claw.urdf"
    path.write_text(HAND_URDF, encoding="utf-8")
    joints = tuple(
        GripperJoint(f"f{i}_{part}_joint", open=OPEN[part], closed=CLOSED[part])
        for i in range(3)
        for part in ("proximal", "distal")
    )
    hand = ArmDescription(
        name="hand",
        end_effector_link="palm",
        tool_frame="tool",
        base_link="base_footprint",
        gripper=GripperDescription(joints),
        parking={"lift_joint": 0.0},
    )
    return RobotDescription("claw", path, base_frame="base_footprint", arms={"hand": hand})


@pytest.fixture
def world() -> Iterator[World]:
    with World() as world:
        world.bodies.add_floor()
        yield world


def test_opening_and_closing_move_every_declared_finger_joint(world: World, tmp_path: Path) -> None:
    world.add_robot(claw(tmp_path))
    robot = ProjectedRobot.of(world, "claw")
    opened = open_gripper(robot, "hand")
    assert opened == pytest.approx({f"f{i}_{p}_joint": OPEN[p] for i in range(3) for p in OPEN})
    closed = close_gripper(robot, "hand")
    assert closed == pytest.approx({f"f{i}_{p}_joint": CLOSED[p] for i in range(3) for p in OPEN})
    half = set_gripper(robot, "hand", 0.2)  # the master f0_proximal_joint half way
    assert half["f2_distal_joint"] == pytest.approx(0.35)


def test_the_hand_grips_a_can_between_its_fingers_by_contact(world: World, tmp_path: Path) -> None:
    world.add_robot(claw(tmp_path))
    can = world.bodies.add_cylinder(
        "can", 0.025, 0.06, pose=(0.0, 0.0, PALM_HEIGHT - 0.06), mass=0.1
    )
    robot = ProjectedRobot.of(world, "claw")
    open_gripper(robot, "hand")
    assert grip(robot, "hand") == "can"
    assert world.bodies.attachments("claw") == {"can": "palm"}
    states = world.joint_states("claw")
    assert OPEN["proximal"] < states["f1_proximal_joint"] < CLOSED["proximal"] - 0.1  # on it
    for i in range(3):  # every finger touches the can, none sinks into it
        points = world.contacts.contact_points("claw", can, distance=0.005)
        gaps = [p.distance for p in points if p.link_a.startswith(f"f{i}_")]
        assert gaps and -0.002 < min(gaps) < 0.002


def test_closing_on_nothing_ends_fully_closed(world: World, tmp_path: Path) -> None:
    world.add_robot(claw(tmp_path))
    world.bodies.add_cylinder("can", 0.025, 0.06, pose=(0.3, 0.0, PALM_HEIGHT - 0.06), mass=0.1)
    robot = ProjectedRobot.of(world, "claw")
    open_gripper(robot, "hand")
    with pytest.raises(GripperClosedCompletely, match="closed on nothing") as info:
        grip(robot, "hand")
    assert info.value.position == pytest.approx(CLOSED["proximal"])
    assert world.bodies.attachments("claw") == {}


def test_a_position_beyond_open_is_clamped_and_reported(world: World, tmp_path: Path) -> None:
    world.add_robot(claw(tmp_path))
    robot = ProjectedRobot.of(world, "claw")
    with pytest.raises(GripperGoalNotReached, match=r"outside \[-0.3, 0.7\]") as info:
        set_gripper(robot, "hand", -0.45)
    assert info.value.reached == pytest.approx(-0.3)
    assert world.joint_states("claw")["f2_proximal_joint"] == pytest.approx(-0.3)


def test_the_pr2_holds_a_can_with_both_finger_tips_on_it(world: World) -> None:
    world.add_robot("pr2")
    robot = ProjectedRobot.of(world, "pr2")
    open_gripper(robot, "right")
    tool = world.link_pose("pr2", "r_gripper_tool_frame").position
    world.bodies.add_cylinder("can", 0.02, 0.1, pose=tool, mass=0.1)  # 4 cm across, fingers 9.4 cm
    assert grip(robot, "right") == "can"
    finger = world.joint_states("pr2")["r_gripper_l_finger_joint"]
    assert 0.05 < finger < 0.4  # stopped on the can, neither open (0.548) nor closed (0)
    for tip in ("r_gripper_l_finger_tip_link", "r_gripper_r_finger_tip_link"):
        points = world.contacts.contact_points("pr2", "can", link_a=tip, distance=0.005)
        assert points and -0.002 < min(p.distance for p in points) < 0.002


def test_the_allegro_hand_opens_and_closes_every_finger_it_declares(world: World) -> None:
    urdf = example_robot_data_folder() / "allegro_hand_description/urdf/allegro_right_hand.urdf"
    curls = [f"joint_{i}.0" for i in (1, 2, 3, 5, 6, 7, 9, 10, 11, 13, 14, 15)]
    gripper = GripperDescription(tuple(GripperJoint(j, open=0.0, closed=1.1) for j in curls))
    hand = ArmDescription(
        "hand", "palm_link", "palm_link", base_link="palm_link", gripper=gripper, parking={}
    )
    world.add_robot(RobotDescription("allegro", urdf, "palm_link", arms={"hand": hand}))
    robot = ProjectedRobot.of(world, "allegro")
    thumb_turn = world.joint_states("allegro")["joint_12.0"]
    close_gripper(robot, "hand")
    assert all(world.joint_states("allegro")[j] == pytest.approx(1.1) for j in curls)
    open_gripper(robot, "hand")  # no finger curls while "opening"
    assert all(world.joint_states("allegro")[j] == pytest.approx(0.0) for j in curls)
    assert world.joint_states("allegro")["joint_12.0"] == thumb_turn  # not declared: stays


def test_a_can_off_centre_is_met_on_one_side_and_gripped_once_the_hand_moves_by_the_shift(
    world: World,
) -> None:
    """The PR2's left finger meets a can 2.5 cm off the tool frame long before the right
    one: the grip fails naming how far to move the hand (half the misfit, towards the can's
    side), and after that move both tips squeeze it, neither deeper than 5 mm."""
    world.add_robot("pr2")
    robot = ProjectedRobot.of(world, "pr2")
    move_tcp(robot, "right", Pose((0.6, -0.25, 0.8)))  # well within reach, facing ahead
    open_gripper(robot, "right")
    tool = world.link_pose("pr2", "r_gripper_tool_frame")
    across = quat.rotate(tool.orientation, (0.0, 1.0, 0.0))  # the fingers close along y
    at = tuple(p + 0.025 * a for p, a in zip(tool.position, across, strict=True))
    world.bodies.add_cylinder("can", 0.02, 0.1, pose=at, mass=0.1)
    with pytest.raises(GripperMetOneSide, match="on one side only") as info:
        grip(robot, "right")
    assert world.bodies.attachments("pr2") == {}  # the fingers did not move
    shift = info.value.shift
    assert shift is not None
    assert sum(s * a for s, a in zip(shift, across, strict=True)) == pytest.approx(0.025, abs=0.004)
    moved = tuple(p + s for p, s in zip(tool.position, shift, strict=True))
    move_tcp(robot, "right", Pose(moved, tool.orientation), collision_mode="allow_hand")
    assert grip(robot, "right") == "can"
    for tip in ("r_gripper_l_finger_tip_link", "r_gripper_r_finger_tip_link"):
        points = world.contacts.contact_points("pr2", "can", link_a=tip, distance=0.005)
        assert points and min(p.distance for p in points) > -HAND_CONTACT_DEPTH
