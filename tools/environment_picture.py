"""Take docs/pycram_kitchen.png: the PR2 after a transport in PyCRAM's kitchen.

The kitchen is tests/data/pycram/kitchen_env.py (the drafted and edited description);
drawers and the table are stand-ins, as their meshes are not shipped. The PR2 takes the
bowl out of the island's drawer, puts it on the table and closes the drawer; the picture
is rendered with PyBullet's TINY renderer through ``World.save_png``. Run
``python tools/environment_picture.py`` from the repository root.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from robocram.designators import a
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import environment_scene
from robocram.scenes.environment_check import environment_from
from robocram.scenes.environment_scene import ItemPlace
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import Camera

ROOT = Path(__file__).resolve().parents[1]
PICTURE = ROOT / "docs" / "pycram_kitchen.png"
EYE = (1.3, -1.7, 2.4)  # [m] in map
TARGET = (-0.7, 0.4, 0.5)  # [m] in map


def look_at(eye: tuple[float, float, float], target: tuple[float, float, float]) -> Camera:
    """A camera (optical frame: z ahead, x right, y down) at ``eye`` looking at ``target``."""
    ahead = np.subtract(target, eye)
    ahead /= np.linalg.norm(ahead)
    right = np.cross(ahead, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    m = np.eye(4)
    m[:3, :3] = np.column_stack((right, np.cross(ahead, right), ahead))
    m[:3, 3] = eye
    return Camera(Pose.from_matrix(m), math.radians(75.0), math.radians(56.0), near=0.1, far=20.0)


def main() -> None:
    desc = environment_from(ROOT / "tests" / "data" / "pycram" / "kitchen_env.py")
    bowl = ItemPlace("bowl-1", "bowl", "kitchen_island_left_upper_drawer_main", (0.1, 0.0))
    start = Pose((0.4, 0.0, 0.0), quat.from_euler(0.0, 0.0, math.pi))
    began = time.perf_counter()
    scene = environment_scene(desc, "pr2", [bowl], start)
    with simulated_robot(scene.world, scene.robot):
        transport("bowl", a.location(on=(scene.environment, "table_area_main"), for_="bowl-1"))
    print(f"transport: {time.perf_counter() - began:.1f} s")
    print("wrote", scene.world.view.save_png(PICTURE, look_at(EYE, TARGET), 960, 720))
    scene.world.close()


if __name__ == "__main__":
    main()
