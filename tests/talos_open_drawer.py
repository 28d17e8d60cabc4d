"""TALOS's kitchen with the bowl's drawer pulled out as the search opens it, the bowl in
it: where the look into the drawer and the pick out of it are tested."""

from __future__ import annotations

import warnings
from pathlib import Path

from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose

TALOS = Path(__file__).parents[1] / "examples" / "robots" / "talos.py"
DRAWER = "drawer_unit_drawer_3"  # the bowl's
OPENING = 0.4  # [m] as the search opens it


def talos_kitchen_drawer_open() -> tuple[KitchenScene, Pose, Pose]:
    """The scene, and the drawer's link pose closed and open (the bowl moved with it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the draft's doubts
        scene = kitchen_scene(str(TALOS))
    world = scene.world
    before = world.link_pose("kitchen", DRAWER)
    world.set_joint_states("kitchen", {f"{DRAWER}_joint": OPENING})
    after = world.link_pose("kitchen", DRAWER)
    world.set_pose("bowl-1", after * before.inverse() * world.pose("bowl-1"))
    return scene, before, after
