"""Timings in the kitchen: building the scene, detecting, searching, opening a drawer, transport.

Run: ``.venv/bin/python benchmarks/kitchen_bench.py [runs] [transports]`` (defaults 10
and 50). Per robot it prints the scene build (cold: description parsed; warm: a loaded
description passed in), one ``detecting`` motion with the mug in view, and a seeded
search for the mug (success rate, median, p95 over ``runs`` costmap seeds); for the PR2
also opening and closing the top drawer with the bowl in it. Then, per robot,
``transports`` seeded transports of the mug from a random spot on the north counter to
the table (success rate, median, p95, and the CPU time split into location resolution,
IK of arm motions, other motions, perception and the rest). PyCRAM 1.0.4's figures for
comparison (PR2, its kitchen, headless, this class of machine): world and robot
1,296 ms, detecting 107 ms, a pick-and-place with two location resolutions 1,150 ms.
Last, the PR2's transport as a user gets it (``cold_transport``): a fresh scene and
resolver per run, wall and CPU time, and the second transport in that scene.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
from collections.abc import Callable

from cold_transport import cold_transport_times, print_cold
from transport_timing import print_transports, transport_times

from robocram.costmaps import CostmapLocations
from robocram.designators import a, an, using_location_resolver
from robocram.execution import perform
from robocram.execution.failures import PlanFailure
from robocram.plans import install_actions
from robocram.plans.search import search
from robocram.projection import simulated_robot
from robocram.robots import load_description
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

ROBOTS = ("pr2", "hsrb", "boxy")
DRAWER = "drawer_unit_drawer_3"


def _timed(fn: Callable[[], object]) -> float:
    """CPU time [ms] of this process (pybullet runs in it): less hostage to machine load."""
    start = time.process_time()
    fn()
    return (time.process_time() - start) * 1e3


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, math.ceil(0.95 * len(ordered)) - 1)]


def build_times(robot: str, runs: int) -> tuple[float, float]:
    """Median cold and warm build time [ms] of ``kitchen_scene(robot)``."""
    cold, warm = [], []
    desc = load_description(robot)
    scenes: list[KitchenScene] = []
    for _ in range(runs):
        cold.append(_timed(lambda: scenes.append(kitchen_scene(robot))))
        warm.append(_timed(lambda: scenes.append(kitchen_scene(desc))))
        while scenes:
            scenes.pop().world.close()
    return statistics.median(cold), statistics.median(warm)


def search_and_detect(robot: str, runs: int) -> tuple[int, list[float], list[float]]:
    """Successes, search times [ms] and detecting times [ms] over ``runs`` seeds."""
    found, searches, detections = 0, [], []
    scene = kitchen_scene(robot)
    world = scene.world
    for seed in range(runs):
        locations = CostmapLocations(world, seed=seed)
        with (
            world.snapshots.stored_state(),
            simulated_robot(world, scene.robot),
            using_location_resolver(locations.resolver()),
        ):
            start = time.process_time()
            try:
                search("mug")
            except PlanFailure:  # a failed search counts as a failure
                searches.append((time.process_time() - start) * 1e3)
                continue
            searches.append((time.process_time() - start) * 1e3)
            found += 1
            detect = a.motion(type="detecting", object=an.object(type="mug"))
            detections.append(_timed(lambda detect=detect: perform(detect)))
    world.close()
    return found, searches, detections


def drawer_times(runs: int) -> tuple[float, float]:
    """Median time [ms] for the PR2 to open the top drawer by 0.3 m and to close it."""
    scene = kitchen_scene("pr2")
    world = scene.world
    install_actions(world.kb)
    x = world.link_pose("kitchen", f"{DRAWER}_handle").position[0]
    stand = Pose((x - 0.19, 0.95, 0.0), quat.from_euler(0.0, 0.0, math.pi / 2))
    opening, closing = [], []
    with simulated_robot(world, scene.robot):
        perform(an.action(type="parking-arms"))
        perform(an.action(type="navigating", target=stand))
        for _ in range(runs):
            act = an.action(type="opening", object=f"{DRAWER}_handle", distance=0.3)
            opening.append(_timed(lambda act=act: perform(act)))
            shut = an.action(type="closing", object=DRAWER)
            closing.append(_timed(lambda shut=shut: perform(shut)))
    world.close()
    return statistics.median(opening), statistics.median(closing)


def main() -> None:
    """Print the figures."""
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 10
    transports = int(sys.argv[2]) if len(sys.argv) > 2 else 50
    print(f"kitchen_bench: {runs} runs per figure; CPU time of this process")
    for robot in ROBOTS:
        cold, warm = build_times(robot, max(3, runs // 3))
        print(
            f"{robot:5s} kitchen_scene build    cold {cold:7.1f} ms  warm {warm:7.1f} ms"
            "   (goal <= 100 ms; PyCRAM 1,296 ms)"
        )
        found, searches, detections = search_and_detect(robot, runs)
        print(
            f"{robot:5s} search mug             {found}/{runs} found  median "
            f"{statistics.median(searches):7.1f} ms  p95 {_p95(searches):7.1f} ms"
        )
        if detections:
            print(
                f"{robot:5s} detecting (mug in view) median {statistics.median(detections):6.2f}"
                " ms   (goal <= 5 ms; PyCRAM 107 ms)"
            )
    opened, closed = drawer_times(max(3, runs // 3))
    print(f"pr2   drawer 0.3 m        open {opened:7.1f} ms  close {closed:7.1f} ms")
    for robot in ROBOTS:
        print_transports(robot, transport_times(robot, transports))
    goal = "   (goal: cold <= 150 ms wall, warm <= 100 ms)"
    print_cold("pr2", cold_transport_times("pr2", max(5, transports // 5)), goal)


if __name__ == "__main__":
    main()
