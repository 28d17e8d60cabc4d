"""Robot-independent plans: they ask the knowledge base about the robot and PERFORM designators."""

from robocram.plans.action_table import ACTION_TYPES, install_actions, perform_action
from robocram.plans.action_type import ActionType
from robocram.plans.containers import Container, close_container, container, open_container
from robocram.plans.errors import PlanSetupError
from robocram.plans.grasp_failures import (
    ObjectUngraspable,
    PickUpFailed,
    PickUpUnreachable,
    PlacingFailed,
)
from robocram.plans.pick_object import Held, pick_up_object
from robocram.plans.pick_up import PickResult, pick_up
from robocram.plans.place_object import place_object

__all__ = [
    "ACTION_TYPES",
    "ActionType",
    "Container",
    "Held",
    "ObjectUngraspable",
    "PickResult",
    "PickUpFailed",
    "PickUpUnreachable",
    "PlacingFailed",
    "PlanSetupError",
    "close_container",
    "container",
    "install_actions",
    "open_container",
    "perform_action",
    "pick_up",
    "pick_up_object",
    "place_object",
]
