"""Costmap benchmark: location designators for the PR2 in the tabletop scene.

Prints, for ``visible_for`` and ``reachable_for`` (the mug), the time to the first pose
and to ten poses, split into building the costmap and validating candidates, with the
candidates each validator rejected; the reachability maps' build time and their cached
load time; and a table of the IK calls the reachable validator made. Times are wall clock
and CPU time of this process (trust CPU on a shared machine), medians over ``runs``.

Reference: PyCRAM v1.0.4 (PR2 in a kitchen, same class of machine) takes 208 ms for a
reachable location and 438 ms for a visible one; the goal here is <= 20 ms to the first
solution of each. PyCRAM is not installable here (ROS 1), so its figures are quoted.

Usage: ``python benchmarks/costmap_bench.py [runs=5]``
"""

from __future__ import annotations

import itertools
import os
import statistics
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from robocram.costmaps import CostmapLocations, ReachabilityMaps
from robocram.costmaps import validators as validator_module
from robocram.designators import a
from robocram.kinematics import IKResult
from robocram.scenes import tabletop_scene

PYCRAM_MS = {"visible_for": 438.0, "reachable_for": 208.0}
GOAL_MS = 20.0


def _clock() -> tuple[float, float]:
    return time.perf_counter(), time.process_time()


def _since(start: tuple[float, float]) -> tuple[float, float]:
    wall, cpu = _clock()
    return 1000 * (wall - start[0]), 1000 * (cpu - start[1])


@contextmanager
def counted_ik() -> Iterator[list[tuple[float, IKResult]]]:
    """Record (CPU ms, result) of every IK call the reachable validator makes."""
    calls: list[tuple[float, IKResult]] = []
    original: Callable[..., IKResult] = validator_module.solve_ik

    def timed(*args: Any, **kwargs: Any) -> IKResult:
        start = time.process_time()
        result = original(*args, **kwargs)
        calls.append((1000 * (time.process_time() - start), result))
        return result

    validator_module.solve_ik = timed  # type: ignore[assignment]
    try:
        yield calls
    finally:
        validator_module.solve_ik = original  # type: ignore[assignment]


def _designator(key: str) -> Any:
    if key == "visible_for":
        return a.location(visible_for="pr2", object="mug-1")
    return a.location(reachable_for="pr2", object="mug-1")


def time_location(locs: CostmapLocations, key: str, runs: int) -> dict[str, float]:
    """Median wall/CPU ms: costmap alone, first pose, ten poses (fresh designator each run)."""
    rows: dict[str, list[float]] = {}
    for run in range(runs):
        locs.seed = run
        start = _clock()
        locs.costmap(_designator(key))
        for name, value in zip(("costmap wall", "costmap cpu"), _since(start), strict=True):
            rows.setdefault(name, []).append(value)
        start = _clock()
        poses = locs.poses(_designator(key))
        next(poses)
        for name, value in zip(("first wall", "first cpu"), _since(start), strict=True):
            rows.setdefault(name, []).append(value)
        list(itertools.islice(poses, 9))
        for name, value in zip(("ten wall", "ten cpu"), _since(start), strict=True):
            rows.setdefault(name, []).append(value)
    return {name: statistics.median(values) for name, values in rows.items()}


def reach_map_times(desc: Any) -> None:
    with tempfile.TemporaryDirectory() as cache:
        os.environ["ROBOCRAM_CACHE_DIR"] = cache
        for arm in ("left", "right"):
            start = _clock()
            ReachabilityMaps().get(desc, arm)
            built = _since(start)
            start = _clock()
            ReachabilityMaps().get(desc, arm)
            loaded = _since(start)
            print(f"  {arm:>5} arm: build {built[1]:7.0f} ms CPU ({built[0]:.0f} wall), "
                  f"cached load {loaded[1]:5.1f} ms CPU ({loaded[0]:.1f} wall)")  # fmt: skip
        del os.environ["ROBOCRAM_CACHE_DIR"]


def main(runs: int = 5) -> None:
    scene = tabletop_scene("pr2")
    desc = scene.world.robot("pr2").description
    print(f"costmap_bench: PR2 tabletop scene, median of {runs} runs (ms, wall / CPU)")
    print("\nreachability maps (fresh cache dir):")
    reach_map_times(desc)
    locs = CostmapLocations(scene.world)
    locs.poses(_designator("reachable_for")).__next__()  # warm: maps loaded, IK tables built
    print(f"\n{'designator':<14}{'costmap':>16}{'first pose':>18}{'10 poses':>18}"
          f"{'PyCRAM first':>14}{'goal':>7}")  # fmt: skip
    for key in ("visible_for", "reachable_for"):
        with counted_ik() as calls:
            t = time_location(locs, key, runs)
        print(f"{key:<14}{t['costmap wall']:8.1f} /{t['costmap cpu']:6.1f}"
              f"{t['first wall']:10.1f} /{t['first cpu']:6.1f}"
              f"{t['ten wall']:10.1f} /{t['ten cpu']:6.1f}"
              f"{PYCRAM_MS[key]:14.0f}{GOAL_MS:7.0f}")  # fmt: skip
        if calls:
            times = [ms for ms, _ in calls]
            failed = [ms for ms, r in calls if not r.success] or [0.0]
            ok = len(calls) - len([1 for _, r in calls if not r.success])
            print(
                f"  IK calls by the reachable validator: {len(calls)}, {ok} solved "
                f"({100 * ok / len(calls):.0f} %); CPU ms mean {statistics.mean(times):.2f}, "
                f"median {statistics.median(times):.2f}, max {max(times):.1f}; "
                f"failed calls mean {statistics.mean(failed):.2f}"
            )
    scene.world.close()


if __name__ == "__main__":
    main(*(int(arg) for arg in sys.argv[1:2]))
