"""Base paths of the PR2 in the kitchen: CPU time per path, fast and exact checks per path.

Run: ``.venv/bin/python benchmarks/base_path_bench.py [repeats]`` (default 3). The PR2,
arms parked, drives between every ordered pair of the stands the kitchen's plans use (its
start, the top drawer's stand as in kitchen_bench, the north counter's, the table's, the
east counter's): with the kitchen shut, with the top drawer open 0.4 m, and with a crate
in the middle of the room as well (OMPL plans around it).
Per set it prints the planners used, the median and p95 CPU time (``time.process_time``,
trajectory timing included) and the fast and exact collision checks per path, and the
median and p95 of the paths OMPL planned. Goals: <= 10 ms per base path, a median <= 100 ms
per planned one.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from collections import Counter
from itertools import permutations

from robocram.execution.failures import NavigationPathBlocked, NavigationPoseUnreachable
from robocram.motion import plan_base_path
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World

STANDS = {
    "start": (-0.8, 0.2, math.pi / 2),
    "drawer": (-1.59, 0.95, math.pi / 2),
    "counter-west": (-1.4, 1.0, math.pi / 2),
    "counter-mid": (-0.8, 1.0, math.pi / 2),
    "table-west": (-0.4, -0.3, -math.pi / 2),
    "table-east": (0.3, -0.3, -math.pi / 2),
    "east": (1.5, 0.6, 0.0),
}


def _pose(x: float, y: float, yaw: float) -> Pose:
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, math.ceil(0.95 * len(ordered)) - 1)]


def run(
    world: World, repeats: int
) -> tuple[list[float], list[int], list[int], Counter[str], list[float]]:
    """CPU times [ms], fast and exact checks, outcomes over every pair of stands, and the
    CPU times [ms] of the paths OMPL planned."""
    times, fast, exact, planned = [], [], [], []
    outcomes: Counter[str] = Counter()
    for a, b in permutations(STANDS, 2):
        world.set_pose("pr2", _pose(*STANDS[a]))
        for _ in range(repeats):
            begin = time.process_time()
            try:
                path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(*STANDS[b]))
            except NavigationPathBlocked:
                outcomes["blocked"] += 1
                continue
            except NavigationPoseUnreachable:
                outcomes["goal in collision"] += 1
                continue
            finally:
                times.append((time.process_time() - begin) * 1e3)
            outcomes[path.planner] += 1
            if path.planner.startswith("RRTConnect"):
                planned.append(times[-1])
            fast.append(path.fast_checks)
            exact.append(path.exact_checks)
    return times, fast, exact, outcomes, planned


def main() -> None:
    """Print the figures."""
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    world = kitchen_scene("pr2").world
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    print(f"base_path_bench: PR2, kitchen, {len(STANDS)} stands, {repeats} repeats; CPU time")
    for label, drawer in (
        ("kitchen shut", 0.0),
        ("top drawer open 0.4 m", 0.4),
        ("drawer open, crate at (0.7, 0.3)", 0.4),
    ):
        world.set_joint_states("kitchen", {"drawer_unit_drawer_3_joint": drawer})
        if "crate" in label:
            world.add_box("crate", (0.5, 0.5, 0.6), (0.7, 0.3, 0.3))
        times, fast, exact, outcomes, planned = run(world, repeats)
        print(f"{label}: {dict(outcomes)}")
        print(
            f"  CPU per path  median {statistics.median(times):6.2f} ms  p95 {_p95(times):7.2f} ms"
            f"  (goal <= 10 ms)"
        )
        if planned:
            print(
                f"  OMPL's paths  median {statistics.median(planned):6.2f} ms  p95 "
                f"{_p95(planned):7.2f} ms  (goal: median <= 100 ms)"
            )
        if fast:
            print(
                f"  fast checks   median {statistics.median(fast):6.0f}  p95 {_p95(fast):6.0f}"
                f"   exact checks median {statistics.median(exact):4.0f}  p95 {_p95(exact):4.0f}"
            )
    world.close()


if __name__ == "__main__":
    main()
