"""Robot-independent plans: they ask the knowledge base about the robot and PERFORM designators."""

from robocram.plans.errors import PlanSetupError
from robocram.plans.pick_up import PickResult, pick_up

__all__ = ["PickResult", "PlanSetupError", "pick_up"]
