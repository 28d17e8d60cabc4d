"""Breakfast for two, then clearing, over seeded variants per robot: success and wall time.

Run: ``.venv/bin/python benchmarks/activity_bench.py [variants] [robots...]`` (defaults 5
and the PR2, the HSR and Boxy; a robot may be a description file, e.g. the drafted
``tests/data/fetch/fetch.py`` and ``tests/data/stretch/stretch.py``). A variant moves
every breakfast item up to :data:`JITTER` from where it is kept (seeded), deeper into or
out of its drawer, shelf or counter (along its link's x: things kept side by side stay
apart). Per robot
it prints how often setting the table succeeded (every thing at its seat) and how often
clearing a set table did (every thing back), and the wall time of each activity: cold is a fresh
scene's first activity (the scene built before the clock starts), warm a second breakfast
in a scene that already ran one (the table cleared by resetting the world, so the robot's
caches are warm). Figures on a loaded machine drift by 15-50 %.
"""

from __future__ import annotations

import random
import statistics
import sys
import time
from dataclasses import replace
from pathlib import Path

from robocram.designators import an
from robocram.execution.failures import PlanFailure
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene
from robocram.scenes.environment_scene import EnvironmentScene, ItemPlace

JITTER = 0.02  # [m] each item's shift from its usual spot, per axis, at most
ROBOTS = ("pr2", "hsrb", "boxy")


def variant(seed: int) -> list[ItemPlace]:
    """The breakfast items, each moved up to :data:`JITTER` along its link's x (seeded)."""
    rng = random.Random(seed)
    return [
        replace(p, xy=(p.xy[0] + rng.uniform(-JITTER, JITTER), p.xy[1])) for p in BREAKFAST_PLACES
    ]


def _timed(scene: EnvironmentScene, action: str, **keys: object) -> tuple[bool, float]:
    """Whether ``action`` succeeded in ``scene`` and its wall time [s]."""
    start = time.perf_counter()
    try:
        with simulated_robot(scene.world, scene.robot):
            perform(an.action(type=action, **keys))
        ok = True
    except PlanFailure:
        ok = False
    return ok, time.perf_counter() - start


def run_robot(robot: str, variants: int) -> None:
    """Print the figures of ``variants`` breakfasts and clearings by ``robot``."""
    set_ok, clear_ok, cold, clearing, warm = 0, 0, [], [], []
    for seed in range(variants):
        scene = breakfast_scene(robot, places=variant(seed))
        with scene.world.snapshots.stored_state():
            ok, wall = _timed(scene, "setting-table", people=2)
            set_ok += ok
            cold.append(wall)
            cleared, wall = _timed(scene, "clearing-table")
            clear_ok += ok and cleared  # clearing an empty table is no success
            clearing.append(wall)
        if seed == 0:
            warm.append(_timed(scene, "setting-table", people=2)[1])
        scene.world.close()
    print(
        f"{Path(robot).stem:6s} setting {set_ok}/{variants} ({100 * set_ok / variants:.0f} %), "
        f"clearing {clear_ok}/{variants} ({100 * clear_ok / variants:.0f} %); wall [s]: "
        f"breakfast cold median {statistics.median(cold):.1f} (max {max(cold):.1f}), "
        f"warm {warm[0]:.1f}; clearing median {statistics.median(clearing):.1f}"
    )


def main() -> None:
    variants = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    robots = tuple(sys.argv[2:]) or ROBOTS
    print(f"breakfast for two, then clearing: {variants} seeded variants per robot")
    for robot in robots:
        run_robot(robot, variants)


if __name__ == "__main__":
    main()
