"""Robots in the world: joint limits, mimic joints, names, link frames and attachments."""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.kinematics import IKOptions, forward_kinematics, solve_ik
from robocram.tf import Pose
from robocram.world import (
    ClampedJoint,
    NotARobotError,
    RobotHandle,
    RobotObject,
    UnknownJointError,
    UnknownLinkError,
    UnknownObjectError,
    World,
)


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("pr2")
        yield w


@pytest.fixture
def pr2(world: World) -> Iterator[RobotObject]:
    with world.snapshots.stored_state():
        yield world.robot("pr2")


def test_robot_is_indexed_by_name(world: World, pr2: RobotObject) -> None:
    assert pr2.type == "robot" and pr2.is_static
    assert pr2.link_index["base_footprint"] == -1
    assert "r_gripper_tool_frame" in world.link_names(pr2)
    assert len(world.joint_states(pr2)) == 30  # movable joints of the example-robot-data PR2
    assert world.contacts.collisions(pr2) == []  # standing on the floor is not touching it


def test_a_handle_carries_the_robot_looked_up_once(world: World, pr2: RobotObject) -> None:
    handle = RobotHandle.of(world, "pr2")
    assert handle.body is pr2 and handle.world is world and handle.name == "pr2"
    assert RobotHandle.of(world, handle) is handle and RobotHandle.of(world, pr2) == handle
    assert handle.model.root_link == "base_footprint" == handle.base_frame
    assert handle.model is handle.description.model and handle.drive == "holonomic"
    assert set(handle.arms) == {"left", "right"} == set(handle.grippers)
    assert handle.grippers["right"].joints[0].name == "r_gripper_l_finger_joint"
    assert handle.camera is not None and handle.camera.frame == "wide_stereo_optical_frame"
    assert handle.joint_states() == world.joint_states("pr2")
    with pytest.raises(AttributeError):
        handle.body = pr2  # type: ignore[misc]
    with pytest.raises(UnknownObjectError, match="pr"):
        RobotHandle.of(world, "pr")
    with pytest.raises(NotARobotError):
        RobotHandle.of(world, "floor")


def test_ik_takes_the_handle_as_its_robot(world: World, pr2: RobotObject) -> None:
    handle = RobotHandle.of(world, pr2)
    seed = handle.joint_states()
    bent = {**seed, "r_elbow_flex_joint": -1.0}
    target = forward_kinematics(handle, bent, "r_gripper_tool_frame")
    options = IKOptions(random_seed=5, use_torso=True)
    by_handle = solve_ik(handle, "right", target, seed=seed, options=options)
    by_description = solve_ik(pr2.description, "right", target, seed=seed, options=options)
    assert by_handle.success and by_handle.position_error < 1e-3
    assert by_handle.joint_positions == by_description.joint_positions  # bit for bit


def test_out_of_range_torso_is_clamped_and_reported(world: World, pr2: RobotObject) -> None:
    clamped = world.set_joint_states(pr2, {"torso_lift_joint": 1.0, "head_pan_joint": 0.2})
    assert clamped == [ClampedJoint("torso_lift_joint", 1.0, 0.31, 0.0, 0.31)]
    states = world.joint_states(pr2)
    assert states["torso_lift_joint"] == pytest.approx(0.31, abs=1e-9)
    assert states["head_pan_joint"] == pytest.approx(0.2, abs=1e-9)
    assert world.bodies.joint_limits(pr2, "torso_lift_joint").upper == pytest.approx(0.31)


def test_continuous_joints_are_never_clamped(world: World, pr2: RobotObject) -> None:
    limits = world.bodies.joint_limits(pr2, "r_wrist_roll_joint")
    assert limits.lower == -math.inf and limits.upper == math.inf
    assert world.set_joint_states(pr2, {"r_wrist_roll_joint": 7.5}) == []
    assert world.joint_states(pr2)["r_wrist_roll_joint"] == pytest.approx(7.5)


def test_gripper_mimic_joints_follow_their_master(world: World, pr2: RobotObject) -> None:
    world.set_joint_states(pr2, {"l_gripper_l_finger_joint": 0.4})
    states = world.joint_states(pr2)
    for follower in ("r_finger", "l_finger_tip", "r_finger_tip"):
        assert states[f"l_gripper_{follower}_joint"] == pytest.approx(0.4, abs=1e-9)
    assert states["r_gripper_r_finger_joint"] == pytest.approx(0.0)  # the other hand stays


