"""Planned arm paths are simplified until no inner waypoint can be dropped, and stay free;
a query that cannot succeed fails within its counted budget.

The judge is PyBullet (``BulletScene``), densely, independent of the coal snapshot the
planner checks on: along the planned path no configuration 1 cm of link travel apart
goes deeper than 1 mm into anything (the audit's bound: a path pulled tight round an
obstacle, checked every 1 cm, may graze it between its checks), and dropping any inner
waypoint makes the path collide.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from itertools import pairwise

import numpy as np
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.kinematics import solve_ik
from robocram.motion import (
    CollisionScene,
    MotionSettings,
    arm_motion,
    joint_limits,
    plan_arm_motion,
)
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.joint_path import PLANNING_BUDGET, plan_joint_path
from robocram.motion.path_simplification import path_length, simplify
from robocram.motion.segment_check import CheckCounter
from robocram.motion.travel_bound import TravelBound
from robocram.plans.basic_actions import move_torso, navigate, park_arms
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.collision_mode import collision_check
from robocram.scenes import kitchen_scene
from robocram.tf import PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World

PENETRATION = 0.001  # [m] the audit's bound: checks 1 cm apart may graze between them
SHELF = ((0.12, 0.12, 0.36), (-0.97, 2.02, 1.04))  # size, centre [m]: on the counter


@dataclass
class Shelf:
    """The PR2 at the counter, a box between its parked right hand and the mug."""

    world: World
    joints: tuple[str, ...]
    start: np.ndarray
    goal: np.ndarray
    box: tuple[list[float], list[float]]
    bound: TravelBound


@pytest.fixture(scope="module")
def shelf() -> Iterator[Shelf]:
    world = kitchen_scene("pr2").world
    x = world.pose("mug-1").position[0]
    with simulated_robot(world, "pr2"):
        park_arms()
        move_torso("upper")
        north = quat.from_euler(0.0, 0.0, math.pi / 2)
        navigate(PoseStamped("map", (x, 1.43, 0.0), north))
        grasp = world.kb.first("object_grasp(O, R, A, N, G, P, L)", O="mug-1", R="pr2", A="right")
    assert grasp is not None
    robot = ProjectedRobot(world, "pr2")
    world.add_box("shelf", *SHELF)
    current = world.joint_states("pr2")
    check = collision_check(robot, "right", "avoid_all")
    goal = solve_ik(robot.description, "right", robot.in_base(grasp["P"]), seed=current,
                    collision_check=check)  # fmt: skip
    joints = tuple(robot.description.arms["right"].joints)
    limits = joint_limits(robot.description, joints)
    yield Shelf(
        world, joints, np.array([current[j] for j in joints]),
        np.array([goal.joint_positions[j] for j in joints]),
        ([lim.lower for lim in limits], [lim.upper for lim in limits]),
        TravelBound.of(RobotHandle.of(world, "pr2"), joints),
    )  # fmt: skip
    world.close()


def _dense_collision(
    judge: BulletScene, points: list[np.ndarray], bound: TravelBound, depth: float = 0.0
) -> bool:
    """Whether any configuration along the polyline, 1 cm of link travel apart, collides:
    touches (``depth`` 0) or goes deeper than ``depth`` [m] into something."""
    for qa, qb in zip(points, points[1:], strict=False):
        n = bound.steps(qa, qb)
        for k in range(n + 1):
            q = qa + (qb - qa) * (k / n)
            if judge.colliding(q, True) and min(judge.clearances(q).values()) <= -depth:
                return True
    return False


@pytest.mark.parametrize("seed", [0, 1, 6])
def test_no_inner_waypoint_of_a_planned_path_can_be_dropped(
    shelf: Shelf, seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(arm_motion.ToolHeight, "of", lambda *args: None)  # no detour: plan
    goal = dict(zip(shelf.joints, shelf.goal, strict=True))
    path = plan_arm_motion(
        RobotHandle.of(shelf.world, "pr2"), goal, settings=MotionSettings(seed=seed)
    ).path
    assert path.planner == "rrt_connect"
    points = [np.array(w) for w in path.waypoints]
    assert len(points) >= 3  # the straight segment is blocked: a corner at least
    assert np.allclose(points[0], shelf.start) and np.allclose(points[-1], shelf.goal)
    judge = BulletScene(RobotHandle.of(shelf.world, "pr2"), shelf.joints)
    with judge.posed():
        assert not _dense_collision(judge, points, shelf.bound, PENETRATION)
        for k in range(1, len(points) - 1):
            assert _dense_collision(judge, points[k - 1 : k] + points[k + 1 : k + 2], shelf.bound)
    straight = float(np.linalg.norm(shelf.goal - shelf.start))
    assert straight < path_length(points) < 2.0 * straight


def test_simplifying_keeps_the_ends_and_never_lengthens(shelf: Shelf) -> None:
    zigzag = [shelf.start, (shelf.start + shelf.goal) / 2 + 0.3, shelf.goal]
    snapshot = CollisionScene.of(RobotHandle.of(shelf.world, "pr2"), shelf.joints)
    counter = CheckCounter()
    out = simplify(snapshot, zigzag, shelf.bound, counter)
    assert np.array_equal(out.waypoints[0], shelf.start)
    assert np.array_equal(out.waypoints[-1], shelf.goal)
    assert path_length(out.waypoints) <= path_length(zigzag) + 1e-12
    assert len(out.checked) == len(out.waypoints) - 1
    assert counter.checks > 0


class _Square:
    """A point robot in the plane (two prismatic "joints") round a square obstacle."""

    joints = ("x", "y")

    def colliding(self, q: object, first_only: bool = False) -> list[tuple[str, str]]:
        x, y = np.asarray(q, dtype=float)
        return [("point", "square")] if abs(x) < 1.0 and abs(y) < 1.0 else []

    def is_free(self, q: object) -> bool:
        return not self.colliding(q)


def _crosses_square(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether the segment a-b meets the open square |x|, |y| < 1 (exactly: clipped)."""
    low, high = 0.0, 1.0
    for axis in (0, 1):
        d = b[axis] - a[axis]
        if d == 0.0:
            if abs(a[axis]) >= 1.0:
                return False
            continue
        t0, t1 = sorted(((-1.0 - a[axis]) / d, (1.0 - a[axis]) / d))
        low, high = max(low, t0), min(high, t1)
    return low < high


