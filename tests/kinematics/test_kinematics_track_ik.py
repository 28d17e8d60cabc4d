"""Tracking a line of tool poses: the answers of one descent each from the answer before."""

from __future__ import annotations

import pytest

from robocram.kinematics import IKOptions, forward_kinematics, solve_ik, track_ik
from robocram.robots import RobotDescription, load_description
from robocram.tf import Pose

TOOL = "r_gripper_tool_frame"
SEED = {
    "torso_lift_joint": 0.1,
    "r_shoulder_pan_joint": -0.4,
    "r_shoulder_lift_joint": 0.3,
    "r_upper_arm_roll_joint": -0.6,
    "r_elbow_flex_joint": -1.2,
    "r_forearm_roll_joint": 0.4,
    "r_wrist_flex_joint": -0.9,
    "r_wrist_roll_joint": 0.2,
}


@pytest.fixture(scope="module")
def pr2() -> RobotDescription:
    return load_description("pr2")


def _line(pr2: RobotDescription, steps: int, step: float) -> list[Pose]:
    start = forward_kinematics(pr2, SEED, TOOL)
    x, y, z = start.position
    return [Pose((x + step * k, y, z - step * k), start.orientation) for k in range(1, steps + 1)]


def test_each_answer_is_the_one_solve_ik_gives_from_the_answer_before(
    pr2: RobotDescription,
) -> None:
    poses = _line(pr2, 10, 0.007)
    seed = dict(SEED)
    for pose, tracked in zip(poses, track_ik(pr2, "right", poses, SEED), strict=True):
        alone = solve_ik(pr2, "right", pose, seed=seed, options=IKOptions(max_restarts=0))
        assert tracked.success and alone.success
        assert tracked.joint_positions == alone.joint_positions
        assert tracked.iterations <= 3 and tracked.position_error < 1e-3
        seed.update(alone.joint_positions)
        assert forward_kinematics(pr2, seed, TOOL).distance_to(pose) < 1e-3


def test_the_torso_stays_at_the_seed_and_a_miss_says_so(pr2: RobotDescription) -> None:
    far = Pose((3.0, -0.188, 0.9))
    answers = list(track_ik(pr2, "right", [*_line(pr2, 2, 0.005), far], SEED))
    assert [a.success for a in answers] == [True, True, False]
    assert all("torso_lift_joint" not in a.joint_positions for a in answers)
    assert answers[2].beyond_reach > 1.0  # the full query's answer, with its reasons
