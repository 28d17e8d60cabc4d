"""Projection figures: scene build and the pick-mug plan per robot, and the recording run.

Prints wall-clock medians [ms] over a few runs; no reference system is installable here.
"""

from __future__ import annotations

import importlib.util
import statistics
import sys
import time
from pathlib import Path
from types import ModuleType

from robocram.projection import recorded_robot, simulated_robot
from robocram.tf import PoseStamped

RUNS = 5
EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "pick_mug.py"


def _example() -> ModuleType:
    spec = importlib.util.spec_from_file_location("pick_mug_example", EXAMPLE)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def main() -> None:
    """Print build and plan times per robot."""
    example = _example()
    print(f"{'robot':8} {'scene [ms]':>11} {'plan [ms]':>10}")
    for robot in ("pr2", "hsrb", "boxy"):
        build, plan = [], []
        for _ in range(RUNS):
            t0 = time.perf_counter()
            scene = example.make_scene(robot)
            t1 = time.perf_counter()
            with simulated_robot(scene.world, robot):
                example.pick_mug(scene.look_target)
            plan.append(time.perf_counter() - t1)
            build.append(t1 - t0)
            scene.world.close()
        build_ms, plan_ms = 1e3 * statistics.median(build), 1e3 * statistics.median(plan)
        print(f"{robot:8} {build_ms:11.1f} {plan_ms:10.1f}")
    times = []
    for _ in range(RUNS):
        t0 = time.perf_counter()
        mug = PoseStamped("base_footprint", (0.62, -0.15, 0.7))
        with recorded_robot("pr2", objects={"mug": mug}):
            example.pick_mug(PoseStamped("map", (0.6, -0.15, 0.7)))
        times.append(time.perf_counter() - t0)
    print(f"recording pr2 plan: {1e3 * statistics.median(times):.1f} ms")


if __name__ == "__main__":
    main()
