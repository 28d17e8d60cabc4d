"""Ready-made projection scenes (a robot, furniture and objects), placed per robot."""

from robocram.scenes.errors import SceneError, UnfitRobotError
from robocram.scenes.kitchen_scene import KitchenScene, kitchen_scene, kitchen_urdf
from robocram.scenes.placement import TabletopPlacement, tabletop_placement
from robocram.scenes.tabletop_scene import TabletopScene, tabletop_scene

__all__ = [
    "KitchenScene",
    "SceneError",
    "TabletopPlacement",
    "TabletopScene",
    "UnfitRobotError",
    "kitchen_scene",
    "kitchen_urdf",
    "tabletop_placement",
    "tabletop_scene",
]
