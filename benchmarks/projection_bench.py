"""Projection figures: scene build and the pick-up plan per robot, plan variants per second
in one world restored between runs, and the recording (non-physics) run.

Prints wall-clock medians [ms] over a few runs; no reference system is installable here.
Usage: ``python benchmarks/projection_bench.py [runs] [variants]``.
"""

from __future__ import annotations

import statistics
import sys
import time

from robocram.plans import pick_up
from robocram.projection import recorded_robot, simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped


def per_robot(runs: int) -> None:
    """Scene build and plan time per robot, each in a fresh world."""
    print(f"{'robot':8} {'scene [ms]':>11} {'plan [ms]':>10}")
    for robot in ("pr2", "hsrb", "boxy"):
        build, plan = [], []
        for _ in range(runs):
            t0 = time.perf_counter()
            scene = tabletop_scene(robot)
            t1 = time.perf_counter()
            with simulated_robot(scene.world, robot):
                pick_up(scene.look_target)
            plan.append(time.perf_counter() - t1)
            build.append(t1 - t0)
            scene.world.close()
        build_ms, plan_ms = 1e3 * statistics.median(build), 1e3 * statistics.median(plan)
        print(f"{robot:8} {build_ms:11.1f} {plan_ms:10.1f}")


def variants(count: int) -> None:
    """Project ``count`` variants of the PR2 plan (mug shifted along y) in one world."""
    scene = tabletop_scene("pr2")
    world, mug = scene.world, scene.world.object("mug-1")
    base = world.pose(mug)
    t0 = time.perf_counter()
    succeeded = 0
    for i in range(count):
        with world.snapshots.stored_state():
            dy = 0.1 * ((i % 5) - 2) / 2  # [m] -0.1 .. 0.1
            world.set_pose(mug, Pose((base.position[0], base.position[1] + dy, base.position[2])))
            look = PoseStamped("map", (base.position[0], base.position[1] + dy, base.position[2]))
            with simulated_robot(world, "pr2"):
                pick_up(look)
            succeeded += 1
    elapsed = time.perf_counter() - t0
    print(
        f"{count} pr2 plan variants in one world: {elapsed:.2f} s, "
        f"{count / elapsed:.1f} variants/s, {succeeded} succeeded"
    )
    world.close()


def recording(runs: int) -> None:
    """The same plan in the recording environment (no physics)."""
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        mug = PoseStamped("base_footprint", (0.62, -0.15, 0.7))
        with recorded_robot("pr2", objects={"mug": mug}):
            pick_up(PoseStamped("map", (0.6, -0.15, 0.7)))
        times.append(time.perf_counter() - t0)
    print(f"recording pr2 plan: {1e3 * statistics.median(times):.1f} ms")


if __name__ == "__main__":
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    per_robot(runs)
    variants(int(sys.argv[2]) if len(sys.argv) > 2 else 100)
    recording(runs)
