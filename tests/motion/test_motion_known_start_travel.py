"""A straight arm walk takes the start's lever travels its checker worked out, and walks
exactly as when it works them out itself.

``_straight_checker`` bounds a short segment's travel from the start's levers
(:func:`start_travel`) to see whether it is free at once; when it is not, the walk needs
the same bound after its first check, with the robot standing at the same start: it is
handed over (``known``) instead of being worked out again. Here the walk with it and
without it must ask the same configurations in the same order and give the same
verdict; handed a bound worked out at another start, it walks otherwise (it is used);
and whole arm motions near the table write the same joints, plan the same path and
time the same trajectory either way (the mug put near the hand, so the walks are needed).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion import arm_motion
from robocram.motion.arm_motion import plan_arm_motion
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.segment_check import CheckCounter, segment_free, start_travel
from robocram.motion.travel_bound import TravelBound
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import RobotHandle, World
from robocram.world.world_tables import WorldTables

JOINTS = (
    "torso_lift_joint", "r_shoulder_pan_joint", "r_shoulder_lift_joint",
    "r_upper_arm_roll_joint", "r_elbow_flex_joint", "r_forearm_roll_joint",
    "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip
SMALL = 0.06  # [rad | m] spread of a small segment's joint changes (a handle step's)


def _segment(rng: np.random.Generator, world: World) -> tuple[np.ndarray, np.ndarray]:
    model = world.robot("pr2").description.model
    lows = np.array([max(model.joints[j].lower, -2.5) for j in JOINTS])
    highs = np.array([min(model.joints[j].upper, 2.5) for j in JOINTS])
    qa = rng.uniform(lows, highs)
    spread = SMALL * np.array([0.2] + [1.0] * (len(JOINTS) - 1))
    return qa, np.clip(qa + rng.normal(0.0, 1.0, len(JOINTS)) * spread, lows, highs)


def _walk(
    scene: BulletScene, qa: np.ndarray, qb: np.ndarray, bound: TravelBound, known: object
) -> tuple[bool, int, list[bytes]]:
    """The walk's verdict, its checks and the configurations it asked, in order."""
    asked: list[bytes] = []
    clearances = scene.clearances

    def recording(q: np.ndarray, reach: float = 0.1) -> dict[str, float]:
        asked.append(np.asarray(q, dtype=float).tobytes())
        return clearances(q, reach)

    scene.clearances = recording  # type: ignore[method-assign]
    counter = CheckCounter()
    try:
        free = segment_free(scene, qa, qb, bound, counter, known)  # type: ignore[arg-type]
    finally:
        del scene.clearances
    return free, counter.checks, asked


def test_a_walk_handed_the_start_travels_walks_as_without() -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    bound = TravelBound.of(robot, JOINTS)
    rng = np.random.default_rng(11)
    walked = used = 0
    for _ in range(60):
        qa, qb = _segment(rng, world)
        world.set_joint_states("pr2", dict(zip(JOINTS, qa.tolist(), strict=True)))
        judge = BulletScene(robot, JOINTS)  # the straight checker's, the robot at qa
        if not judge.is_free(qa) or judge.clearance_now() >= judge.reach:
            continue  # in collision, or far from everything: nothing to walk
        known: dict[str, float] = {}
        start_travel(judge, qa, qb, bound, known)
        walk = BulletScene(robot, JOINTS)  # the walk's own checker, as arm motions make it
        alone = _walk(walk, qa, qb, bound, None)
        handed = _walk(walk, qa, qb, bound, known)
        assert handed == alone
        world.set_joint_states("pr2", dict(zip(JOINTS, (qa + 0.3).tolist(), strict=True)))
        elsewhere: dict[str, float] = {}  # worked out standing elsewhere: not this walk's
        start_travel(BulletScene(robot, JOINTS), qa + 0.3, qb + 0.3, bound, elsewhere)
        world.set_joint_states("pr2", dict(zip(JOINTS, qa.tolist(), strict=True)))
        used += _walk(walk, qa, qb, bound, elsewhere)[2] != alone[2]
        walked += 1
    assert walked >= 3
    assert used >= 1  # the handed travels are what the walk steps by
    world.close()


@contextmanager
def _writes() -> Iterator[list[tuple[str, tuple[tuple[str, float], ...]]]]:
    """Every joint write of the world's tables, in order."""
    seen: list[tuple[str, tuple[tuple[str, float], ...]]] = []
    original = WorldTables.set_joint_states

    def record(self: WorldTables, obj: object, values: dict[str, float], carry: bool = True):  # type: ignore[no-untyped-def]
        seen.append((getattr(obj, "name", str(obj)), tuple(sorted(values.items()))))
        return original(self, obj, values, carry)  # type: ignore[arg-type]

    WorldTables.set_joint_states = record  # type: ignore[method-assign]
    try:
        yield seen
    finally:
        WorldTables.set_joint_states = original  # type: ignore[method-assign]


def test_arm_motions_near_the_table_are_the_same_either_way(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    world = tabletop_scene("pr2").world
    robot = RobotHandle.of(world, "pr2")
    rng = np.random.default_rng(5)
    compared = 0
    checker = arm_motion._straight_checker
    for _ in range(40):
        qa, qb = _segment(rng, world)
        world.set_joint_states("pr2", dict(zip(JOINTS, qa.tolist(), strict=True)))
        palm = world.link_pose("pr2", "r_gripper_palm_link").position
        world.set_pose("mug-1", Pose((palm[0] + 0.15, palm[1], palm[2] - 0.05)))  # near
        if not BulletScene(robot, JOINTS).is_free(qa):
            continue
        goal = dict(zip(JOINTS, qb.tolist(), strict=True))
        answers = []
        for hand_over in (True, False):
            with monkeypatch.context() as patch:
                if not hand_over:  # the walk works the travels out itself
                    patch.setattr(
                        arm_motion, "_straight_checker", lambda *a: (checker(*a)[0], None)
                    )
                with _writes() as writes:
                    try:
                        motion = plan_arm_motion(robot, goal)
                        found: object = (
                            motion.path,
                            motion.trajectory.positions().tobytes(),
                            motion.trajectory.times().tobytes(),
                        )
                    except ManipulationPathBlocked as failure:  # the same failure either way
                        found = str(failure)
            answers.append((found, writes))
        assert answers[0] == answers[1]
        compared += 1
    assert compared >= 10
    world.close()
