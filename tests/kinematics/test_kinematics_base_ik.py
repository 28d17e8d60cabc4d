"""IK with the base: the HSR's five-joint arm reaches with planar virtual joints x, y, yaw."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from robocram.kinematics import (
    BaseMotion,
    IKOptions,
    IKSolver,
    KinematicsError,
    PlanarBase,
    base_in_ik,
    forward_kinematics,
    solve_ik,
    split_base_motion,
)
from robocram.kinematics.planar_base import BASE_X_JOINT, with_planar_base
from robocram.robots import LoadedDescription, load_description
from robocram.tf import Pose
from robocram.tf import quaternion as quat

TOOL = "hand_tool_frame"


@pytest.fixture(scope="module")
def hsr() -> LoadedDescription:
    return load_description("hsrb")


def top_grasp(x: float, y: float, z: float, yaw: float) -> Pose:
    """The tool's approach axis (x) pointing down, turned by ``yaw`` about the vertical."""
    down = quat.from_euler(0.0, math.pi / 2, 0.0)
    return Pose((x, y, z), quat.multiply(quat.from_euler(0.0, 0.0, yaw), down))


def reached(desc: LoadedDescription, joints: dict[str, float], motion: BaseMotion) -> Pose:
    """The tool pose in the current base frame after moving the base, then the arm."""
    return motion.pose() * forward_kinematics(desc, joints, TOOL)


def test_which_arms_reach_with_the_base(hsr: LoadedDescription) -> None:
    assert base_in_ik(hsr, "arm")  # its hand moves in a thin slice (no shoulder pan)
    assert not base_in_ik(load_description("pr2"), "right")
    assert not base_in_ik(load_description("boxy"), "left")
    assert not base_in_ik(hsr, "no-such-arm")
    arm = dataclasses.replace(hsr.arms["arm"], base_in_ik=False)
    assert not base_in_ik(dataclasses.replace(hsr, arms={"arm": arm}), "arm")
    pr2 = load_description("pr2")
    right = dataclasses.replace(pr2.arms["right"], base_in_ik=True)
    assert base_in_ik(dataclasses.replace(pr2, arms={**pr2.arms, "right": right}), "right")


@pytest.mark.parametrize(
    ("x", "y", "z", "yaw"),
    [(0.45, 0.10, 0.75, 0.0), (0.55, -0.25, 0.6, 1.2), (0.35, 0.3, 0.9, -2.5)],
)
def test_top_grasps_the_arm_alone_misses_are_reached_with_the_base(
    hsr: LoadedDescription, x: float, y: float, z: float, yaw: float
) -> None:
    target = top_grasp(x, y, z, yaw)
    still = solve_ik(
        hsr, "arm", target, options=IKOptions(use_torso=True, orientation_tolerance=1e-3)
    )
    assert not still.success
    assert still.base_motion is None
    result = solve_ik(
        hsr,
        "arm",
        target,
        options=IKOptions(use_torso=True, base=PlanarBase(), orientation_tolerance=1e-3),
    )
    assert result.success
    motion = result.base_motion
    assert motion is not None and motion.distance > 1e-3
    assert abs(motion.x) <= 0.5 and abs(motion.y) <= 0.5 and abs(motion.yaw) <= math.pi
    lift = {"arm_lift_joint", "torso_lift_joint"}  # the head's lift follows the arm's
    assert set(result.joint_positions) == {*lift, *hsr.arms["arm"].joints}
    tool = reached(hsr, dict(result.joint_positions), motion)
    assert tool.distance_to(target) < 1e-3
    assert tool.angle_to(target) < 1e-3


def test_a_target_the_arm_reaches_alone_needs_no_base_motion(hsr: LoadedDescription) -> None:
    arm = IKSolver.cached(hsr, "arm", use_torso=True)
    rng = np.random.default_rng(7)
    for _ in range(10):
        truth = dict(zip(arm.variables, rng.uniform(arm.chain.lower, arm.chain.upper), strict=True))
        target = forward_kinematics(hsr, truth, TOOL)
        result = solve_ik(hsr, "arm", target, options=IKOptions(use_torso=True, base=PlanarBase()))
        assert result.success
        assert result.base_motion == BaseMotion(0.0, 0.0, 0.0)


def test_the_base_stays_within_its_travel(hsr: LoadedDescription) -> None:
    far = top_grasp(1.3, 0.0, 0.7, 0.0)  # about 0.7 m beyond the arm's reach from the base
    short = solve_ik(
        hsr, "arm", far, options=IKOptions(use_torso=True, base=PlanarBase(0.3, 0.3, 1.0))
    )
    assert not short.success
    assert short.base_motion is not None and abs(short.base_motion.x) <= 0.3 + 1e-9
    long = solve_ik(
        hsr, "arm", far, options=IKOptions(use_torso=True, base=PlanarBase(1.0, 0.5, math.pi))
    )
    assert long.success and long.base_motion is not None
    assert 0.3 < long.base_motion.x <= 1.0
    tool = reached(hsr, dict(long.joint_positions), long.base_motion)
    assert tool.distance_to(far) < 1e-3


def test_the_same_query_gives_the_same_answer(hsr: LoadedDescription) -> None:
    target = top_grasp(0.5, -0.2, 0.7, 0.8)
    answers = [
        solve_ik(
            hsr, "arm", target, options=IKOptions(use_torso=True, base=PlanarBase(), random_seed=3)
        )
        for _ in range(2)
    ]
    assert answers[0].joint_positions == answers[1].joint_positions
    assert answers[0].base_motion == answers[1].base_motion


def test_collision_checks_see_the_base_motion(hsr: LoadedDescription) -> None:
    seen: list[BaseMotion | None] = []

    def refuse_moves_forward(values: dict[str, float]) -> bool:
        _, motion = split_base_motion(values)
        seen.append(motion)
        return motion is not None and motion.x > 0.0

    target = top_grasp(0.45, 0.10, 0.75, 0.0)
    result = solve_ik(
        hsr,
        "arm",
        target,
        options=IKOptions(use_torso=True, base=PlanarBase()),
        collision_check=refuse_moves_forward,
    )
    assert any(m is not None for m in seen)
    if result.success:
        assert result.base_motion is not None and result.base_motion.x <= 0.0
    else:
        assert result.rejected_in_collision > 0


def test_bad_travel_and_clashing_names_are_refused(hsr: LoadedDescription) -> None:
    with pytest.raises(KinematicsError, match="travel_x"):
        PlanarBase(travel_x=0.0)
    with pytest.raises(KinematicsError, match="travel_yaw"):
        PlanarBase(travel_yaw=4.0)
    extended = with_planar_base(hsr.model, PlanarBase())
    assert extended.root_link == "planar_base_origin"
    assert extended.joints[BASE_X_JOINT].upper == 0.5
    with pytest.raises(KinematicsError, match="virtual base joints"):
        with_planar_base(extended, PlanarBase())
