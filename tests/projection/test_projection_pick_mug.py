"""Acceptance: one unchanged plan picks a mug on the PR2, the HSR and Boxy in projection,
and runs again in the recording environment."""

from __future__ import annotations

import math

import pytest

from robocram.designators import desig_equal
from robocram.execution import top_level
from robocram.grasping.grasp_model import LIFT
from robocram.logic import KnowledgeBase, using_kb
from robocram.plans import PlanSetupError, pick_up
from robocram.projection import recorded_robot, simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped
from robocram.world import World

POSITION_TOL = 0.01  # [m]
ANGLE_TOL = 0.05  # [rad]


def _assert_joints_within_limits(world: World, robot: str) -> None:
    for joint, value in world.joint_states(robot).items():
        limits = world.bodies.joint_limits(robot, joint)
        assert limits.lower - 1e-9 <= value <= limits.upper + 1e-9, (joint, value, limits)


def _in_map(world: World, robot: str, pose: PoseStamped) -> Pose:
    assert pose.frame_id == "map"  # targets stay put while a base that reaches moves
    return pose.pose


@pytest.mark.parametrize("robot", ["pr2", "hsrb", "boxy"])
def test_the_same_plan_picks_the_mug(robot: str) -> None:
    scene = tabletop_scene(robot)
    world = scene.world
    mug_before = world.pose("mug-1")
    with simulated_robot(world, robot) as run:
        result = pick_up(scene.look_target)
    assert run.tree.root.status.name == "SUCCEEDED"
    tool = world.link_pose(robot, result.tool_frame)
    lifted = _in_map(world, robot, result.lifted)
    assert tool.distance_to(lifted) < POSITION_TOL
    assert tool.angle_to(lifted) < ANGLE_TOL
    approach_down = tool.matrix()[:3, :3] @ [1.0, 0.0, 0.0]
    assert approach_down[2] == pytest.approx(-1.0, abs=0.01)  # top-down grasp
    _assert_joints_within_limits(world, robot)
    arm = world.robot(robot).description.arms[result.arm]
    assert world.bodies.attachments(robot) == {"mug-1": arm.end_effector_link}
    mug_after = world.pose("mug-1")
    grasp = _in_map(world, robot, result.grasp)
    dz_tool = lifted.position[2] - grasp.position[2]
    assert dz_tool == pytest.approx(LIFT, abs=1e-6)
    assert mug_after.position[2] - mug_before.position[2] == pytest.approx(dz_tool, abs=0.01)
    assert math.dist(mug_after.position[:2], mug_before.position[:2]) < POSITION_TOL
    fingers = world.joint_states(robot)[arm.gripper_joints[0]]
    assert (
        fingers > world.bodies.joint_limits(robot, arm.gripper_joints[0]).lower + 1e-3
    )  # holds it


def test_detection_is_equated_and_in_the_base_frame() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    world.set_pose("pr2", Pose((0.05, -0.02, 0.0), (0.0, 0.0, 0.0499792, 0.9987503)))
    mug = world.pose("mug-1")
    with simulated_robot(world, "pr2"):
        result = pick_up(scene.look_target)
    seen = result.detected
    assert desig_equal(seen, seen.first_desig())
    assert seen.first_desig() is not seen
    assert seen.get("name") == "mug-1" and seen.get("type") == "mug"
    pose = seen.get("pose")
    assert pose.frame_id == "base_footprint"
    expected = world.pose("pr2").inverse() * mug
    assert math.dist(pose.position, expected.position) < 1e-6


def test_the_same_plan_runs_in_the_recording_environment() -> None:
    mug = PoseStamped("base_footprint", (0.62, -0.15, 0.70))
    with recorded_robot("pr2", objects={"mug": mug}) as run:
        result = pick_up(PoseStamped("map", (0.6, -0.15, 0.7)))
    commands = [(module, term.name) for module, term in run.log]
    assert commands == [
        ("recorded_arms", "move_joints"),
        ("recorded_arms", "move_joints"),
        ("recorded_ptu", "move_head"),
        ("recorded_torso", "move_torso"),
        ("recorded_ptu", "move_head"),
        ("recorded_perception", "detect"),
        ("recorded_grippers", "move_gripper_joint"),
        ("recorded_arms", "move_tcp"),
        ("recorded_arms", "move_tcp"),
        ("recorded_grippers", "move_gripper_joint"),
        ("recorded_arms", "move_tcp"),
    ]
    assert run.log[3][1].args == (0.31,)
    assert [run.log[i][1].args[1] for i in (6, 9)] == ["open", "grip"]
    assert result.arm == "right"  # the nearer arm to a mug on the right
    # 4 cm under the top of the mug's box (which has pybullet's 3 mm collision margin)
    assert result.grasp.position == pytest.approx((0.62, -0.15, 0.763))
    assert result.lifted.position == pytest.approx((0.62, -0.15, 0.863))


def test_pick_up_in_an_environment_without_a_robot_says_how_to_run_it() -> None:
    kb = KnowledgeBase()
    with using_kb(kb), top_level(name="no-robot") as _, pytest.raises(PlanSetupError) as info:
        pick_up(PoseStamped("map", (0.6, -0.15, 0.7)))
    assert "simulated_robot" in str(info.value)
