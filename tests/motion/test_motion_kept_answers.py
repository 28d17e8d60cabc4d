"""Checks keep what they measured (posed configurations, gaps, self bounds, travel bounds):
asked again, they must answer exactly what a fresh check answers, to the bit, and a
contact check must name what the world itself (PyBullet) finds."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.motion.bullet_scene import BulletScene
from robocram.motion.coal_clearance import POSED_KEPT, CoalClearance
from robocram.motion.self_path_check import SelfPathCheck
from robocram.motion.travel_bound import TravelBound, _made, link_radii
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World

ARM = (
    "r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
    "r_elbow_flex_joint", "r_forearm_roll_joint", "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
AT_COUNTER = Pose((-1.12, 1.24, 0.0), quat.from_euler(0.0, 0.0, 1.88))  # facing the mug


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    made = kitchen_scene("pr2").world
    made.set_pose("pr2", AT_COUNTER)
    yield made
    made.close()


def _visits(world: World, seed: int) -> list[np.ndarray]:
    """Seeded arm configurations, each asked again later (more than a checker keeps)."""
    model = world.robot("pr2").description.model
    lows = [max(model.joints[j].lower, -2.5) for j in ARM]
    highs = [min(model.joints[j].upper, 2.5) for j in ARM]
    qs = list(np.random.default_rng(seed).uniform(lows, highs, size=(POSED_KEPT + 4, len(ARM))))
    return [*qs, *qs[::-1], qs[0], qs[0]]


def test_a_coal_checker_asked_again_answers_as_a_fresh_one(world: World) -> None:
    judge = BulletScene(RobotHandle.of(world, "pr2"), ARM)
    kept = CoalClearance(judge)
    near_counter = 0
    for q in _visits(world, 1):
        fresh = CoalClearance(judge)
        near = kept.near(q)
        again = fresh.near(q)
        assert (near.names, near.bounds) == (again.names, again.bounds)
        assert [near.gap(k) for k in range(len(near.names))] == [
            again.gap(k) for k in range(len(again.names))
        ]
        assert (
            kept.clearance(q)
            == fresh.clearance(q)
            == min(fresh.clearances(q).values(), default=judge.reach)
        )
        assert kept.clearances(q) == CoalClearance(judge).clearances(q)
        assert set(kept.colliding(q)) == set(judge.colliding(q))  # the world's own word
        near_counter += kept.clearance(q) < judge.reach
    assert near_counter  # some configurations are measured near the counter


def test_a_self_check_asked_again_answers_as_a_fresh_one(world: World) -> None:
    handle = RobotHandle.of(world, "pr2")
    kept = SelfPathCheck.of(handle, ARM)
    for q in _visits(world, 2):
        fresh = SelfPathCheck.of(handle, ARM)
        bounds, again = kept.distances.bounds(q), fresh.distances.bounds(q)
        assert bounds.tobytes() == again.tobytes()
        near = np.flatnonzero(bounds < 0.05).tolist()
        assert [kept.distances.distance(k) for k in near] == [
            fresh.distances.distance(k) for k in near
        ]
        assert kept.colliding(q) == fresh.colliding(q)


def test_a_kept_travel_bound_is_the_one_built_now(world: World) -> None:
    handle = RobotHandle.of(world, "pr2")
    bound = TravelBound.of(handle, ARM)
    assert TravelBound.of(handle, ARM) is bound  # kept with the world
    built = _made(handle, ARM, link_radii(handle), {}, bound.max_link_travel, 0.02)
    assert bound.lever.tobytes() == built.lever.tobytes()
    assert bound.link_lever.keys() == built.link_lever.keys()
    assert all(bound.link_lever[k].tobytes() == v.tobytes() for k, v in built.link_lever.items())
    assert TravelBound.of(handle, ARM[:3]) is not bound
