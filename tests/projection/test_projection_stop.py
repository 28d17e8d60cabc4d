"""Stopping a task inside projection's long commands: it ends there and the world stays whole.

A task that asks itself to stop at its n-th stop point makes "a stop arrives in the middle
of the command" exact and repeatable, with no timing in the test: the commands are called
directly (not through ``perform``), so every stop point counted is one inside the command.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import pytest

from robocram.designators import a
from robocram.execution import (
    Task,
    TaskListener,
    TaskStopped,
    TopLevel,
    checkpoint,
    listening,
    perform,
)
from robocram.execution.task_context import binding_task
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.motion.tool_goal import POSITION_TOLERANCE
from robocram.plans import transport
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.arm import move_joints, move_tcp
from robocram.projection.articulation import move_part
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat
from tests.projection.drawer_stand import DRAWER, pr2_before_drawer

INSIDE_TORSO = Pose((0.0, 0.0, 0.8), quat.from_euler(0.0, math.pi / 2, 0.0))  # IK fails here


class StopAtPoint(Task):
    """A task that asks itself to stop when it reaches its ``n``-th stop point."""

    def __init__(self, n: int) -> None:
        super().__init__("stopping")
        self.n = n
        self.reached = 0

    def check_stop(self) -> None:
        self.reached += 1
        if self.reached >= self.n:
            self.stop()
        super().check_stop()


@pytest.fixture(scope="module")
def kitchen() -> Iterator[tuple[KitchenScene, ProjectedRobot]]:
    """The PR2 with parked arms in front of the drawer that holds the bowl."""
    scene, robot = pr2_before_drawer(0.3, 1.0)
    yield scene, robot
    scene.world.close()


def test_a_stop_ends_a_failing_ik_search_between_descents_and_the_arm_stays(
    kitchen: tuple[KitchenScene, ProjectedRobot],
) -> None:
    scene, robot = kitchen
    world = scene.world
    target = robot.base_pose() * INSIDE_TORSO
    unstopped = StopAtPoint(10**9)
    with (
        world.snapshots.stored_state(),
        binding_task(unstopped),
        pytest.raises(Exception) as failed,
    ):
        move_tcp(robot, "right", target)
    assert type(failed.value).__name__ == "ManipulationPoseUnreachable"
    assert unstopped.reached > 10  # the search passed many stop points: one per descent
    before = world.joint_states(robot.name)
    for n in (1, 5, unstopped.reached // 2):
        task = StopAtPoint(n)
        with binding_task(task), pytest.raises(TaskStopped):
            move_tcp(robot, "right", target)
        assert task.reached == n  # it ended at the very stop point it was stopped at
        assert world.joint_states(robot.name) == pytest.approx(before, abs=1e-12)


@pytest.mark.parametrize("n", [3, 12, 13, 25, 33])  # the opening passes 37 stop points
def test_a_stop_while_a_drawer_opens_leaves_no_attachment_and_the_bowl_in_the_drawer(
    kitchen: tuple[KitchenScene, ProjectedRobot], n: int
) -> None:
    scene, robot = kitchen
    world = scene.world
    joint, handle = f"{DRAWER}_joint", f"{DRAWER}_handle"
    with world.snapshots.stored_state():
        bowl_before = world.pose("bowl-1").position
        task = StopAtPoint(n)
        with binding_task(task), pytest.raises(TaskStopped):
            move_part(robot, "right", "kitchen", joint, handle, 0.30)
        assert task.reached == n
        opened = world.joint_states("kitchen")[joint]
        assert 0.0 <= opened <= 0.30 + 1e-9
        if 0.0 < opened < 0.30:  # the hand holds the handle where the drawer stopped
            tool = world.link_pose(robot.name, robot.arm("right").tool_frame)
            assert tool.distance_to(world.link_pose("kitchen", handle)) < POSITION_TOLERANCE
        assert world.bodies.attached_to("bowl-1") is None
        assert all(att.obj != "bowl-1" for att in world.bodies.all_attachments())
        bowl = world.pose("bowl-1").position
        assert bowl[1] == pytest.approx(bowl_before[1] - opened, abs=1e-6)  # rode along
        assert bowl[0] == pytest.approx(bowl_before[0], abs=1e-6)


def test_a_stop_ends_a_simulation_after_a_whole_step(
    kitchen: tuple[KitchenScene, ProjectedRobot],
) -> None:
    world = kitchen[0].world
    with world.snapshots.stored_state():
        start = world.physics.time
        task = StopAtPoint(10)
        with binding_task(task), pytest.raises(TaskStopped):
            world.physics.simulate(2.0, stop_check=checkpoint)
        assert task.reached == 10
        assert world.physics.time - start == pytest.approx(9 * world.time_step, abs=1e-12)


def test_a_stop_ends_the_prolog_simulate_predicate_of_a_task(
    kitchen: tuple[KitchenScene, ProjectedRobot],
) -> None:
    world = kitchen[0].world
    with world.snapshots.stored_state():
        start = world.physics.time
        task = StopAtPoint(4)
        with binding_task(task), pytest.raises(TaskStopped):
            world.kb.holds("world(W), simulate(W, 2.0)")
        assert world.physics.time - start < 4 * world.time_step + 1e-12


def test_a_stopped_plan_does_not_drive_and_a_stopped_drive_is_whole(
    kitchen: tuple[KitchenScene, ProjectedRobot],
) -> None:
    scene, robot = kitchen
    world = scene.world
    goal = PoseStamped("base_footprint", (0.3, 0.0, 0.0))
    with world.snapshots.stored_state():
        before = world.pose(robot.name)
        with pytest.raises(TaskStopped), simulated_robot(world, robot.name) as run:
            run.top_level.stop()
            perform(a.motion(type="going", target=goal))
        assert world.pose(robot.name).distance_to(before) < 1e-12
        with pytest.raises(TaskStopped), simulated_robot(world, robot.name) as run:
            perform(a.motion(type="going", target=goal))
            run.top_level.stop()  # after the drive: the plan ends, the base stays at the goal
            checkpoint()
        assert world.pose(robot.name).distance_to(before) == pytest.approx(0.3, abs=1e-9)


class StopAtTask(TaskListener):
    """Stops the top level when the ``n``-th task of the run starts (no clock involved)."""

    def __init__(self, n: int, executed: list[JointTrajectory]) -> None:
        self.n, self.started, self.executed = n, 0, executed
        self.top_level: TopLevel | None = None
        self.executed_at_stop: int | None = None

    def task_started(self, task: Task) -> None:
        self.started += 1
        if self.started == self.n and self.top_level is not None:
            self.executed_at_stop = len(self.executed)
            self.top_level.stop()


@pytest.mark.parametrize("n", [3, 9, 16, 24])  # of the 27 tasks a transport starts
def test_a_transport_stopped_at_its_nth_task_moves_no_further(n: int) -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    executed: list[JointTrajectory] = []
    stopper = StopAtTask(n, executed)
    with (
        trajectory_listener(executed.append),
        listening(stopper),
        simulated_robot(world, "pr2") as run,
    ):
        stopper.top_level = run.top_level
        with pytest.raises(TaskStopped):
            transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
    assert stopper.executed_at_stop is not None  # the stop came during the transport
    assert len(executed) <= stopper.executed_at_stop + 1  # at most the motion under way
    held = world.bodies.attached_to("mug-1")
    assert held is None or held.robot == "pr2"  # on its counter, or in the hand: whole
    world.close()


def test_a_stop_ends_an_arm_joint_motion_while_it_is_planned_and_the_arm_stays(
    kitchen: tuple[KitchenScene, ProjectedRobot],
) -> None:
    """``moving-arm-joints`` out of parking towards the counter: its checks pass stop
    points, and a stop at any of them leaves the arm where it was (the campaign's slowest
    stops were in this command, issue 42)."""
    scene, robot = kitchen
    world = scene.world
    across = dict(robot.description.arms["right"].parking, r_shoulder_pan_joint=-0.8)
    with world.snapshots.stored_state():
        before = world.joint_states(robot.name)
        unstopped = StopAtPoint(10**9)
        with world.snapshots.stored_state(), binding_task(unstopped):
            move_joints(robot, "right", across)
        assert unstopped.reached > 5
        for n in (1, unstopped.reached // 2, unstopped.reached - 1):
            task = StopAtPoint(n)
            with binding_task(task), pytest.raises(TaskStopped):
                move_joints(robot, "right", across)
            assert task.reached == n
            now = world.joint_states(robot.name)  # where the planning or the motion ended
            for joint, start in before.items():
                end = across.get(joint, start)
                assert min(start, end) - 1e-9 <= now[joint] <= max(start, end) + 1e-9
            world.set_joint_states(robot.name, before)