def test_torso_moves_the_camera_link_up(world: World, pr2: RobotObject) -> None:
    low = world.link_pose(pr2, "wide_stereo_optical_frame").position[2]
    world.set_joint_states(pr2, {"torso_lift_joint": 0.3})
    high = world.link_pose(pr2, "wide_stereo_optical_frame").position[2]
    assert high - low == pytest.approx(0.3, abs=1e-6)


def test_unknown_names_raise_with_suggestions(world: World, pr2: RobotObject) -> None:
    with pytest.raises(UnknownJointError, match="did you mean 'torso_lift_joint'"):
        world.set_joint_states(pr2, {"torso_lift": 0.1})
    with pytest.raises(UnknownJointError, match="fixed"):
        world.set_joint_states(pr2, {"head_plate_frame_joint": 0.1})
    with pytest.raises(UnknownLinkError, match="did you mean 'r_gripper_tool_frame'"):
        world.link_pose(pr2, "r_gripper_tool")
    with pytest.raises(ValueError, match="finite"):
        world.set_joint_states(pr2, {"torso_lift_joint": math.nan})
    with pytest.raises(NotARobotError):
        world.robot("floor")


def test_attached_object_follows_joints_base_and_simulation(world: World, pr2: RobotObject) -> None:
    tool = world.link_pose(pr2, "r_gripper_tool_frame")
    cup = world.add_item("cup", "cup", tool * Pose((0.02, 0, 0)))
    world.attach(cup, pr2, "r_gripper_tool_frame")
    assert world.bodies.attachments(pr2) == {"cup": "r_gripper_tool_frame"}
    assert world.contacts.collisions(pr2) == [] and not world.contacts.contact(cup, pr2)
    world.set_joint_states(pr2, {"r_shoulder_pan_joint": -0.8, "torso_lift_joint": 0.2})
    world.set_pose(pr2, Pose((1.0, 0.5, 0), (0, 0, math.sin(0.3), math.cos(0.3))))
    world.physics.simulate(0.5)
    expected = world.link_pose(pr2, "r_gripper_tool_frame") * Pose((0.02, 0, 0))
    assert world.pose(cup).distance_to(expected) < 1e-6
    assert world.pose(cup).angle_to(expected) < 1e-6
    world.detach(cup)
    world.physics.simulate(0.5)
    assert world.pose(cup).position[2] < expected.position[2] - 0.05  # now it falls
    assert world.bodies.attachments(pr2) == {}


@pytest.mark.parametrize("name", ["hsrb", "boxy", "quadrotor"])
def test_other_builtin_robots_spawn_and_hold_still(name: str) -> None:
    with World() as world:
        world.bodies.add_floor()
        robot = world.add_robot(name, Pose((0, 0, 1.0 if name == "quadrotor" else 0.0)))
        before = world.joint_states(robot)
        world.physics.simulate(0.2)
        assert world.joint_states(robot) == pytest.approx(before, abs=1e-9)
        assert world.pose(robot).position == pytest.approx((0, 0, world.pose(robot).position[2]))
        assert not world.contacts.in_collision(robot)  # standing on the floor does not count
        for cam in robot.description.cameras:
            assert world.view.camera(robot, cam.name).pose.position[2] > 0.1


def test_robots_start_with_every_joint_within_its_limits() -> None:
    with World() as world:
        boxy = world.add_robot("boxy")
        states = world.joint_states(boxy)
        for name, value in states.items():
            limits = world.bodies.joint_limits(boxy, name)
            assert limits.lower - 1e-9 <= value <= limits.upper + 1e-9, name
        assert states["left_gripper_joint"] == pytest.approx(0.0065, abs=1e-9)  # 0 is outside
        assert states["left_gripper_base_gripper_left_joint"] == pytest.approx(-0.00325, abs=1e-9)


def test_a_joint_let_go_is_stiff_again_after_being_held() -> None:
    """Held joints simulate without their motors; one no longer held gets its motor back
    (without it the shoulder would fall ~0.6 rad in 0.3 s)."""
    with World() as world:
        world.bodies.add_floor()
        pr2 = world.add_robot("pr2")
        world.physics.simulate(0.05)  # every joint held: their motors are off
        held = world.snapshots.held_joints(pr2)
        del held["r_shoulder_lift_joint"]
        world.snapshots.set_held_joints(pr2, held)
        world.physics.simulate(0.3)
        assert world.joint_states(pr2)["r_shoulder_lift_joint"] == pytest.approx(0.0, abs=0.01)
        assert world.joint_states(pr2)["l_shoulder_lift_joint"] == 0.0  # still held exactly
