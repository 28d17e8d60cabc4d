"""How long stopping a task takes while projection opens a drawer (issue: <= 100 ms).

A thread opens the PR2's kitchen drawer by 0.3 m inside its own task; after a delay the
main thread stops that task and times how long the command takes to end. Run:
``python benchmarks/stop_bench.py``.
"""

from __future__ import annotations

import contextlib
import math
import statistics
import threading
import time

from robocram.execution import Task, TaskStopped
from robocram.execution.task_context import binding_task
from robocram.projection import ProjectedRobot
from robocram.projection.articulation import move_part
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DRAWER = "drawer_unit_drawer_3"
DELAYS = (0.01, 0.025, 0.04, 0.06, 0.08)  # [s] after the start, when the stop is asked


def stop_latency(delay: float) -> tuple[float, float]:
    """Seconds [s] from ``task.stop()`` to the command's end, and the drawer value [m] then."""
    scene = kitchen_scene("pr2")
    world = scene.world
    desc = world.robot(scene.robot).description
    world.set_joint_states(
        scene.robot, {j: v for a in desc.arms.values() for j, v in a.parking.items()}
    )
    handle_x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
    facing_north = quat.from_euler(0.0, 0.0, math.pi / 2)
    world.set_pose(scene.robot, Pose((handle_x - 0.19, 0.95, 0.0), facing_north))
    robot = ProjectedRobot.of(world, scene.robot)
    task = Task("open-drawer")
    ended: list[float] = []

    def opening() -> None:
        with binding_task(task), contextlib.suppress(TaskStopped):
            move_part(robot, "right", "kitchen", f"{DRAWER}_joint", f"{DRAWER}_handle", 0.3)
        ended.append(time.perf_counter())

    worker = threading.Thread(target=opening)
    worker.start()
    time.sleep(delay)
    asked = time.perf_counter()
    task.stop()
    worker.join()
    reached = world.joint_states("kitchen")[f"{DRAWER}_joint"]
    world.close()
    return max(0.0, ended[0] - asked), reached


def main() -> None:
    print("stop while the PR2 opens a drawer by 0.3 m (goal: <= 100 ms)")
    latencies = []
    for delay in DELAYS:
        latency, reached = stop_latency(delay)
        latencies.append(latency)
        when = f"stop after {delay * 1e3:4.0f} ms"
        print(f"  {when}: ended {latency * 1e3:6.1f} ms later, drawer at {reached:.3f} m")
    print(f"median {statistics.median(latencies) * 1e3:.1f} ms, max {max(latencies) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
