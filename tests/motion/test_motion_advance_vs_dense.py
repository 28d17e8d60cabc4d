"""Conservative advancement on coal's clearances gives the dense check's verdicts.

``segment_free`` walks a segment by steps as large as the clearances allow (each link's
speed along the segment where it stands, on long sweeps); the dense check judges every
configuration 1 cm of travel apart on the world itself. For seeded segments of the PR2's
right arm and torso at the kitchen counter (short and long, free and blocked, empty hand
and holding the mug), both must agree: a free segment stays free, a blocked one blocked.
"""

from __future__ import annotations

import numpy as np
import pytest

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.configuration_checker import ClearanceChecker
from robocram.motion.segment_check import CheckCounter, interior, segment_free
from robocram.motion.travel_bound import TravelBound
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
SEGMENTS = 40  # per seed
AT_COUNTER = Pose((-1.12, 1.24, 0.0), quat.from_euler(0.0, 0.0, 1.88))  # facing the mug


def _segments(
    world: World, judge: BulletScene, seed: int, n: int
) -> list[tuple[np.ndarray, np.ndarray]]:
    """``n`` segments with free ends: every other one random (moves of every size), the
    others through a configuration just touching something (found by bisection between
    a free and a colliding one), in a random direction: they graze what they hit."""
    model = world.robot("pr2").description.model
    lows = np.array([max(model.joints[j].lower, -2.5) for j in JOINTS])
    highs = np.array([min(model.joints[j].upper, 2.5) for j in JOINTS])
    rng = np.random.default_rng(seed)
    found: list[tuple[np.ndarray, np.ndarray]] = []
    while len(found) < n:
        qa = rng.uniform(lows, highs)
        scale = float(rng.choice([0.05, 0.2, 0.6, 1.5]))
        if len(found) % 2:
            qb = rng.uniform(lows, highs)
            if judge.is_free(qa) == judge.is_free(qb):
                continue
            free, hit = (qa, qb) if judge.is_free(qa) else (qb, qa)
            for _ in range(12):
                middle = (free + hit) / 2.0
                free, hit = (middle, hit) if judge.is_free(middle) else (free, middle)
            side = rng.normal(scale=scale, size=len(JOINTS))
            qa, qb = np.clip(hit - side, lows, highs), np.clip(hit + side, lows, highs)
        else:
            qb = np.clip(qa + rng.normal(scale=scale, size=len(JOINTS)), lows, highs)
        if judge.is_free(qa) and judge.is_free(qb):
            found.append((qa, qb))
    return found


def _dense_free(judge: BulletScene, qa: np.ndarray, qb: np.ndarray, bound: TravelBound) -> bool:
    """Every configuration 1 cm of travel (0.02 rad) apart, judged on the world."""
    n = bound.steps(qa, qb)
    with judge.posed():
        return all(judge.is_free(qa + (qb - qa) * (k / n)) for k in interior(n))


def _verdicts(world: World, judge: BulletScene, checker: ClearanceChecker, seed: int) -> int:
    """Compare both checks on seeded segments; return how many were blocked."""
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), JOINTS)
    blocked = 0
    for qa, qb in _segments(world, judge, seed, SEGMENTS):
        fast = segment_free(checker, qa, qb, bound, CheckCounter())
        dense = _dense_free(judge, qa, qb, bound)
        assert fast == dense, (qa.tolist(), qb.tolist(), fast, dense)
        blocked += not dense
    return blocked


@pytest.fixture(scope="module")
def world() -> World:
    made = kitchen_scene("pr2").world
    made.set_pose("pr2", AT_COUNTER)
    yield made
    made.close()


@pytest.mark.parametrize("seed", range(3))
def test_advancement_on_coal_agrees_with_the_dense_check(world: World, seed: int) -> None:
    judge = BulletScene(RobotHandle.of(world, "pr2"), JOINTS)
    blocked = _verdicts(world, judge, CoalClearance(judge), seed)
    assert 0 < blocked < SEGMENTS  # both kinds are met


def test_advancement_on_the_world_agrees_with_the_dense_check(world: World) -> None:
    judge = BulletScene(RobotHandle.of(world, "pr2"), JOINTS)
    blocked = _verdicts(world, judge, judge, 3)
    assert 0 < blocked < SEGMENTS


def test_advancement_holding_the_mug_agrees_with_the_dense_check(world: World) -> None:
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    try:
        judge = BulletScene(RobotHandle.of(world, "pr2"), JOINTS)
        blocked = _verdicts(world, judge, CoalClearance(judge), 4)
    finally:
        world.detach("mug-1")
    assert 0 < blocked < SEGMENTS
