"""A failed IK answer says why: the colliding link pairs and how far beyond reach."""

from __future__ import annotations

import pytest

from robocram.kinematics import IKOptions, solve_ik
from robocram.tf import Pose


def test_rejected_solutions_carry_their_colliding_pairs_most_frequent_first() -> None:
    calls: list[int] = []

    def collides(joints: dict[str, float]) -> list[tuple[str, str]]:
        calls.append(1)
        pairs = [("r_gripper_palm_link", "mug-1")]
        return pairs + [("r_forearm_link", "table")] if len(calls) % 2 else pairs

    target = Pose((0.6, -0.2, 0.9))
    result = solve_ik(
        "pr2", "right", target, options=IKOptions(max_restarts=5), collision_check=collides
    )
    assert not result.success
    assert result.rejected_in_collision == len(calls) >= 2
    assert result.colliding_pairs == (("r_gripper_palm_link", "mug-1"), ("r_forearm_link", "table"))
    assert result.beyond_reach == 0.0


def test_a_boolean_check_still_works_and_names_no_pairs() -> None:
    result = solve_ik("pr2", "right", Pose((0.6, -0.2, 0.9)), collision_check=lambda j: True)
    assert result.rejected_in_collision > 0 and result.colliding_pairs == ()


def test_beyond_reach_grows_with_the_distance_from_the_shoulder() -> None:
    near, far = (solve_ik("pr2", "right", Pose((x, -0.188, 0.9))) for x in (2.5, 3.0))
    assert not far.success and far.iterations == 0  # no descent beyond the bound
    assert near.beyond_reach > 1.0
    assert far.beyond_reach - near.beyond_reach == pytest.approx(0.5, abs=0.01)
    inside = solve_ik("pr2", "right", Pose((0.6, -0.2, 0.9)))
    assert inside.success and inside.beyond_reach == 0.0
