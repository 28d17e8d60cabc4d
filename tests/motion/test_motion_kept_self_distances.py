"""A motion's self distances are kept with the world while the joints it does not plan
stand as they did: every answer is a fresh build's, to the bit, and a moved other joint
gets its own.

``SelfPathCheck.of`` used to build coal's self distances for every motion; a handle's
steps plan the same joints with the others standing still, so the distances are kept by
robot, planned joints and the other joints' values. Here the kept ones, asked at seeded
configurations in any order (the walk's cached configurations included), must answer
exactly what distances built afresh where the robot stands answer; a walk and a goal
check through the kept ones must give a fresh check's verdicts; and moving the head (not
planned) must give other distances, again a fresh build's.
"""

from __future__ import annotations

import numpy as np

from robocram.motion.coal_self_distances import SELF_MARGIN, SelfDistances
from robocram.motion.robot_geometry import RobotGeometry
from robocram.motion.self_path_check import SelfPathCheck
from robocram.scenes import tabletop_scene
from robocram.world import RobotHandle, World

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip


def _configurations(world: World, rng: np.random.Generator, count: int) -> list[np.ndarray]:
    model = world.robot("pr2").description.model
    lows = np.array([max(model.joints[j].lower, -2.5) for j in JOINTS])
    highs = np.array([min(model.joints[j].upper, 2.5) for j in JOINTS])
    return [rng.uniform(lows, highs) for _ in range(count)]


def _fresh(world: World, check: SelfPathCheck) -> SelfDistances:
    """Distances built afresh where the robot stands (as every motion built them)."""
    model = world.robot("pr2").description.model
    standing = {j: v for j, v in world.joint_states("pr2").items() if model.joints[j].mimic is None}
    geometry = model.derived(RobotGeometry.of)
    return SelfDistances(geometry, check.distances._parts, JOINTS, standing, SELF_MARGIN)


def _answers(distances: SelfDistances, qs: list[np.ndarray]) -> list[tuple[bytes, tuple]]:
    """Per configuration: the bounds and every pair's coal distance (all pairs asked)."""
    out = []
    for q in qs:
        bounds = distances.bounds(q).tobytes()
        out.append((bounds, tuple(distances.distance(k) for k in range(len(bounds) // 8))))
    return out


def test_kept_distances_answer_as_fresh_ones() -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    rng = np.random.default_rng(3)
    starts = _configurations(world, rng, 3)
    world.set_joint_states("pr2", dict(zip(JOINTS, starts[0].tolist(), strict=True)))
    first = SelfPathCheck.of(robot, JOINTS)
    qs = _configurations(world, rng, 6)
    for start in starts[1:]:  # the next motions start elsewhere; the head and left arm stay
        world.set_joint_states("pr2", dict(zip(JOINTS, start.tolist(), strict=True)))
        check = SelfPathCheck.of(robot, JOINTS)
        assert check.distances is first.distances  # kept
        fresh = _fresh(world, check)
        order = [qs[2], start, qs[0], qs[2], *qs, start]  # repeats: answered as kept
        assert _answers(check.distances, order) == _answers(fresh, order)
        for q in qs[:3]:
            path = [start.tolist(), q.tolist()]
            walked = check.first_collision(path)
            again = SelfPathCheck(
                robot, JOINTS, check.pairs, check.levers, check.floors, _fresh(world, check)
            ).first_collision(path)
            assert walked == again
            assert check.colliding(q) == SelfPathCheck(
                robot, JOINTS, check.pairs, check.levers, check.floors, _fresh(world, check)
            ).colliding(q)
    world.close()


def test_an_unplanned_joint_moved_gets_its_own_distances() -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    rng = np.random.default_rng(4)
    start, *qs = _configurations(world, rng, 5)
    world.set_joint_states("pr2", dict(zip(JOINTS, start.tolist(), strict=True)))
    before = SelfPathCheck.of(robot, JOINTS)
    answers = _answers(before.distances, qs)
    world.set_joint_states("pr2", {"head_pan_joint": 0.9, "l_shoulder_pan_joint": -0.5})
    after = SelfPathCheck.of(robot, JOINTS)
    assert after.distances is not before.distances
    moved = _answers(after.distances, qs)
    assert moved == _answers(_fresh(world, after), qs)
    assert moved != answers  # the head and the left arm stand elsewhere
    world.set_joint_states("pr2", {"head_pan_joint": 0.0, "l_shoulder_pan_joint": 0.0})
    world.set_joint_states("pr2", {"head_pan_joint": 0.9, "l_shoulder_pan_joint": -0.5})
    assert SelfPathCheck.of(robot, JOINTS).distances is after.distances  # the same again
    world.close()
