"""Pick up a mug with any robot: one plan, unchanged, on the PR2, the HSR and Boxy.

Run it: ``python examples/pick_mug.py [pr2|hsrb|boxy|path/to/my_robot.py]`` (a description
file as ``robocram robot draft`` writes it works too). The plan is ``robocram.plans.pick_up``;
only the scene's placement differs per robot.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene


def main(robot: str = "pr2") -> None:
    """Run the plan on ``robot`` (a name or a description file); print the tree and the mug."""
    start = time.perf_counter()
    scene = tabletop_scene(robot)
    with simulated_robot(scene.world, scene.robot) as run:
        result = pick_up(scene.look_target)
    mug = scene.world.pose(result.object_name).position
    print(run.tree.render())
    print(
        f"{scene.robot}: {result.arm} arm holds {result.object_name} at {np.round(mug, 3)} "
        f"({time.perf_counter() - start:.2f} s)"
    )
    scene.world.close()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "pr2")
