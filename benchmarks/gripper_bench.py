"""Time gripping by contact: closing in steps until the fingers squeeze an object.

Run: ``.venv/bin/python benchmarks/gripper_bench.py [runs]`` (default 20). For each
robot's first gripper arm it puts a 4 cm can between the fingers and prints the median and
p95 of ``grip`` and ``open_gripper`` [ms], and of a grip that closes on nothing (the
whole sweep, ``GripperClosedCompletely``). There is no reference figure: PyCRAM's
projection closes to the commanded pose and attaches without any contact test.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable

from robocram.execution.failures import GripperClosedCompletely
from robocram.projection import ProjectedRobot
from robocram.projection.gripper import grip, open_gripper
from robocram.world import World

ROBOTS = ("pr2", "hsrb", "boxy")


def _ms(fn: Callable[[], object]) -> float:
    start = time.perf_counter()
    fn()
    return (time.perf_counter() - start) * 1000.0


def _between_fingers(robot: ProjectedRobot, arm: str) -> tuple[float, float, float]:
    """The centre [m] of the finger links' origins (map)."""
    points = [robot.world.link_pose(robot.name, f).position for f in robot.arm(arm).gripper_links]
    x, y, z = (sum(p[k] for p in points) / len(points) for k in range(3))
    return x, y, z


def _closing_on_nothing(robot: ProjectedRobot, arm: str) -> None:
    try:
        grip(robot, arm)
    except GripperClosedCompletely:
        return
    raise AssertionError("gripped something in an empty world")


def bench(name: str, runs: int) -> None:
    """Print grip, open and empty-grip times [ms] for robot ``name``."""
    with World() as world:
        world.bodies.add_floor()
        world.add_robot(name)
        robot = ProjectedRobot.of(world, name)
        arm = next(k for k, a in robot.description.arms.items() if a.gripper is not None)
        times: dict[str, list[float]] = {"grip": [], "open": [], "empty grip": []}
        for _ in range(runs):
            open_gripper(robot, arm)
            world.bodies.add_cylinder("can", 0.02, 0.1, pose=_between_fingers(robot, arm), mass=0.1)
            times["grip"].append(_ms(lambda: grip(robot, arm)))
            times["open"].append(_ms(lambda: open_gripper(robot, arm)))
            world.remove("can")
            times["empty grip"].append(_ms(lambda: _closing_on_nothing(robot, arm)))
    figures = "  ".join(
        f"{k} {statistics.median(v):6.2f} / {sorted(v)[int(0.95 * (len(v) - 1))]:6.2f} ms"
        for k, v in times.items()
    )
    print(f"{name:6s} {arm:6s} median / p95: {figures}")


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 20
    for robot in ROBOTS:
        bench(robot, count)
