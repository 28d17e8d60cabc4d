"""Arm motions in projection follow checked paths: around a shelf, never through it.

The PR2 stands at the counter with its arms parked and its torso up; a shelf board stands
on the counter between its parked right hand and the mug, so the straight joint-space
move to the mug's pre-grasp would sweep the forearm through the board. The motion must
succeed by a planned path, and every densely interpolated configuration of the executed
trajectory must be free in the world, as judged by PyBullet independently of the planner.
With planning off, the same motion fails with ``ManipulationPathBlocked`` naming the shelf.
"""

from __future__ import annotations

import gc
import importlib.util
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from robocram.designators import a
from robocram.execution import Task, TaskStopped, perform, run_top_level
from robocram.execution.failures import ManipulationPathBlocked, PlanFailure
from robocram.execution.task import WHOLE_FAILURES
from robocram.execution.task_context import binding_task
from robocram.kinematics import solve_ik
from robocram.motion import (
    CollisionScene,
    JointTrajectory,
    MotionSettings,
    joint_limits,
    trajectory_listener,
)
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.joint_path import planning_box
from robocram.motion.rrt_connect import rrt_connect
from robocram.motion.segment_check import CheckCounter
from robocram.motion.travel_bound import TravelBound
from robocram.plans.basic_actions import move_torso, navigate, park_arms
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.collision_mode import collision_check
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
NORTH = quat.from_euler(0.0, 0.0, math.pi / 2)
SHELF_SIZE = (0.12, 0.12, 0.36)  # [m] a box standing on the counter, in the arm's way
SHELF_CENTRE = (-0.97, 2.02, 1.04)  # [m] between the parked right hand and the mug


def _stand(scene: KitchenScene, settings: MotionSettings | None = None) -> PoseStamped:
    """Put the PR2 before the mug, torso up, arms parked; return the mug's top pre-grasp."""
    world = scene.world
    x = world.pose("mug-1").position[0]
    with simulated_robot(world, "pr2", motion=settings):
        park_arms()
        move_torso("upper")
        navigate(PoseStamped("map", (x, 1.43, 0.0), NORTH))
        grasp = world.kb.first("object_grasp(O, R, A, N, G, P, L)", O="mug-1", R="pr2", A="right")
    assert grasp is not None
    pre_grasp = grasp["P"]
    assert isinstance(pre_grasp, PoseStamped)
    return pre_grasp


@pytest.fixture()
def scene() -> Iterator[KitchenScene]:
    made = kitchen_scene("pr2")
    yield made
    made.world.close()


def _move(scene: KitchenScene, target: PoseStamped, settings: MotionSettings | None) -> list:
    executed: list[JointTrajectory] = []
    with (
        trajectory_listener(executed.append),
        simulated_robot(scene.world, "pr2", motion=settings),
    ):
        perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=target)))
    return executed


def _dense_configurations(scene: KitchenScene, trajectory: JointTrajectory) -> Iterator[dict]:
    """Every configuration 1 cm of link travel / 0.02 rad apart along the trajectory."""
    bound = TravelBound.of(RobotHandle.of(scene.world, "pr2"), trajectory.joint_names)
    points = trajectory.positions()
    for qa, qb in zip(points, points[1:], strict=False):
        n = bound.steps(qa, qb)
        for k in range(n + 1):
            yield dict(zip(trajectory.joint_names, qa + (qb - qa) * (k / n), strict=True))


def test_the_arm_goes_round_the_shelf_and_never_through_it(scene: KitchenScene) -> None:
    target = _stand(scene)
    world = scene.world
    start = world.joint_states("pr2")
    world.add_box("shelf", SHELF_SIZE, SHELF_CENTRE)
    executed = _move(scene, target, None)
    arm = [t for t in executed if t.kind == "arm"]
    assert len(arm) == 1
    trajectory = arm[0]
    assert len(trajectory.points) > 2
    judge = BulletScene(RobotHandle.of(world, "pr2"), trajectory.joint_names)
    world.set_joint_states("pr2", {j: start[j] for j in trajectory.joint_names})
    checked = 0
    for configuration in _dense_configurations(scene, trajectory):
        assert judge.colliding_at(configuration) == [], configuration
        checked += 1
    assert checked > 50
    # the straight segment from start to end really is blocked by the shelf
    ends = trajectory.positions()
    straight = np.linspace(ends[0], ends[-1], 200)
    assert any(("shelf" in other) for q in straight for _, other in judge.colliding(q))


