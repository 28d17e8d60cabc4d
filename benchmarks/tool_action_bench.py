"""The tool actions per robot: success and wall time per action over a few seeds.

Each run builds a fresh tabletop (the robot grips the tool first, not timed), places the
work a little off its spot (a seeded shift of up to 2 cm), then times the action alone:
pouring 60 ml from a cup into a bowl (success: >= 90 % of the particles landed), wiping
a 20 x 14 cm region of the table (>= 90 % covered), cutting a loaf into 4 slices (4
slices, widths within 20 %), stirring in a bowl (the whole spiral followed). A robot
that reaches no path from where the tabletop puts it carries the tool to stands that do.
Usage: python benchmarks/tool_action_bench.py [seeds] [robot ...]
(default 3 seeds, the PR2; robots are built-in names or description files)
"""

from __future__ import annotations

import math
import random
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.scenes.tool_objects import add_tool_object
from robocram.tf import Pose

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "plans"))
from tool_setup import ToolScene, tool_scene  # noqa: E402


def _pour(scene: ToolScene, dx: float, dy: float) -> bool:
    x, y, h = scene.spot
    add_tool_object(scene.world, "bowl-1", "bowl", Pose((x + 0.05 + dx, y - 0.1 + dy, h)))
    with simulated_robot(scene.world, scene.robot):
        r = perform(an.action(type="pouring", source="cup-1", target="bowl-1", amount=60))
    return bool(r.landed is not None and r.landed >= 0.9 * r.particles)


def _wipe(scene: ToolScene, dx: float, dy: float) -> bool:
    x, y, _ = scene.spot
    region = ((x + dx, y + dy), (0.2, 0.14))
    with simulated_robot(scene.world, scene.robot):
        r = perform(an.action(type="wiping", surface="table", region=region, tool="sponge-1"))
    return bool(r.covered >= 0.9)


def _cut(scene: ToolScene, dx: float, dy: float) -> bool:
    x, y, h = scene.spot
    add_tool_object(scene.world, "bread-1", "bread", Pose((x + dx, y + dy, h + 0.04)))
    with simulated_robot(scene.world, scene.robot):
        r = perform(an.action(type="cutting", object="bread-1", tool="knife-1", slices=4))
    return len(r.slices) == 4 and max(r.widths) <= 1.2 * min(r.widths)


def _mix(scene: ToolScene, dx: float, dy: float) -> bool:
    x, y, h = scene.spot
    add_tool_object(scene.world, "bowl-1", "bowl", Pose((x + dx, y + dy, h)))
    with simulated_robot(scene.world, scene.robot):
        r = perform(an.action(type="mixing", container="bowl-1", tool="spoon-1"))
    return bool(r.fraction >= 1.0)


ACTIONS: dict[str, tuple[str, Callable[[ToolScene, float, float], bool]]] = {
    "pouring": ("cup", _pour),
    "wiping": ("sponge", _wipe),
    "cutting": ("knife", _cut),
    "mixing": ("spoon", _mix),
}


def main(seeds: int, robots: list[str]) -> None:
    """Print success and wall time per robot and action over ``seeds`` seeded shifts."""
    for robot in robots:
        _robot(seeds, robot)


def _robot(seeds: int, robot: str) -> None:
    label = Path(robot).stem
    for action, (tool, run) in ACTIONS.items():
        done, times = 0, []
        for seed in range(seeds):
            rng = random.Random(seed)
            dx, dy = rng.uniform(-0.02, 0.02), rng.uniform(-0.02, 0.02)
            try:
                scene = tool_scene(robot, tool)
            except Exception as failure:  # the tool never reached the hand: a failed run
                print(f"  {action} seed {seed}: set-up {type(failure).__name__}: {failure}"[:200])
                continue
            start = time.perf_counter()
            try:
                ok = run(scene, dx, dy)
            except Exception as failure:  # a failed run counts, with its cause
                print(f"  {action} seed {seed}: {type(failure).__name__}: {failure}"[:200])
                ok = False
            times.append(time.perf_counter() - start)
            done += ok
            scene.world.close()
        print(
            f"{label} {action:8s} success {done}/{seeds}  wall median "
            f"{statistics.median(times or [math.nan]):.2f} s  max {max(times or [math.nan]):.2f} s"
        )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3, sys.argv[2:] or ["pr2"])
