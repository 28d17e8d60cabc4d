"""Ready-made projection scenes (a robot, furniture and objects), placed per robot."""

from robocram.scenes.errors import SceneError, UnfitRobotError
from robocram.scenes.placement import TabletopPlacement, tabletop_placement
from robocram.scenes.tabletop_scene import TabletopScene, tabletop_scene

__all__ = [
    "SceneError",
    "TabletopPlacement",
    "TabletopScene",
    "UnfitRobotError",
    "tabletop_placement",
    "tabletop_scene",
]
