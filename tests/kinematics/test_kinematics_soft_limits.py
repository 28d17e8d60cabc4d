"""IK keeps to the ``<safety_controller>`` soft limits where a URDF has them (the PR2's),
since the real robot's controllers stop the joints there; elsewhere the hard limits."""

from __future__ import annotations

import pytest

from robocram.kinematics import IKSolver, forward_kinematics, solve_ik
from robocram.robots import RobotDescription, load_description

TOOL = "r_gripper_tool_frame"
# A right-arm pose with the wrist flexed less than its soft upper limit (-0.1) allows
NEAR_STRAIGHT_WRIST = {
    "r_shoulder_pan_joint": -0.3,
    "r_shoulder_lift_joint": 0.3,
    "r_upper_arm_roll_joint": 0.0,
    "r_elbow_flex_joint": -1.0,
    "r_forearm_roll_joint": 0.0,
    "r_wrist_flex_joint": -0.04,
    "r_wrist_roll_joint": 0.0,
}
REACHED = 0.01  # [m]


@pytest.fixture(scope="module")
def pr2() -> RobotDescription:
    return load_description("pr2")


def test_the_pr2_urdf_gives_soft_limits_inside_the_hard_ones(pr2: RobotDescription) -> None:
    assert pr2.model is not None
    wrist = pr2.model.joints["r_wrist_flex_joint"]
    assert (wrist.lower, wrist.upper) == pytest.approx((-2.094, 0.0))
    assert wrist.working_limits == pytest.approx((-1.994, -0.1))
    torso = pr2.model.joints["torso_lift_joint"]
    assert torso.working_limits == pytest.approx((0.0115, 0.305))
    hsrb = load_description("hsrb").model
    assert hsrb is not None
    lift = hsrb.joints["arm_lift_joint"]
    assert lift.working_limits == (lift.lower, lift.upper)  # no safety_controller: hard


def test_ik_bounds_are_the_soft_limits(pr2: RobotDescription) -> None:
    solver = IKSolver(pr2, "right")
    k = solver.variables.index("r_wrist_flex_joint")
    assert solver.chain.upper[k] == pytest.approx(-0.1)


def test_ik_solutions_stay_inside_the_soft_limits(pr2: RobotDescription) -> None:
    target = forward_kinematics(pr2, NEAR_STRAIGHT_WRIST, TOOL)
    result = solve_ik(pr2, "right", target, seed=NEAR_STRAIGHT_WRIST)
    assert result.success
    assert pr2.model is not None
    for joint, value in result.joint_positions.items():
        low, high = pr2.model.joints[joint].working_limits
        if low is not None and high is not None:
            assert low - 1e-9 <= value <= high + 1e-9, joint
    reached = forward_kinematics(pr2, dict(result.joint_positions), TOOL)
    assert reached.distance_to(target) < REACHED
