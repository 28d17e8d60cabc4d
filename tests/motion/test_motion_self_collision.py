"""Arm motions keep the robot's own links apart, judged by raw PyBullet queries.

The judge here is not the planner's: it samples the path densely (0.005 rad) and asks
PyBullet's ``getClosestPoints`` for every pair of links with shapes that are not joined by
one joint, counting a pair only where it is deeper than where the motion started (so the
hulls a parked arm folds into each other do not count, as long as they do not deepen).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion import MotionSettings, plan_arm_motion
from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.scenes import tabletop_scene
from robocram.world import RobotHandle, World

SAMPLE = 0.005  # [rad | m] between the judge's samples
DEEPER = 0.001  # [m] deeper than at the start counts


@pytest.fixture(scope="module")
def pr2() -> Iterator[World]:
    world = tabletop_scene("pr2").world
    yield world
    world.close()


def _judged_pairs(world: World, robot: str) -> list[tuple[int, int, str, str]]:
    """Every pair of links with shapes not joined by one joint (fixed joints merged)."""
    handle = world.robot(robot)
    names = handle.collider_names()
    model = handle.description.model
    near = set()
    for joint in model.joints.values():
        near.add(frozenset((joint.parent, joint.child)))
    return [
        (i, j, names[i], names[j])
        for i, j in itertools.combinations(sorted(names), 2)
        if frozenset((names[i], names[j])) not in near
    ]


def _depths(world: World, robot: str, pairs: list[tuple[int, int, str, str]]) -> np.ndarray:
    body = world.object(robot).body_id
    cid = world.physics.client()
    out = np.zeros(len(pairs))
    for k, (i, j, _, _) in enumerate(pairs):
        points = pybullet.getClosestPoints(
            body, body, 0.001, linkIndexA=i, linkIndexB=j, physicsClientId=cid
        )
        out[k] = max((-p[8] for p in points), default=0.0)
    return out


def _deepening(world: World, robot: str, joints: tuple[str, ...], waypoints) -> list[str]:
    """Pairs the path through ``waypoints`` sinks deeper than at its start (the judge)."""
    pairs = _judged_pairs(world, robot)
    model = world.robot(robot).description.model
    before = {j: v for j, v in world.joint_states(robot).items() if model.joints[j].mimic is None}
    found: set[str] = set()
    try:
        start = _depths(world, robot, pairs)
        points = np.asarray(waypoints, dtype=float)
        for a, b in itertools.pairwise(points):
            n = max(1, int(np.ceil(np.abs(b - a).max() / SAMPLE)))
            for s in np.linspace(0.0, 1.0, n + 1):
                world.set_joint_states(robot, dict(zip(joints, a + (b - a) * s, strict=True)))
                deep = _depths(world, robot, pairs) - start
                over = [p for p, d in zip(pairs, deep, strict=True) if d > DEEPER]
                found.update(f"{p[2]}-{p[3]}" for p in over)
    finally:
        world.set_joint_states(robot, before)
    return sorted(found)


def test_the_matrix_checks_a_forearm_against_its_own_fingers(pr2: World) -> None:
    matrix = SelfCollisionMatrix.of(RobotHandle.of(pr2, "pr2"))
    assert matrix.reason("r_forearm_link", "r_gripper_l_finger_link") is None
    assert ("r_forearm_link", "r_gripper_l_finger_link") in matrix.checked or (
        "r_gripper_l_finger_link",
        "r_forearm_link",
    ) in matrix.checked
    assert matrix.reason("r_elbow_flex_link", "r_upper_arm_roll_link") == "adjacent"


def test_a_wrist_flexed_into_the_open_fingers_is_refused_before_it_moves(pr2: World) -> None:
    """The straight wrist flex runs the forearm into the open fingers (the judge agrees);
    without planning it is refused naming the pair, and nothing moves."""
    with pr2.snapshots.stored_state():
        pr2.set_joint_states("pr2", {"r_gripper_l_finger_joint": 0.548, "r_wrist_roll_joint": 0.0})
        joint = "r_wrist_flex_joint"
        start = pr2.joint_states("pr2")[joint]
        assert _deepening(pr2, "pr2", (joint,), [[start], [-2.09]])  # the judge sees it
        with pytest.raises(ManipulationPathBlocked) as failure:
            plan_arm_motion(
                RobotHandle.of(pr2, "pr2"), {joint: -2.09}, settings=MotionSettings(plan=False)
            )
        assert ("r_forearm_link", "r_gripper_l_finger_link") in failure.value.colliding_pairs
        assert "into itself" in str(failure.value)
        assert pr2.joint_states("pr2")[joint] == pytest.approx(start, abs=1e-12)


def test_a_planned_arm_motion_never_sinks_links_into_each_other(pr2: World) -> None:
    """With planning, the motion either goes round (the judge finds nothing) or fails."""
    with pr2.snapshots.stored_state():
        pr2.set_joint_states("pr2", {"r_gripper_l_finger_joint": 0.548, "r_wrist_roll_joint": 0.0})
        desc = pr2.robot("pr2").description
        joints = desc.arms["right"].joints
        goal = {**{j: pr2.joint_states("pr2")[j] for j in joints}, "r_wrist_flex_joint": -2.09}
        try:
            motion = plan_arm_motion(RobotHandle.of(pr2, "pr2"), goal)
        except ManipulationPathBlocked:
            return
        assert _deepening(pr2, "pr2", motion.path.joints, motion.path.waypoints) == []
