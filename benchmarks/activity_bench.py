"""Breakfast for two, then clearing, over seeded variants per robot: success and wall time.

Run: ``.venv/bin/python benchmarks/activity_bench.py [N | A:B] [robots...]`` (defaults 5
and the PR2, the HSR and Boxy; a robot may be a description file, e.g. the drafted
``tests/data/fetch/fetch.py`` and ``tests/data/stretch/stretch.py``). A variant (seeded)
is a household: which drawer holds the bowls, the cups and the cutlery (one of
:data:`DRAWERS` each, the knowledge saying so: its usual places), and every item up to
:data:`JITTER` from its spot, deeper into or out of its drawer, shelf or counter (along
its link's x: things kept side by side stay apart). Seed 0 is the default kitchen's
arrangement. Per robot
it prints how often setting the table succeeded (every thing at its seat) and how often
clearing a set table did (every thing back), and the wall time of each activity: cold is a fresh
scene's first activity (the scene built before the clock starts), warm a second breakfast
in a scene that already ran one (the table cleared by resetting the world, so the robot's
caches are warm). Figures on a loaded machine drift by 15-50 %.
"""

from __future__ import annotations

import math
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
# the top drawers that may hold each group (the first: the default kitchen's), one group
# per drawer; all are the same 0.6 m deep drawer model, so a spot in one fits the others
LIE = math.pi / 2  # [rad] how things lie in the default kitchen's drawers, from the drawer's
# axes (square to the map there): the same in a drawer facing another way (a knife along
# the drawer's width, not through its front)
DRAWERS = {
    "drawer_unit_drawer_3": (
        "drawer_unit_drawer_3",
        "stove_unit_drawer_2",
        "east_drawers_2_drawer_3",
    ),
    "cutlery_unit_drawer_4": ("cutlery_unit_drawer_4", "east_drawers_1_drawer_3"),
    "cutlery_unit_drawer_3": ("cutlery_unit_drawer_3", "east_drawers_3_drawer_3"),
}


def variant(seed: int) -> tuple[list[ItemPlace], list[ItemPlace]]:
    """Where the household keeps the items (seeded; seed 0: the default kitchen's
    arrangement), and where they are: each moved up to :data:`JITTER` along its link's x
    from its spot."""
    rng = random.Random(seed)
    moved = {old: (old if seed == 0 else rng.choice(new)) for old, new in DRAWERS.items()}
    kept = [
        p if moved.get(p.link, p.link) == p.link else replace(p, link=moved[p.link], yaw=LIE)
        for p in BREAKFAST_PLACES
    ]
    places = [replace(p, xy=(p.xy[0] + rng.uniform(-JITTER, JITTER), p.xy[1])) for p in kept]
    return kept, places


def _timed(scene: EnvironmentScene, action: str, **keys: object) -> tuple[bool, float, str]:
    """Whether ``action`` succeeded in ``scene``, its wall time [s], and why it failed."""
    start = time.perf_counter()
    why = ""
    try:
        with simulated_robot(scene.world, scene.robot):
            perform(an.action(type=action, **keys))
    except PlanFailure as failure:
        why = f"{type(failure).__name__}: {str(failure)[:160]}"
    return not why, time.perf_counter() - start, why


def run_robot(robot: str, seeds: range) -> None:
    """Print the figures of the breakfasts and clearings by ``robot`` of ``seeds``."""
    variants = len(seeds)
    set_ok, clear_ok, cold, clearing, warm = 0, 0, [], [], []
    for seed in seeds:
        kept, places = variant(seed)
        scene = breakfast_scene(robot, places=places, kept=kept)
        with scene.world.snapshots.stored_state():
            ok, wall, why = _timed(scene, "setting-table", people=2)
            set_ok += ok
            cold.append(wall)
            cleared, wall, why_not = _timed(scene, "clearing-table")
            clear_ok += ok and cleared  # clearing an empty table is no success
            clearing.append(wall)
        drawers = sorted({p.link for p in kept if "drawer" in p.link})
        print(
            f"  seed {seed:2d} {' '.join(drawers)}: set {'ok' if ok else why}; "
            f"cleared {'ok' if cleared else why_not}",
            flush=True,
        )
        if seed == seeds[0]:
            warm.append(_timed(scene, "setting-table", people=2)[1])
        scene.world.close()
    print(
        f"{Path(robot).stem:6s} setting {set_ok}/{variants} ({100 * set_ok / variants:.0f} %), "
        f"clearing {clear_ok}/{variants} ({100 * clear_ok / variants:.0f} %); wall [s]: "
        f"breakfast cold median {statistics.median(cold):.1f} (max {max(cold):.1f}), "
        f"warm {warm[0]:.1f}; clearing median {statistics.median(clearing):.1f}"
    )


def main() -> None:
    """``N`` runs seeds 0 to N - 1; ``A:B`` seeds A to B - 1 (a batch split by hand)."""
    given = sys.argv[1] if len(sys.argv) > 1 else "5"
    first, _, last = given.rpartition(":")
    seeds = range(int(first or 0), int(last))
    robots = tuple(sys.argv[2:]) or ROBOTS
    print(f"breakfast for two, then clearing: seeded variants {seeds.start}-{seeds.stop - 1}")
    for robot in robots:
        run_robot(robot, seeds)


if __name__ == "__main__":
    main()
