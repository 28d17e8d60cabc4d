"""The reach bound: a necessary condition that never rules out a reachable target."""

from __future__ import annotations

import math

import numpy as np
import pytest

from robocram.kinematics import IKOptions, IKSolver, forward_kinematics, reachable, solve_ik
from robocram.kinematics.seed_table import random_configurations
from robocram.robots import RobotDescription, load_description
from robocram.tf import Pose

TOOL = "r_gripper_tool_frame"


@pytest.fixture(scope="module")
def pr2() -> RobotDescription:
    return load_description("pr2")


def test_pr2_arm_length_from_its_urdf(pr2: RobotDescription) -> None:
    # shoulder lift 0.1 + upper arm 0.4 + forearm 0.321 + wrist to tool 0.18 [m]
    bound = IKSolver.cached(pr2, "right").reach
    assert bound.radius == pytest.approx(1.001, abs=1e-9)
    assert tuple(bound.start) == pytest.approx((0.0, -0.188, 0.0))  # in the torso frame
    torso = IKSolver.cached(pr2, "right", use_torso=True).reach
    lift = pr2.model.joints["torso_lift_joint"]  # type: ignore[union-attr]
    assert torso.end[2] - torso.start[2] == pytest.approx(lift.upper - lift.lower)  # type: ignore[operator]


@pytest.mark.parametrize(
    ("robot", "arm", "use_torso"),
    [("pr2", "right", True), ("hsrb", "arm", True), ("boxy", "left", False)],
)
def test_every_sampled_pose_lies_inside_the_bound(robot: str, arm: str, use_torso: bool) -> None:
    desc = load_description(robot)
    solver = IKSolver.cached(desc, arm, use_torso)
    rng = np.random.default_rng(3)
    xs = random_configurations(solver.chain, rng, 200, np.zeros(len(solver.variables)))
    for x in xs:
        joints = dict(zip(solver.variables, x.tolist(), strict=True))
        tool = forward_kinematics(desc, joints, solver.frame)
        assert reachable(desc, arm, tool, options=IKOptions(use_torso=use_torso))
        _, in_base, _ = solver.locate(tool, joints)
        assert solver.reach.distance_outside(in_base.translation) <= 1e-9
        assert solver.reach.pose_outside(in_base) <= 1e-9


def test_pr2_wrist_lies_behind_the_tool_within_the_shorter_radius(pr2: RobotDescription) -> None:
    bound = IKSolver.cached(pr2, "right").reach
    assert tuple(bound.wrist) == pytest.approx((-0.18, 0.0, 0.0))  # the wrist flex joint
    assert bound.wrist_radius == pytest.approx(0.821, abs=1e-9)  # 0.1 + 0.4 + 0.321 [m]


def test_a_top_grasp_beyond_the_wrist_reach_fails_without_a_descent(pr2: RobotDescription) -> None:
    shoulder = forward_kinematics(pr2, {}, "r_shoulder_pan_link").position
    down = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))  # the tool's x axis points down
    # the tool is within 1.001 m of the shoulder, its wrist 0.18 m above it is not
    top = Pose((shoulder[0] + 0.78, shoulder[1], shoulder[2] + 0.2), down)
    assert reachable(pr2, "right", Pose(top.position))
    assert not reachable(pr2, "right", top)
    result = solve_ik(pr2, "right", top)
    assert not result.success and result.iterations == 0
    assert result.beyond_reach == pytest.approx(math.hypot(0.78, 0.38) - 0.821, abs=1e-6)


def test_beyond_reach_fails_without_a_descent(pr2: RobotDescription) -> None:
    shoulder = forward_kinematics(pr2, {}, "r_shoulder_pan_link").position
    far = Pose((shoulder[0] + 1.05, shoulder[1], shoulder[2]))
    assert not reachable(pr2, "right", far)
    assert reachable(pr2, "right", Pose((shoulder[0] + 0.95, shoulder[1], shoulder[2])))
    seed = {"r_elbow_flex_joint": -0.5, "r_shoulder_pan_joint": 0.3}
    result = solve_ik(pr2, "right", far, seed=seed)
    assert not result.success and result.restarts == 0 and result.iterations == 0
    assert result.position_error == pytest.approx(
        forward_kinematics(pr2, result.joint_positions, TOOL).distance_to(far), abs=1e-9
    )
    for joint, value in seed.items():  # the answer is the seed itself
        assert result.joint_positions[joint] == value


def test_torso_extends_the_reach(pr2: RobotDescription) -> None:
    high = forward_kinematics(pr2, {"torso_lift_joint": 0.33, "r_shoulder_lift_joint": -1.2}, TOOL)
    above = Pose((high.position[0], high.position[1], high.position[2] + 0.2), high.orientation)
    assert not reachable(pr2, "right", above, seed={"torso_lift_joint": 0.0})
    assert reachable(
        pr2, "right", above, seed={"torso_lift_joint": 0.0}, options=IKOptions(use_torso=True)
    )
    assert not math.isclose(IKSolver.cached(pr2, "right", True).reach.radius, 1.001)


def test_a_near_miss_of_the_wrist_still_gets_the_nearest_configuration(
    pr2: RobotDescription,
) -> None:
    shoulder = forward_kinematics(pr2, {}, "r_shoulder_pan_link").position
    down = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))
    wrist_out = 0.005  # [m] beyond the wrist's reach: a near miss, not ruled out
    along = math.sqrt((0.821 + wrist_out) ** 2 - 0.38**2)
    near = Pose((shoulder[0] + along, shoulder[1], shoulder[2] + 0.2), down)
    assert reachable(pr2, "right", near)
    result = solve_ik(pr2, "right", near)
    assert not result.success and result.iterations > 0  # descended: the nearest found
    assert result.beyond_reach == pytest.approx(wrist_out, abs=1e-6)
