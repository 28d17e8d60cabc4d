"""``make demo``: a PR2 in projection picks up a mug, headless, in a few seconds.

Builds the tabletop scene, performs the robot-independent plan ``robocram.plans.pick_up``
inside ``simulated_robot``, prints the task tree and writes ``out/demo.png`` rendered from
a camera looking at the table.
"""

from __future__ import annotations

import time
from pathlib import Path

from robocram.plans import pick_up
from robocram.projection import looking_orientation, simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose

VIEW_FROM = (2.3, 1.7, 1.9)  # [m] in map, where the picture is taken from
VIEW_AT = (0.5, -0.1, 0.7)  # [m] in map, what it looks at


def main(out_dir: Path = Path("out")) -> Path:
    """Run the PR2 pick-up, print the task tree, write and return the PNG's path."""
    start = time.perf_counter()
    scene = tabletop_scene("pr2")
    with simulated_robot(scene.world, "pr2", name="pick-mug") as run:
        result = pick_up(scene.look_target)
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
