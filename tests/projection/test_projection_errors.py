"""Set-up errors of plans and projection are plan failures, wrapped when a module raises them."""

from __future__ import annotations

from robocram.execution import PlanFailure
from robocram.execution.failures import SetupFailure, failure_class
from robocram.plans import PlanSetupError
from robocram.projection import ProjectionError


def test_setup_errors_of_plans_and_projection_are_plan_failures() -> None:
    for cls in (PlanSetupError, ProjectionError):
        assert issubclass(cls, SetupFailure) and issubclass(cls, PlanFailure)
    assert issubclass(ProjectionError, ValueError) and issubclass(PlanSetupError, RuntimeError)
    assert str(ProjectionError("arm 'rigth' not in pr2")) == "arm 'rigth' not in pr2"
    assert failure_class("setup-failure") is SetupFailure
