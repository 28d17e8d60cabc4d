"""IK on real robot descriptions: PR2 and HSR from their URDFs, a small mimic arm in text."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from robocram.kinematics import (
    IKOptions,
    IKSettings,
    IKSolver,
    KinematicsError,
    TargetFrameError,
    UnknownNameError,
    forward_kinematics,
    solve_ik,
)
from robocram.robots import ArmDescription, RobotDescription, RobotModel, load_description
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

TOOL = "r_gripper_tool_frame"


@pytest.fixture(scope="module")
def pr2() -> RobotDescription:
    return load_description("pr2")


def _random_config(solver: IKSolver, rng: np.random.Generator) -> dict[str, float]:
    lo = np.where(np.isfinite(solver.chain.lower), solver.chain.lower, -math.pi)
    hi = np.where(np.isfinite(solver.chain.upper), solver.chain.upper, math.pi)
    return dict(zip(solver.variables, rng.uniform(lo, hi), strict=True))


def _within_limits(desc: RobotDescription, joints: dict[str, float]) -> bool:
    assert desc.model is not None
    for name, value in joints.items():
        j = desc.model.joints[name]
        if j.lower is not None and not j.lower - 1e-9 <= value <= j.upper + 1e-9:  # type: ignore[operator]
            return False
    return True


def test_fk_round_trips_within_limits(pr2: RobotDescription) -> None:
    solver = IKSolver.cached(pr2, "right")
    rng = np.random.default_rng(42)
    for _ in range(25):
        truth = _random_config(solver, rng)
        target = forward_kinematics(pr2, truth, TOOL)
        result = solve_ik(pr2, "right", target)
        assert result.success and bool(result)
        assert set(result.joint_positions) == set(pr2.arms["right"].joints)
        reached = forward_kinematics(pr2, result.joint_positions, TOOL)
        assert reached.distance_to(target) < 1e-3
        assert reached.angle_to(target) < 1e-2
        assert result.position_error == pytest.approx(reached.distance_to(target), abs=1e-9)
        assert _within_limits(pr2, dict(result.joint_positions))


def test_known_pose_of_the_tool_frame(pr2: RobotDescription) -> None:
    # all arm joints at 0, torso down: the PR2 URDF puts the right tool frame at
    # x = 0.05 (torso) + 0.1 (upper arm) + 0.4 + 0.321 + 0.18 (wrist to tool) = 0.951 m,
    # y = -0.188 m, z = 0.739675 + 0.051 (base) = 0.790675 m, axis-aligned.
    pose = forward_kinematics(pr2, {}, TOOL)
    assert pose.position == pytest.approx((0.951, -0.188, 0.790675), abs=1e-6)
    assert pose.angle_to(Pose()) < 1e-9


def test_unreachable_target_fails_within_its_budget(pr2: RobotDescription) -> None:
    result = solve_ik(
        pr2, "right", Pose((5.0, 0.0, 1.0)), options=IKOptions(max_restarts=20, max_iterations=30)
    )
    assert not result.success and not result
    assert result.restarts <= 20 and result.iterations <= 21 * 30
    assert result.position_error > 3.5  # the arm reaches about 1.2 m from the base
    assert _within_limits(pr2, dict(result.joint_positions))


def test_torso_moves_when_the_target_is_too_high(pr2: RobotDescription) -> None:
    seed = {"torso_lift_joint": 0.0}
    # elbow and wrist bent inside their soft limits (a straight PR2 arm is beyond them)
    bent = {"r_elbow_flex_joint": -0.5, "r_wrist_flex_joint": -0.3}
    high = forward_kinematics(
        pr2, {"torso_lift_joint": 0.3, "r_shoulder_lift_joint": -0.3, **bent}, TOOL
    )
    assert not solve_ik(pr2, "right", high, seed=seed)
    result = solve_ik(pr2, "right", high, seed=seed, options=IKOptions(use_torso=True))
    assert result.success
    assert result.joint_positions["torso_lift_joint"] > 0.1
    reached = forward_kinematics(pr2, result.joint_positions, TOOL)
    assert reached.distance_to(high) < 1e-3 and _within_limits(pr2, dict(result.joint_positions))


def test_held_torso_comes_from_the_seed(pr2: RobotDescription) -> None:
    config = {"torso_lift_joint": 0.2, "r_elbow_flex_joint": -1.0, "r_shoulder_pan_joint": -0.4}
    target = forward_kinematics(pr2, config, TOOL)
    result = solve_ik(pr2, "right", target, seed={"torso_lift_joint": 0.2})
    assert result.success and "torso_lift_joint" not in result.joint_positions
    reached = forward_kinematics(pr2, {**result.joint_positions, "torso_lift_joint": 0.2}, TOOL)
    assert reached.distance_to(target) < 1e-3


def test_stamped_target_in_a_robot_link(pr2: RobotDescription) -> None:
    seed = {"torso_lift_joint": 0.1}
    in_root = forward_kinematics(pr2, {**seed, "r_elbow_flex_joint": -0.8}, TOOL)
    torso_in_root = forward_kinematics(pr2, seed, "torso_lift_link")
    target = PoseStamped.from_pose("torso_lift_link", torso_in_root.inverse() * in_root)
    result = solve_ik(pr2, "right", target, seed=seed)
    assert result.success
    reached = forward_kinematics(pr2, {**seed, **result.joint_positions}, TOOL)
    assert reached.distance_to(in_root) < 1e-3
    with pytest.raises(TargetFrameError, match=r"'map'.*transform_pose"):
        solve_ik(pr2, "right", PoseStamped("map", (0.5, 0, 1)))


def test_collision_check_rejections_force_restarts(pr2: RobotDescription) -> None:
    target = forward_kinematics(pr2, {"r_elbow_flex_joint": -1.2, "r_wrist_flex_joint": -0.6}, TOOL)
    seen: list[dict[str, float]] = []

    def elbow_up_collides(joints: dict[str, float]) -> bool:
        seen.append(joints)
        return joints["r_upper_arm_roll_joint"] > -1.0  # pretend only rolled elbows are free

    result = solve_ik(pr2, "right", target, collision_check=elbow_up_collides)
    assert result.success
    assert result.rejected_in_collision >= 1 and result.restarts >= 1
    assert len(seen) == result.rejected_in_collision + 1
    assert result.joint_positions["r_upper_arm_roll_joint"] <= -1.0
    assert forward_kinematics(pr2, result.joint_positions, TOOL).distance_to(target) < 1e-3


def test_always_colliding_fails_after_restarts(pr2: RobotDescription) -> None:
    target = forward_kinematics(pr2, {"r_elbow_flex_joint": -1.2}, TOOL)
    result = solve_ik(
        pr2, "right", target, options=IKOptions(max_restarts=5), collision_check=lambda j: True
    )
    assert not result.success and result.restarts == 5 and result.rejected_in_collision >= 1


def test_bad_names(pr2: RobotDescription) -> None:
    with pytest.raises(UnknownNameError, match=r"arm 'rigth' not in pr2; did you mean 'right'"):
        solve_ik(pr2, "rigth", Pose((0.5, 0, 1)))
    with pytest.raises(UnknownNameError, match="r_gripper_tool_frame"):
        solve_ik(pr2, "right", Pose((0.5, 0, 1)), options=IKOptions(frame="r_gripper_tool_fram"))
    with pytest.raises(UnknownNameError, match="r_elbow_flex_joint"):
        forward_kinematics(pr2, {"r_elbow_flex": 0.1}, TOOL)
    quad = load_description("quadrotor")
    with pytest.raises(UnknownNameError, match="arm 'arm' not in quadrotor"):
        solve_ik(quad, "arm", Pose())


def test_hsr_torso_mimic_follows_arm_lift() -> None:
    hsr = load_description("hsr")
    assert hsr.torso_joint == "arm_lift_joint"
    truth = {"arm_lift_joint": 0.4, "arm_flex_joint": -0.8, "wrist_flex_joint": -0.7}
    target = forward_kinematics(hsr, truth, "hand_tool_frame")
    result = solve_ik(hsr, "arm", target, options=IKOptions(use_torso=True))
    assert result.success
    lift = result.joint_positions["arm_lift_joint"]
    assert result.joint_positions["torso_lift_joint"] == pytest.approx(0.5 * lift)
    reached = forward_kinematics(hsr, result.joint_positions, "hand_tool_frame")
    assert reached.distance_to(target) < 1e-3 and reached.angle_to(target) < 1e-2


MIMIC_ARM = """<robot name="mimic_arm">
  <link name="base"/><link name="l1"/><link name="l2"/><link name="tip"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="l1"/>
    <axis xyz="0 0 1"/><limit lower="-1.5" upper="1.5" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="l1"/><child link="l2"/>
    <origin xyz="0.5 0 0"/><axis xyz="0 0 1"/>
    <limit lower="-1.0" upper="1.0" effort="1" velocity="1"/>
    <mimic joint="j1" multiplier="2.0" offset="0.1"/></joint>
  <joint name="j3" type="revolute"><parent link="l2"/><child link="tip"/>
    <origin xyz="0.4 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>"""


