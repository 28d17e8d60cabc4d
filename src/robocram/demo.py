"""``make demo``: a PR2 in projection picks up a mug, headless, in a few seconds.

Loads the scene and the robot-independent plan of ``examples/pick_mug.py``, performs it
inside ``simulated_robot``, prints the task tree and writes ``out/demo.png`` rendered from
a camera looking at the table.
"""

from __future__ import annotations

import importlib.util
import sys
import time
from pathlib import Path
from types import ModuleType

from robocram.projection import simulated_robot
from robocram.projection.neck import looking_orientation
from robocram.tf import Pose

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "pick_mug.py"
VIEW_FROM = (2.3, 1.7, 1.9)  # [m] in map, where the picture is taken from
VIEW_AT = (0.5, -0.1, 0.7)  # [m] in map, what it looks at


def load_example(path: Path = EXAMPLE) -> ModuleType:
    """Import the pick-mug example (plan and scene) from the repository's examples folder."""
    if not path.is_file():
        raise FileNotFoundError(
            f"the demo runs the plan in {path}, which is missing; run it from a checkout "
            "of the repository (pip install -e .)"
        )
    spec = importlib.util.spec_from_file_location("pick_mug_example", path)
    if spec is None or spec.loader is None:
        raise ImportError(f"cannot import {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def main(out_dir: Path = Path("out")) -> Path:
    """Run the PR2 pick-up, print the task tree, write and return the PNG's path."""
    start = time.perf_counter()
    example = load_example()
    scene = example.make_scene("pr2")
    with simulated_robot(scene.world, "pr2", name="pick-mug") as run:
        result = example.pick_mug(scene.look_target)
    print(run.tree.render())
    mug = scene.world.pose(result.object_name).position
    print(
        f"\nthe {result.arm} arm holds {result.object_name} at "
        f"({mug[0]:.3f}, {mug[1]:.3f}, {mug[2]:.3f}) m in map"
    )
    out_dir.mkdir(parents=True, exist_ok=True)
    camera = Pose(VIEW_FROM, looking_orientation(VIEW_FROM, VIEW_AT))
    png = scene.world.save_png(out_dir / "demo.png", camera, width=800, height=600)
    scene.world.close()
    print(f"wrote {png.resolve()} in {time.perf_counter() - start:.2f} s total")
    return png


if __name__ == "__main__":
    main()
