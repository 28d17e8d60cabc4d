"""Ready-made projection scenes (a robot, furniture and objects), placed per robot."""

from robocram.scenes.environment_description import (
    ContainerDescription,
    EnvironmentDescription,
    SurfaceDescription,
)
from robocram.scenes.environment_draft import EnvironmentDraft, draft_environment
from robocram.scenes.environment_scene import EnvironmentScene, environment_scene
from robocram.scenes.errors import (
    SceneArgumentError,
    SceneError,
    UnfitRobotError,
)
from robocram.scenes.kitchen_scene import KitchenScene, kitchen_scene, kitchen_urdf
from robocram.scenes.placement import TabletopPlacement, tabletop_placement
from robocram.scenes.stand_in import StandIn
from robocram.scenes.tabletop_scene import TabletopScene, tabletop_scene
from robocram.scenes.workcell_scene import workcell_scene, workcell_spots

__all__ = [
    "ContainerDescription",
    "EnvironmentDescription",
    "EnvironmentDraft",
    "EnvironmentScene",
    "KitchenScene",
    "SceneArgumentError",
    "SceneError",
    "StandIn",
    "SurfaceDescription",
    "TabletopPlacement",
    "TabletopScene",
    "UnfitRobotError",
    "draft_environment",
    "environment_scene",
    "kitchen_scene",
    "kitchen_urdf",
    "tabletop_placement",
    "tabletop_scene",
    "workcell_scene",
    "workcell_spots",
]
