"""Time table-driven motions: grounding (property check + generated rules) and PERFORM.

Runs in the recording environment (no physics), so the figures are the cost of the motion
vocabulary itself: checking a designator's properties against the motion table, its
``motion_grounding/2`` rules, matching the module and the table dispatch.
Usage: ``python benchmarks/motion_table_bench.py [count]``.
"""

from __future__ import annotations

import statistics
import sys
import time
from collections.abc import Callable

from robocram.designators import MotionDesignator, a, an
from robocram.execution import perform
from robocram.logic import current_kb
from robocram.projection import recorded_robot
from robocram.tf import PoseStamped

MUG = PoseStamped("base_footprint", (0.62, -0.15, 0.70))
MOTIONS: dict[str, Callable[[int], MotionDesignator]] = {
    "moving-torso": lambda i: a.motion(type="moving-torso", joint_angle=0.1 + i * 1e-4),
    "moving-tcp arm": lambda i: a.motion(type="moving-tcp", arm="left", target=(0.5, 0.1, 0.9)),
    "moving-tcp both": lambda i: a.motion(
        type="moving-tcp", left_target=(0.5, 0.2, 0.9), right_target=(0.5, -0.2, 0.9)
    ),
    "gripping": lambda i: a.motion(type="gripping", gripper="right"),
    "detecting": lambda i: a.motion(type="detecting", object=an.object(type="mug")),
}


def median_us(fn: Callable[[int], object], count: int, rounds: int = 5) -> float:
    """Median over ``rounds`` of the mean time [us] of ``fn(i)`` for ``count`` calls."""
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        for i in range(count):
            fn(i)
        times.append((time.perf_counter() - start) / count)
    return 1e6 * statistics.median(times)


def main(count: int) -> None:
    """Print grounding and PERFORM times per motion type."""
    with recorded_robot("pr2", objects={"mug": MUG}):
        kb = current_kb()
        for label, make in MOTIONS.items():
            ground = median_us(lambda i, make=make: make(i).reference(kb), count)
            run = median_us(lambda i, make=make: perform(make(i)), count)
            print(f"{label:16s} ground {ground:7.0f} us   perform {run:7.0f} us")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200)
