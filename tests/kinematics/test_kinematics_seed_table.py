"""The start table: batch FK equal to pinocchio's, nearest samples near the target, and
fewer descents than starting from the seed alone."""

from __future__ import annotations

import numpy as np
import pytest

from robocram.kinematics import IKOptions, IKSolver, forward_kinematics, reachable, solve_ik
from robocram.kinematics.chain_sweep import chain_base, sweep_tip_poses
from robocram.kinematics.seed_table import SeedTable, random_configurations
from robocram.robots import load_description
from robocram.tf import Pose


@pytest.mark.parametrize(
    ("robot", "arm", "use_torso"),
    [
        ("pr2", "right", False),
        ("pr2", "left", True),
        ("hsrb", "arm", True),
        ("boxy", "neck", False),
    ],
)
def test_sweep_equals_pinocchio(robot: str, arm: str, use_torso: bool) -> None:
    # PR2: continuous joints and a held torso; HSR: prismatic lift, unaligned axes, mimic
    solver = IKSolver.cached(load_description(robot), arm, use_torso)
    chain = solver.chain
    xs = random_configurations(chain, np.random.default_rng(1), 50, np.zeros(len(chain.variables)))
    b = chain.offsets({})
    positions, rotations = sweep_tip_poses(chain, xs @ chain.a.T + b)
    for x, position, rotation in zip(xs, positions, rotations, strict=True):
        tip = chain.tip_pose(x, b)
        in_base = chain_base(chain).actInv(tip)
        np.testing.assert_allclose(position, in_base.translation, atol=1e-12)
        np.testing.assert_allclose(rotation, in_base.rotation, atol=1e-12)


def test_nearest_samples_are_near_and_sorted() -> None:
    pr2 = load_description("pr2")
    solver = IKSolver.cached(pr2, "right")
    table = SeedTable(solver.chain, 5000, solver.reach.radius)
    again = SeedTable(solver.chain, 5000, solver.reach.radius)
    np.testing.assert_array_equal(table.configurations, again.configurations)  # seeded
    truth = {"r_shoulder_pan_joint": -0.3, "r_elbow_flex_joint": -1.1, "r_wrist_flex_joint": -0.5}
    target = forward_kinematics(pr2, truth, "r_gripper_tool_frame")
    _, in_base, _ = solver.locate(target, {})
    configs, distances = table.nearest(in_base, 4)
    assert configs.shape == (4, 7) and list(distances) == sorted(distances)
    assert distances[0] < 0.15  # [m] pose distance, 5000 samples
    for x, distance in zip(configs, distances, strict=True):
        joints = dict(zip(solver.variables, x.tolist(), strict=True))
        tool = forward_kinematics(pr2, joints, "r_gripper_tool_frame")
        assert tool.distance_to(target) <= distance + 1e-9


def test_far_target_has_no_samples_around() -> None:
    solver = IKSolver.cached(load_description("pr2"), "right")
    configs, distances = solver.table.nearest(solver.locate(Pose((3.0, 0.0, 0.8)), {})[1], 4)
    assert configs.shape[0] == 0 and distances.size == 0


def test_hsr_without_its_lift_gives_up_after_fruitless_descents() -> None:
    hsr = load_description("hsrb")
    # inside the arm's reach without the lift (the arm points down, the lift brings its wrist
    # nearer the shoulder), but at a pose four joints cannot take
    target = forward_kinematics(
        hsr,
        {
            "arm_lift_joint": 0.1,
            "arm_flex_joint": -2.2,
            "arm_roll_joint": 0.6,
            "wrist_flex_joint": -1.0,
        },
        "hand_tool_frame",
    )
    assert solve_ik(hsr, "arm", target, options=IKOptions(use_torso=True)).success
    assert reachable(hsr, "arm", target, seed={"arm_lift_joint": 0.0})
    result = solve_ik(hsr, "arm", target, seed={"arm_lift_joint": 0.0})
    assert not result.success
    assert result.restarts + 1 < 12  # of a budget of 101 descents
    assert 0.005 < result.position_error < 0.2


def test_nearest_answers_alike_from_a_gathered_and_a_fresh_neighbourhood(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # the table keeps the rows of a few cells gathered; dropping them changes no answer
    solver = IKSolver.cached(load_description("pr2"), "right")
    table = SeedTable(solver.chain, 5000, solver.reach.radius)
    targets = [Pose((0.5 + 0.07 * k, -0.2 + 0.03 * k, 0.8)) for k in range(6)]
    in_base = [solver.locate(t, {})[1] for t in targets]
    first = [table.nearest(t, 4) for t in in_base]
    assert len({tuple(np.floor(t.translation / table.cell)) for t in in_base}) > 2
    assert all(c.size for c, _ in first)
    monkeypatch.setattr("robocram.kinematics.seed_table.CACHED_CELLS", 2)
    for t, (configs, distances) in zip(in_base * 2, first * 2, strict=True):
        again_configs, again_distances = table.nearest(t, 4)
        np.testing.assert_array_equal(again_configs, configs)
        np.testing.assert_array_equal(again_distances, distances)
