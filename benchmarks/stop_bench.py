"""How long stopping a task takes during projection's long commands (issue: <= 100 ms).

For each command a thread runs it inside its own task in the PR2 kitchen; after a delay
the main thread stops that task and times how long the command takes to end. Cases: an
arm motion whose IK fails (every solution collides with the torso, ~90 ms unstopped), two
seconds of physics, a drive, an arm's joint motion (``moving-arm-joints``), and opening a
drawer by 0.3 m. The world is put back after
every run. Then a PR2 kitchen transport is stopped at 20 seeded moments of its run
(issue 24: max <= 100 ms idle). Run: ``python benchmarks/stop_bench.py``.
"""

from __future__ import annotations

import contextlib
import math
import statistics
import threading
import time
from collections.abc import Callable

import numpy as np

from robocram.designators import a
from robocram.execution import Task, TaskStopped, checkpoint
from robocram.execution.failures import PlanFailure
from robocram.execution.task_context import binding_task
from robocram.plans import transport
from robocram.projection import ProjectedRobot, SimulatedRun, simulated_robot
from robocram.projection.arm import move_joints, move_tcp
from robocram.projection.articulation import move_part
from robocram.projection.navigation import drive
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World

DRAWER = "drawer_unit_drawer_3"
DELAYS = (0.0, 0.005, 0.01, 0.025, 0.04, 0.06, 0.08)  # [s] after the start, when stop is asked
TRANSPORT_MOMENTS = 20  # seeded moments of a transport at which it is stopped
INSIDE_TORSO = Pose((0.0, 0.0, 0.8), quat.from_euler(0.0, math.pi / 2, 0.0))  # IK fails: collides

Command = Callable[[ProjectedRobot], object]


def _unreachable(robot: ProjectedRobot) -> object:
    return move_tcp(robot, "right", robot.base_pose() * INSIDE_TORSO)


def _simulate(robot: ProjectedRobot) -> object:
    return robot.world.physics.simulate(2.0, stop_check=checkpoint)


def _drive(robot: ProjectedRobot) -> object:
    return drive(robot, robot.base_pose() * Pose((0.3, 0.0, 0.0)))


def _open_drawer(robot: ProjectedRobot) -> object:
    return move_part(robot, "right", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.3)


def _arm_joints(robot: ProjectedRobot) -> object:
    """``moving-arm-joints``: the right arm from stretched out ahead over to the left, a
    joint-space path round the counter (the campaign's slow stops, issue 42)."""
    arm = robot.description.arms["right"]
    ahead = {j: 0.0 for j in arm.joints}
    robot.world.set_joint_states(robot.name, ahead)
    across = dict(ahead, r_shoulder_pan_joint=0.6, r_elbow_flex_joint=-1.8)
    return move_joints(robot, "right", across)


CASES: dict[str, Command] = {
    "arm motion whose IK fails": _unreachable,
    "moving-arm-joints": _arm_joints,
    "simulate 2 s": _simulate,
    "drive 0.3 m": _drive,
    "open a drawer 0.3 m": _open_drawer,
}


def _unstopped(robot: ProjectedRobot, command: Command) -> float:
    """Seconds [s] the command runs inside a task that nobody stops."""
    started = time.perf_counter()
    with binding_task(Task("command")), contextlib.suppress(PlanFailure):
        command(robot)
    return time.perf_counter() - started


def stop_latency(robot: ProjectedRobot, command: Command, delay: float) -> float:
    """Seconds [s] from ``task.stop()`` to the command's end (0 if it ended before)."""
    task = Task("command")
    ended: list[float] = []

    def running() -> None:
        with binding_task(task), contextlib.suppress(TaskStopped, PlanFailure):
            command(robot)
        ended.append(time.perf_counter())

    worker = threading.Thread(target=running)
    worker.start()
    time.sleep(delay)
    asked = time.perf_counter()
    task.stop()
    worker.join()
    return max(0.0, ended[0] - asked)


def kitchen_robot() -> ProjectedRobot:
    """The PR2 in the kitchen, arms parked, its right hand in front of the drawer handle."""
    scene = kitchen_scene("pr2")
    world = scene.world
    desc = world.robot(scene.robot).description
    world.set_joint_states(
        scene.robot, {j: v for a in desc.arms.values() for j, v in a.parking.items()}
    )
    handle_x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
    facing_north = quat.from_euler(0.0, 0.0, math.pi / 2)
    world.set_pose(scene.robot, Pose((handle_x - 0.19, 0.95, 0.0), facing_north))
    return ProjectedRobot.of(world, scene.robot)


def _transport_once(world: World, stop_after: float | None) -> tuple[float, float]:
    """Transport the mug in a thread; stop its top level ``stop_after`` [s] in (None: never).

    Returns (seconds the run lasted, seconds from the stop to its end; 0 if it ended first).
    """
    box: dict[str, SimulatedRun] = {}
    started, ended = threading.Event(), []

    def running() -> None:
        with contextlib.suppress(TaskStopped, PlanFailure), simulated_robot(world, "pr2") as run:
            box["run"] = run
            started.set()
            transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
        ended.append(time.perf_counter())

    worker = threading.Thread(target=running)
    begun = time.perf_counter()
    worker.start()
    started.wait()
    if stop_after is None:
        worker.join()
        return ended[0] - begun, 0.0
    time.sleep(stop_after)
    asked = time.perf_counter()
    box["run"].top_level.stop()
    worker.join()
    return ended[0] - begun, max(0.0, ended[0] - asked)


def transport_case(moments: int = TRANSPORT_MOMENTS, seed: int = 0) -> None:
    """Stop a PR2 kitchen transport at ``moments`` seeded moments of its run (wall time)."""
    scene = kitchen_scene("pr2")
    world = scene.world
    with world.snapshots.stored_state():
        _transport_once(world, None)  # warm: IK start tables, reachability maps
    with world.snapshots.stored_state():
        lasted, _ = _transport_once(world, None)
    delays = sorted(np.random.default_rng(seed).uniform(0.0, lasted, moments))
    latencies = []
    for delay in delays:
        with world.snapshots.stored_state():
            latencies.append(_transport_once(world, float(delay))[1])
    print(
        f"  {'transport, ' + str(moments) + ' moments':28s} median "
        f"{statistics.median(latencies) * 1e3:6.1f} ms, max {max(latencies) * 1e3:6.1f} ms"
        f"  (unstopped it runs {lasted * 1e3:6.1f} ms)"
    )
    world.close()


def main() -> None:
    robot = kitchen_robot()
    world = robot.world
    with contextlib.suppress(PlanFailure), world.snapshots.stored_state():
        _unreachable(robot)  # builds the IK start tables once, as any first motion does
    print("stopping a task during a projection command (goal: max <= 100 ms)")
    for name, command in CASES.items():
        with world.snapshots.stored_state():
            unstopped = _unstopped(robot, command)
        latencies = []
        for delay in DELAYS:
            with world.snapshots.stored_state():
                latencies.append(stop_latency(robot, command, delay))
        print(
            f"  {name:28s} median {statistics.median(latencies) * 1e3:6.1f} ms, "
            f"max {max(latencies) * 1e3:6.1f} ms  (unstopped it runs {unstopped * 1e3:6.1f} ms)"
        )
    world.close()
    transport_case()


if __name__ == "__main__":
    main()
