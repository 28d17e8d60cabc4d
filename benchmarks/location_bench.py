"""Location designators in the kitchen: CPU time to the first and to the next solutions.

For the PR2, the HSR and Boxy in ``kitchen_scene`` it resolves the designators a
transport uses: where the robot sees the counter (``visible_for`` a target point, as
searching asks), where it reaches the mug (``reachable_for`` the mug), where the mug
goes on the table (``on`` the table top, ``for_`` the mug) and where the robot reaches
that placing spot (``reachable_for`` a target point), hands empty and holding the mug
(then the stand is judged by the place plan's tool poses). Per designator it prints the
median CPU time [ms] to the first pose and to each next pose (fresh designator and seed
per run), and the share of the first solutions' time spent in each stage: building the
layers, sampling cells (and lazy layer factors) into poses, validating candidates.

Goal (issue 15): each first solution <= 20 ms on the PR2, next solutions cheaper; a whole
PR2 transport (two location resolutions included) <= 115 ms. PyCRAM 1.0.4 takes 208 ms
(reachable) and 438 ms (visible) per location.

Usage: ``python benchmarks/location_bench.py [runs=15] [robots...]``
"""

from __future__ import annotations

import itertools
import statistics
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from robocram.costmaps import CostmapLocations
from robocram.costmaps.costmap_locations import Sampling
from robocram.designators import a, an
from robocram.execution import perform
from robocram.plans import install_actions, pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose

ROBOTS = ("pr2", "hsrb", "boxy")
NEXT = 4  # next solutions timed after the first
GOAL_FIRST_MS = 20.0


class Stages:
    """CPU time [ms] per stage of a pose stream, gathered by wrapping the stages' calls."""

    def __init__(self) -> None:
        self.layers = 0.0
        self.validation = 0.0

    def reset(self) -> None:
        """Start counting a new stream."""
        self.layers = self.validation = 0.0

    @contextmanager
    def instrumented(self, locs: CostmapLocations) -> Iterator[None]:
        """Time ``locs``' costmap building and validators for the block."""
        build = locs._costmap
        checks = dict(locs.validators)

        def timed_build(*args: Any, **kwargs: Any) -> Any:
            start = time.process_time()
            try:
                return build(*args, **kwargs)
            finally:
                self.layers += (time.process_time() - start) * 1e3

        def timed_check(check: Callable[..., bool]) -> Callable[..., bool]:
            def run(*args: Any) -> bool:
                start = time.process_time()
                try:
                    return check(*args)
                finally:
                    self.validation += (time.process_time() - start) * 1e3

            return run

        locs._costmap = timed_build  # type: ignore[method-assign]
        locs.validators = {name: timed_check(fn) for name, fn in checks.items()}
        try:
            yield
        finally:
            del locs._costmap
            locs.validators = checks


def designators(robot: str, placing: Pose) -> dict[str, Callable[[], Any]]:
    """The transport's designators for ``robot`` (fresh ones per call)."""
    counter = (1.6, 2.0, 1.05)  # [m] over counter_top_north, as searching looks there
    return {
        "visible_for target": lambda: a.location(visible_for=robot, target=counter),
        "reachable_for mug": lambda: a.location(reachable_for=robot, object="mug-1"),
        "on table for mug": lambda: a.location(on=("kitchen", "table_top"), for_="mug-1"),
        "reachable_for spot": lambda: a.location(reachable_for=robot, target=placing.position),
    }


def time_stream(
    locs: CostmapLocations, make: Callable[[], Any], stages: Stages, runs: int
) -> tuple[list[float], list[float], tuple[float, float, float], int]:
    """First-pose and next-pose CPU ms, the first poses' stage split, streams that failed."""
    firsts, nexts, split, failed = [], [], [0.0, 0.0, 0.0], 0
    for run in range(runs):
        locs.seed = run
        stages.reset()
        start = time.process_time()
        poses = locs.poses(make())
        try:
            next(poses)
        except Exception:  # a failed resolution is counted, not timed
            failed += 1
            continue
        first = (time.process_time() - start) * 1e3
        firsts.append(first)
        split[0] += stages.layers
        split[1] += stages.validation
        split[2] += first - stages.layers - stages.validation
        for _ in range(NEXT):
            start = time.process_time()
            if next(poses, None) is None:
                break
            nexts.append((time.process_time() - start) * 1e3)
    return firsts, nexts, (split[0], split[2], split[1]), failed


def _placing_spot(locs: CostmapLocations) -> Pose:
    """A place for the mug on the table within 20 cm of its north edge, where robots stand."""
    edge = locs.world.contacts.link_aabb("kitchen", "table_top")[1][1]
    places = locs.poses(a.location(on=("kitchen", "table_top"), for_="mug-1"))
    return next(p for p in places if p.position[1] > edge - 0.2)


@contextmanager
def holding_the_mug(scene: KitchenScene) -> Iterator[None]:
    """The robot, standing where it picked the mug up, holds it for the block."""
    world, robot = scene.world, scene.robot
    install_actions(world.kb)
    with world.snapshots.stored_state(), simulated_robot(world, robot):
        stand = a.location(reachable_for=robot, object="mug-1").reference()
        perform(an.action(type="parking-arms"))
        perform(an.action(type="navigating", target=stand))
        pick_up_object("mug-1")
        yield


def _print(
    robot: str,
    label: str,
    firsts: list[float],
    nexts: list[float],
    split: tuple[float, float, float],
    failed: int,
    runs: int,
) -> None:
    """One line: first and next pose [ms], the first poses' stage shares, failures."""
    if not firsts:
        print(f"{robot:5s} {label:20s} no solution in {runs} runs")
        return
    total = sum(split) or 1.0
    shares = "  ".join(
        f"{name} {100 * part / total:3.0f} %"
        for name, part in zip(("layers", "sampling", "validation"), split, strict=True)
    )
    goal = f"  (goal <= {GOAL_FIRST_MS:.0f} ms)" if robot == "pr2" else ""
    following = f"{statistics.median(nexts):6.1f}" if nexts else "   n/a"
    print(
        f"{robot:5s} {label:20s} first {statistics.median(firsts):6.1f} ms  "
        f"next {following} ms  [{shares}]" + (f"  {failed} failed" if failed else "") + goal
    )


def bench_robot(robot: str, runs: int, sampling: Sampling) -> None:
    """Print one robot's figures."""
    scene = kitchen_scene(robot)
    locs = CostmapLocations(scene.world, sampling=sampling)
    placing = _placing_spot(locs)
    stages = Stages()
    for make in designators(robot, placing).values():  # warm: maps loaded, IK tables built
        list(itertools.islice(locs.poses(make()), 2))
    with stages.instrumented(locs):
        for label, make in designators(robot, placing).items():
            _print(robot, label, *time_stream(locs, make, stages, runs), runs)
    with holding_the_mug(scene), stages.instrumented(locs):
        make = designators(robot, placing)["reachable_for spot"]
        _print(robot, "... holding the mug", *time_stream(locs, make, stages, runs), runs)
    scene.world.close()


def main() -> None:
    """Print the figures."""
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    robots = tuple(sys.argv[2:]) or ROBOTS
    print(f"location_bench: kitchen, median of {runs} seeds, CPU time of this process")
    for robot in robots:
        bench_robot(robot, runs, "random")


if __name__ == "__main__":
    main()
