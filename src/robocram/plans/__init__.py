"""Robot-independent plans: they ask the knowledge base about the robot and PERFORM designators."""

from robocram.execution import perform  # the one PERFORM; importing plans gives it ACTIONS
from robocram.execution.action_table import ActionTable
from robocram.execution.action_type import ActionType
from robocram.plans.action_table import (
    ACTION_TYPES,
    ACTIONS,
    install_actions,
    perform_action,
)
from robocram.plans.attempt_log import Attempt, AttemptLog
from robocram.plans.containers import Container, close_container, container, open_container
from robocram.plans.deliver import deliver
from robocram.plans.errors import (
    DeliveryExhausted,
    FetchExhausted,
    ObjectLetGo,
    PlanArgumentError,
    PlanSetupError,
    SearchExhausted,
)
from robocram.plans.fetch import fetch
from robocram.plans.grasp_failures import (
    ObjectUngraspable,
    PickUpFailed,
    PickUpUnreachable,
    PlacingFailed,
)
from robocram.plans.pick_object import Held, pick_up_object
from robocram.plans.pick_up import PickResult, pick_up
from robocram.plans.place_object import place_object
from robocram.plans.transport import TransportResult, transport

__all__ = [
    "ACTIONS",
    "ACTION_TYPES",
    "ActionTable",
    "ActionType",
    "Attempt",
    "AttemptLog",
    "Container",
    "DeliveryExhausted",
    "FetchExhausted",
    "Held",
    "ObjectLetGo",
    "ObjectUngraspable",
    "PickResult",
    "PickUpFailed",
    "PickUpUnreachable",
    "PlacingFailed",
    "PlanArgumentError",
    "PlanSetupError",
    "SearchExhausted",
    "TransportResult",
    "close_container",
    "container",
    "deliver",
    "fetch",
    "install_actions",
    "open_container",
    "perform",
    "perform_action",
    "pick_up",
    "pick_up_object",
    "place_object",
    "transport",
]