@pytest.mark.parametrize("seed", range(5))
def test_a_path_round_a_square_is_as_short_as_its_corners_allow(seed: int) -> None:
    start, goal = np.array([-3.0, 0.2]), np.array([3.0, -0.1])
    bound = TravelBound(("x", "y"), np.ones(2))
    box = ([-5.0, -5.0], [5.0, 5.0])
    path = plan_joint_path(_Square(), start, goal, bound, box, seed=seed)
    points = [np.array(w) for w in path.waypoints]
    assert path.planner == "rrt_connect" and len(points) >= 3
    assert not any(_crosses_square(a, b) for a, b in zip(points, points[1:], strict=False))
    for k in range(1, len(points) - 1):  # every corner is needed (exact geometry judges)
        assert _crosses_square(points[k - 1], points[k + 1])
    over = [start, np.array([-1.0, 1.0]), np.array([1.0, 1.0]), goal]
    under = [start, np.array([-1.0, -1.0]), np.array([1.0, -1.0]), goal]
    shortest = min(path_length(over), path_length(under))  # round two corners: 6.44
    assert shortest <= path_length(points) < 1.1 * shortest


def test_a_start_known_free_is_not_asked_again() -> None:
    """A caller that made its checker allowing the start's contacts says so; the start is
    then not asked (a start inside the square would otherwise fail at once)."""
    inside, goal = np.array([0.5, 0.0]), np.array([3.0, 0.0])
    bound = TravelBound(("x", "y"), np.ones(2))
    box = ([-5.0, -5.0], [5.0, 5.0])
    with pytest.raises(ManipulationPathBlocked, match="start configuration is in collision"):
        plan_joint_path(_Square(), inside, goal, bound, box, plan=False)
    with pytest.raises(ManipulationPathBlocked, match="straight path is blocked"):
        plan_joint_path(_Square(), inside, goal, bound, box, plan=False, start_free=True)
    outside = np.array([-3.0, 0.0])
    path = plan_joint_path(_Square(), outside, -outside, bound, box, start_free=True)
    assert path.planner == "rrt_connect"  # the goal is still asked, and the way round planned
    assert not any(_crosses_square(a, b) for a, b in pairwise(np.array(path.waypoints)))


class _Caged:
    """The snapshot, with the goal enclosed in joint space: every configuration between
    0.05 and 0.3 rad (max norm) of it collides with "cage"; counts what it is asked."""

    def __init__(self, scene: CollisionScene, goal: np.ndarray) -> None:
        self.scene, self.goal, self.asked = scene, goal, 0
        self.joints = scene.joints

    def _caged(self, q: object) -> bool:
        self.asked += 1
        distance = float(np.abs(np.asarray(q, dtype=float) - self.goal).max())
        return 0.05 < distance < 0.3

    def is_free(self, q: object) -> bool:
        return not self._caged(q) and self.scene.is_free(q)  # type: ignore[arg-type]

    def colliding(self, q: object, first_only: bool = False) -> list[tuple[str, str]]:
        if self._caged(q):
            return [("r_gripper_palm_link", "cage")]
        return self.scene.colliding(q, first_only)  # type: ignore[arg-type]


def test_an_enclosed_goal_fails_within_the_counted_budget(shelf: Shelf) -> None:
    snapshot = CollisionScene.of(RobotHandle.of(shelf.world, "pr2"), shelf.joints)
    asked = []
    for _ in range(2):
        caged = _Caged(snapshot, shelf.goal)
        with pytest.raises(ManipulationPathBlocked) as caught:
            plan_joint_path(caged, shelf.start, shelf.goal, shelf.bound, shelf.box, seed=0)
        asked.append(caged.asked)
    explain = shelf.bound.steps(shelf.start, shelf.goal) + 1  # the straight walk's checks
    assert asked[0] == asked[1]  # counted, not timed: the same checks every time
    assert PLANNING_BUDGET <= asked[0] <= PLANNING_BUDGET + explain + 100
    assert PLANNING_BUDGET == 5_000
    assert "RRTConnect found no way round in 5000 checks" in str(caught.value)