@pytest.fixture(scope="module")
def mimic_arm(tmp_path_factory: pytest.TempPathFactory) -> RobotDescription:
    folder = tmp_path_factory.mktemp("mimic")
    model = RobotModel.from_string(MIMIC_ARM, folder)
    arm = ArmDescription("arm", end_effector_link="tip", tool_frame="tip", base_link="base")
    return load_description(
        RobotDescription("mimic_arm", "", "base", arms={"arm": arm}, model=model)
    )


def test_mimic_follower_on_the_chain(mimic_arm: RobotDescription) -> None:
    # j2 = 2 j1 + 0.1 and must stay in [-1, 1], so j1 is confined to [-0.55, 0.45].
    solver = IKSolver.cached(mimic_arm, "arm")
    assert solver.variables == ("j1", "j3")
    assert solver.chain.lower[0] == pytest.approx(-0.55) and solver.chain.upper[0] == pytest.approx(
        0.45
    )
    target = forward_kinematics(mimic_arm, {"j1": 0.3, "j3": 0.5}, "tip")
    assert target.position[1] == pytest.approx(
        0.5 * math.sin(0.3) + 0.4 * math.sin(0.3 + 0.7)  # l2 turned by j1 + j2
    )
    result = solve_ik(mimic_arm, "arm", target, seed={"j1": -0.5, "j3": -0.5})
    assert result.success
    assert result.joint_positions["j1"] == pytest.approx(0.3, abs=1e-3)
    assert result.joint_positions["j2"] == pytest.approx(0.7, abs=2e-3)
    assert result.joint_positions["j3"] == pytest.approx(0.5, abs=1e-2)
    with pytest.raises(KinematicsError, match="no torso joint"):
        solve_ik(mimic_arm, "arm", target, options=IKOptions(use_torso=True))