def test_without_planning_the_same_motion_fails_naming_the_shelf(scene: KitchenScene) -> None:
    target = _stand(scene)
    world = scene.world
    before = world.joint_states("pr2")
    world.add_box("shelf", SHELF_SIZE, SHELF_CENTRE)
    with pytest.raises(ManipulationPathBlocked) as caught:
        _move(scene, target, MotionSettings(plan=False))
    failure = caught.value
    assert any(other == "shelf" for _, other in failure.colliding_pairs or ())
    assert "shelf" in str(failure)
    assert failure.path_fraction is not None and 0.0 < failure.path_fraction < 1.0
    after = world.joint_states("pr2")
    assert max(abs(after[j] - before[j]) for j in before) < 1e-9  # nothing moved


def test_the_same_seed_gives_the_same_trajectory(scene: KitchenScene) -> None:
    target = _stand(scene)
    world = scene.world
    world.add_box("shelf", SHELF_SIZE, SHELF_CENTRE)
    with world.snapshots.stored_state():
        first = _move(scene, target, None)
    second = _move(scene, target, None)
    assert [t.points for t in first] == [t.points for t in second]


def test_the_example_draws_both_paths(tmp_path: Path) -> None:
    spec = importlib.util.spec_from_file_location("motion_picture", EXAMPLES / "motion_picture.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    image = np.asarray(Image.open(module.draw(tmp_path / "shelf.png")).convert("RGB"), dtype=int)
    red, green, blue = image[:, :, 0], image[:, :, 1], image[:, :, 2]
    planned = (green > 150) & (red < 100) & (blue < 100)
    straight = (red > 180) & (green < 60) & (blue < 60)
    assert image.shape == (600, 800, 3)
    assert planned.sum() > 200 and straight.sum() > 100  # both paths drawn


def test_a_stopped_task_ends_the_planner_at_once_and_nothing_moves(scene: KitchenScene) -> None:
    target = _stand(scene)
    world = scene.world
    world.add_box("shelf", SHELF_SIZE, SHELF_CENTRE)
    robot = ProjectedRobot.of(world, "pr2")
    current = world.joint_states("pr2")
    check = collision_check(robot, "right", "avoid_all")
    goal = solve_ik(robot.description, "right", robot.in_base(target), seed=current,
                    collision_check=check)  # fmt: skip
    joints = robot.description.arms["right"].joints
    start, end = [current[j] for j in joints], [goal.joint_positions[j] for j in joints]
    limits = joint_limits(robot.description, joints)
    box = planning_box(
        np.array(start), np.array(end),
        ([lim.lower for lim in limits], [lim.upper for lim in limits]),
    )  # fmt: skip
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), joints)
    snapshot = CollisionScene.of(RobotHandle.of(world, "pr2"), joints)
    counter = CheckCounter()
    task = Task("stopped-while-planning")
    task.stop()
    with binding_task(task), pytest.raises(TaskStopped):
        rrt_connect(snapshot, np.array(start), np.array(end), *box, bound, counter, 20_000, 0)
    assert counter.checks < 50  # OMPL asked once or twice, not its whole budget
    assert world.joint_states("pr2") == current
    # and the same query, not stopped, plans: the stop was what ended it
    assert rrt_connect(snapshot, np.array(start), np.array(end), *box, bound, CheckCounter(),
                       20_000, 0) is not None  # fmt: skip


def test_failed_motions_let_go_of_their_collision_scenes(scene: KitchenScene) -> None:
    """A plan that recovers from many failed motions keeps only the task tree's latest
    failures whole: older ones no longer hold their planning snapshots (native memory a
    long clearing once grew past 20 GB with). Counted on the garbage collector's objects."""
    target = _stand(scene)
    scene.world.add_box("wall", (0.12, 0.12, 1.2), (-0.97, 2.02, 1.46))  # too tall to go over

    def tries() -> list[PlanFailure]:
        failures = []
        for _ in range(3 * WHOLE_FAILURES):
            try:
                perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=target)))
            except ManipulationPathBlocked as failure:
                failures.append(failure)
        return failures

    before = _scenes_alive()
    with simulated_robot(scene.world, "pr2", motion=MotionSettings(budget=1)):
        failures = run_top_level(tries)
    assert len(failures) == 3 * WHOLE_FAILURES
    assert all("RRTConnect found no way round" in str(f) for f in failures)  # each planned
    assert _scenes_alive() - before <= WHOLE_FAILURES  # without the release: all 12


def _scenes_alive() -> int:
    gc.collect()
    return sum(isinstance(o, CollisionScene) for o in gc.get_objects())
