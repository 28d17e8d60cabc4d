"""What a user's transport costs: a fresh scene and a fresh resolver for every run.

``transport_timing`` keeps one scene, one resolver's reachability maps and every cache
warm across its runs; a user who builds a scene and transports once pays for more. Here
each run builds ``kitchen_scene(robot)`` from the robot's name, binds the default
resolver (``simulated_robot`` without ``locations``) and transports the mug from the same
seeded spot as ``transport_timing``; then it transports again in that scene (the user's
second plan). Wall and CPU time are both printed. The process's first transport is timed
apart: it builds what the scenes after it share (the parsed URDFs, and on them IK's solvers
and start tables, kept while a scene holds them) and is excluded from the cold figure, as
the issue asks.
"""

from __future__ import annotations

import statistics
import time
from dataclasses import dataclass, field

from transport_timing import _mug_spot

from robocram.designators import a
from robocram.execution.failures import PlanFailure
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose

KEPT = (
    "kept while something holds them: the parsed URDF models (robocram.robots.model_memo "
    "holds them weakly; the previous scene holds them while the next is built) and what "
    "is kept on them (IK's solvers and start tables, the hands, the reachability maps "
    "read from disk once); per scene: the world and what it keeps (coal obstacle shapes, "
    "base footprints); nothing else carries over"
)


@dataclass
class ColdTimes:
    """Wall and CPU times [ms] of each kind of run."""

    first: tuple[float, float] = (0.0, 0.0)
    build: list[tuple[float, float]] = field(default_factory=list)
    cold: list[tuple[float, float]] = field(default_factory=list)
    second: list[tuple[float, float]] = field(default_factory=list)
    failed: int = 0


def _timed_transport(scene: KitchenScene, spot: Pose) -> tuple[float, float, bool]:
    """Wall and CPU [ms] of one transport from ``spot``; whether it succeeded."""
    world = scene.world
    with world.snapshots.stored_state():
        z = world.pose("mug-1").position[2]
        world.set_pose("mug-1", Pose((*spot.position[:2], z), spot.orientation))
        wall, cpu = time.perf_counter(), time.process_time()
        try:
            with simulated_robot(world, scene.robot):
                transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
            ok = True
        except PlanFailure:
            ok = False
        return (time.perf_counter() - wall) * 1e3, (time.process_time() - cpu) * 1e3, ok


def cold_transport_times(robot: str, runs: int) -> ColdTimes:
    """The process's first transport, then ``runs`` fresh scenes with two transports each."""
    out = ColdTimes()
    scene = kitchen_scene(robot)
    wall, cpu, _ = _timed_transport(scene, _mug_spot(0))
    out.first = (wall, cpu)
    scene.world.close()
    for seed in range(runs):
        wall, cpu = time.perf_counter(), time.process_time()
        scene = kitchen_scene(robot)
        out.build.append(((time.perf_counter() - wall) * 1e3, (time.process_time() - cpu) * 1e3))
        *cold, ok = _timed_transport(scene, _mug_spot(seed))
        out.cold.append((cold[0], cold[1]))
        out.failed += not ok
        *again, _ = _timed_transport(scene, _mug_spot(seed))
        out.second.append((again[0], again[1]))
        scene.world.close()
    return out


def _medians(pairs: list[tuple[float, float]]) -> str:
    wall = statistics.median(p[0] for p in pairs)
    cpu = statistics.median(p[1] for p in pairs)
    return f"wall {wall:6.1f} ms  CPU {cpu:6.1f} ms"


def print_cold(robot: str, times: ColdTimes, goal: str = "") -> None:
    """The cold and second-plan medians beside the first transport and the build."""
    runs = len(times.cold)
    print(
        f"{robot:5s} transport, fresh scene  cold  {_medians(times.cold)}   "
        f"second in that scene  {_medians(times.second)}   ({runs} runs, "
        f"{runs - times.failed}/{runs} succeeded){goal}"
    )
    print(
        f"{robot:5s}   scene build {_medians(times.build)}; the process's first transport "
        f"(builds what is kept) wall {times.first[0]:6.1f} ms  CPU {times.first[1]:6.1f} ms"
    )
    print(f"{robot:5s}   {KEPT}")
