"""Grasping figures: pick_up_object and place_object per robot in the kitchen.

For each seed the mug is shifted on ``counter_top_north`` by up to 4 cm (seeded), the
robot stands before it, picks it up, is driven to the table and puts it down. Prints the
median and the slowest time [ms] of each plan over the seeds, with the success count and
the grasps used; the grasp model's own cost (the KB door answering every grasp of the mug
for one arm) is printed apart. No reference system is installable here (PyCRAM 1.0.4 takes
~1,150 ms for a whole PR2 pick-and-place with two location resolutions, issue 15).
Usage: ``python benchmarks/grasp_bench.py [seeds]``.
"""

from __future__ import annotations

import math
import random
import statistics
import sys
import time
from collections import Counter

from robocram.plans import pick_up_object, place_object
from robocram.plans.basic_actions import navigate, park_arms
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

STANDOFF = {"pr2": (0.45, 0.45), "hsrb": (0.45, 0.45), "boxy": (0.65, 0.55)}  # [m]
COUNTER_FRONT, TABLE_EDGE, TABLE_TOP = 1.88, -0.95, 0.751  # [m]
SHIFT = 0.04  # [m] largest shift of the mug per axis
TARGET_Y = -1.15  # [m] where the mug goes on the table (x = 0)


Times = tuple[float, float]  # [s] wall clock, CPU time of this process


def _clock() -> Times:
    return time.perf_counter(), time.process_time()


def _since(start: Times) -> Times:
    now = _clock()
    return now[0] - start[0], now[1] - start[1]


def one_run(robot: str, seed: int) -> tuple[Times, Times, str]:
    """Pick and place times and the grasp used, for one seeded mug placement."""
    scene = kitchen_scene(robot)
    world = scene.world
    rng = random.Random(seed)
    here = world.pose("mug-1").position
    mug = (here[0] + rng.uniform(-SHIFT, SHIFT), here[1] + rng.uniform(-SHIFT, SHIFT), here[2])
    world.set_pose("mug-1", Pose(mug))
    counter, table = STANDOFF[robot]
    try:
        with simulated_robot(world, robot):
            park_arms()
            north = quat.from_euler(0.0, 0.0, math.pi / 2)
            navigate(PoseStamped("map", (here[0], COUNTER_FRONT - counter, 0.0), north))
            start = _clock()
            held = pick_up_object("mug-1")
            pick = _since(start)
            south = quat.from_euler(0.0, 0.0, -math.pi / 2)
            navigate(PoseStamped("map", (0.0, TABLE_EDGE + table, 0.0), south))
            start = _clock()
            place_object(held, PoseStamped("map", (0.0, TARGET_Y, TABLE_TOP)))
            place = _since(start)
        return pick, place, held.grasp
    finally:
        world.close()


def door_cost(robot: str, repeats: int = 50) -> float:
    """Median time [ms] of the KB door listing every grasp of the mug for one arm."""
    scene = kitchen_scene(robot)
    world = scene.world
    arm = next(iter(a for a in world.robot(robot).description.arms if a != "neck"))
    times = []
    with simulated_robot(world, robot):
        for _ in range(repeats):
            t0 = time.perf_counter()
            list(world.kb.query("object_grasp('mug-1', R, A, N, G, P, L)", R=robot, A=arm))
            times.append(time.perf_counter() - t0)
    world.close()
    return 1e3 * statistics.median(times)


def _figures(times: list[Times]) -> str:
    wall, cpu = [1e3 * t[0] for t in times], [1e3 * t[1] for t in times]
    return f"{statistics.median(wall):6.1f} /{statistics.median(cpu):6.1f} {max(cpu):6.1f}"


def main(seeds: int) -> None:
    """Print the figures of every robot."""
    print(f"{seeds} seeds per robot; [ms] median wall / CPU, slowest CPU (trust CPU when shared)")
    print(f"{'robot':6} {'ok':>5} {'pick':>21} {'place':>21} {'door':>6}  grasps")
    for robot in ("pr2", "hsrb", "boxy"):
        picks: list[Times] = []
        places: list[Times] = []
        grasps: Counter[str] = Counter()
        failed = 0
        for seed in range(seeds):
            try:
                pick, place, grasp = one_run(robot, seed)
            except Exception as failure:  # noqa: BLE001 - a failed run is counted, not fatal
                failed += 1
                print(f"  {robot} seed {seed}: {type(failure).__name__}: {str(failure)[:100]}")
                continue
            picks.append(pick)
            places.append(place)
            grasps[grasp] += 1
        ok = f"{seeds - failed}/{seeds}"
        if not picks:
            print(f"{robot:6} {ok:>5}")
            continue
        print(
            f"{robot:6} {ok:>5} {_figures(picks):>21} {_figures(places):>21} "
            f"{door_cost(robot):6.2f}  " + ", ".join(f"{g} x{n}" for g, n in sorted(grasps.items()))
        )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
