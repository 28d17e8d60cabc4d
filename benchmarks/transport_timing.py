"""Transport runs for kitchen_bench: seeded mug placements, success, times and their split.

Each run puts the mug at a seeded random spot (and heading) on the north counter, between
the sink and the stove, and transports it to the table with a costmap resolver of that
seed. CPU time (this process; pybullet runs in it) is split by the innermost of: location
resolution (the costmap generator, its validators' IK included), IK of arm motions,
perception (``detecting``), other motions (driving, looking, gripper, torso, the arm's
own stepping), settling (physics simulated after letting go, to check the object rests)
and the rest (the plans, the KB, the grasp model). The world is restored after each run.
"""

from __future__ import annotations

import math
import statistics
import time
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

import robocram.projection.arm as projected_arm
from robocram.costmaps import CostmapLocations
from robocram.costmaps.reachability_map import ReachabilityMaps
from robocram.designators import a
from robocram.execution import TaskListener, listening
from robocram.execution.failures import PlanFailure
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world.physics import Physics

COUNTER_X = (-1.7, -1.15)  # [m] map x between the sink and the stove
COUNTER_Y = (1.96, 2.14)  # [m] map y: 8 to 26 cm in from the counter's front edge
GOALS = {"pr2": (0.95, 115.0), "hsrb": (0.90, None), "boxy": (0.90, None)}
CATEGORIES = ("location", "ik", "motion", "perception", "settling", "rest")


class Split:
    """CPU time per category; the innermost open category takes the time."""

    def __init__(self) -> None:
        self.totals: Counter[str] = Counter()
        self.stack: list[str] = []
        self.mark = time.process_time()

    def _switch(self) -> None:
        now = time.process_time()
        self.totals[self.stack[-1] if self.stack else "rest"] += now - self.mark
        self.mark = now

    def enter(self, category: str) -> None:
        self._switch()
        self.stack.append(category)

    def leave(self) -> None:
        self._switch()
        self.stack.pop()

    def finish(self) -> dict[str, float]:
        """The totals [ms] once the run is over."""
        self._switch()
        return {c: self.totals[c] * 1e3 for c in CATEGORIES}


class MotionTimer(TaskListener):
    """Opens a category for every PERFORM of a motion: perception or motion."""

    def __init__(self, split: Split) -> None:
        self.split = split
        self.open: set[int] = set()

    def performing(self, task: Any, designator: Any) -> None:
        kind = str(designator.get("type"))
        self.split.enter("perception" if kind == "detecting" else "motion")
        self.open.add(id(task))

    def task_finished(self, task: Any) -> None:
        if id(task) in self.open:
            self.open.discard(id(task))
            self.split.leave()


class TimedLocations(CostmapLocations):
    """Costmap locations whose pose stream counts as location resolution."""

    split: Split | None = None

    def poses(self, designator: Any) -> Iterator[Pose]:
        stream = super().poses(designator)
        while True:
            if self.split is None:
                raise RuntimeError("TimedLocations needs its split set")
            self.split.enter("location")
            try:
                pose = next(stream)
            except StopIteration:
                return
            finally:
                self.split.leave()
            yield pose


def timed(split: Split, category: str, function: Callable[..., Any]) -> Callable[..., Any]:
    """``function`` counted as ``category``."""

    def counted(*args: Any, **kwargs: Any) -> Any:
        split.enter(category)
        try:
            return function(*args, **kwargs)
        finally:
            split.leave()

    return counted


@dataclass
class TransportTimes:
    """Outcomes of one robot's runs: successes, total times [ms], the split of each."""

    runs: int = 0
    succeeded: int = 0
    totals: list[float] = field(default_factory=list)
    splits: list[dict[str, float]] = field(default_factory=list)
    failures: Counter[str] = field(default_factory=Counter)


def _mug_spot(seed: int) -> Pose:
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(*COUNTER_X), rng.uniform(*COUNTER_Y)
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, rng.uniform(-math.pi, math.pi)))


def transport_times(robot: str, runs: int) -> TransportTimes:
    """Transport the mug ``runs`` times, each from its seeded spot, with that seed."""
    scene = kitchen_scene(robot)
    world = scene.world
    maps = ReachabilityMaps()
    out = TransportTimes(runs=runs)
    solve_ik, simulate, settle = projected_arm.solve_ik, Physics.simulate, Physics.settle
    for seed in range(runs):
        spot = _mug_spot(seed)
        split = Split()
        locations = TimedLocations(world, seed=seed, reach_maps=maps)
        locations.split = split
        projected_arm.solve_ik = timed(split, "ik", solve_ik)
        Physics.simulate = timed(split, "settling", simulate)  # type: ignore[method-assign]
        Physics.settle = timed(split, "settling", settle)  # type: ignore[method-assign]
        with world.snapshots.stored_state():
            z = world.pose("mug-1").position[2]
            world.set_pose("mug-1", Pose((*spot.position[:2], z), spot.orientation))
            target = a.location(on=("kitchen", "table_top"), for_="mug-1")
            with (
                simulated_robot(world, scene.robot, locations=locations),
                listening(MotionTimer(split)),
            ):
                start = time.process_time()
                split.mark = start
                try:
                    transport("mug", target)
                    out.succeeded += 1
                except PlanFailure as failure:
                    out.failures[type(failure).__name__] += 1
                out.totals.append((time.process_time() - start) * 1e3)
                out.splits.append(split.finish())
        projected_arm.solve_ik = solve_ik
        Physics.simulate = simulate  # type: ignore[method-assign]
        Physics.settle = settle  # type: ignore[method-assign]
    world.close()
    return out


def _p95(values: list[float]) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, math.ceil(0.95 * len(ordered)) - 1)]


def print_transports(robot: str, times: TransportTimes) -> None:
    """Success rate, median and p95 with the goals beside them, then the median split."""
    rate_goal, time_goal = GOALS[robot]
    rate = times.succeeded / max(times.runs, 1)
    goal = f"goal <= {time_goal:.0f} ms; PyCRAM 1,150 ms" if time_goal else "no time goal"
    print(
        f"{robot:5s} transport mug          {times.succeeded}/{times.runs} = {rate:5.1%} "
        f"(goal >= {rate_goal:.0%})  median {statistics.median(times.totals):7.1f} ms  "
        f"p95 {_p95(times.totals):7.1f} ms   ({goal})"
    )
    total = sum(times.totals) or 1.0
    split = "  ".join(
        f"{c} {statistics.median(s[c] for s in times.splits):5.1f} "
        f"({sum(s[c] for s in times.splits) / total:4.0%})"
        for c in CATEGORIES
    )
    print(f"{robot:5s}   median ms (share of all): {split}")
    if times.failures:
        print(f"{robot:5s}   failures: {dict(times.failures)}")