def test_mimic_target_only_reachable_beyond_follower_limit(mimic_arm: RobotDescription) -> None:
    # j1 = 0.5 would put j2 at 1.1, past its limit: the solver must not go there.
    target = forward_kinematics(mimic_arm, {"j1": 0.5, "j2": 1.1, "j3": 0.0}, "tip")
    result = solve_ik(mimic_arm, "arm", target, options=IKOptions(max_restarts=10))
    assert not result.success
    assert result.joint_positions["j2"] <= 1.0 + 1e-9


def test_continuous_joints_wrap_near_the_seed(pr2: RobotDescription) -> None:
    seed = {"r_forearm_roll_joint": 6.0, "r_wrist_roll_joint": -6.0}
    bent = {"r_elbow_flex_joint": -0.5, "r_wrist_flex_joint": -0.3}  # inside the soft limits
    target = forward_kinematics(
        pr2, {"r_forearm_roll_joint": 6.1, "r_wrist_roll_joint": -6.2, **bent}, TOOL
    )
    result = solve_ik(pr2, "right", target, seed=seed)
    assert result.success
    assert abs(result.joint_positions["r_forearm_roll_joint"] - 6.0) <= math.pi
    assert abs(result.joint_positions["r_wrist_roll_joint"] + 6.0) <= math.pi
    assert (
        quat.angle_between(
            forward_kinematics(pr2, result.joint_positions, TOOL).orientation, target.orientation
        )
        < 1e-2
    )


def test_same_random_seed_same_answer(pr2: RobotDescription) -> None:
    # refusing every solution spends the whole budget, the last descents from random starts
    target = forward_kinematics(pr2, {"r_elbow_flex_joint": -1.2}, TOOL)
    runs = [
        solve_ik(
            pr2,
            "right",
            target,
            options=IKOptions(max_restarts=8, random_seed=s),
            collision_check=lambda j: True,
        )
        for s in (3, 3, 4)
    ]
    assert runs[0].joint_positions == runs[1].joint_positions
    assert runs[0].iterations == runs[1].iterations
    assert runs[0].joint_positions != runs[2].joint_positions


def test_options_default_to_the_descents_settings() -> None:
    """IKOptions() asks what the descent's defaults ask: no budget or tolerance changes."""
    defaults = IKSettings()
    assert IKOptions().settings() == defaults
    assert IKOptions(max_restarts=3).settings().max_restarts == 3
    with pytest.raises(dataclasses.FrozenInstanceError):
        IKOptions().use_torso = True  # type: ignore[misc]
