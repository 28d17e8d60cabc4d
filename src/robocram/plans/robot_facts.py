"""What plans ask the knowledge base about the robot they run on."""

from __future__ import annotations

from robocram.logic import UnknownPredicateError, current_kb
from robocram.plans.errors import PlanSetupError


def current_robot() -> str:
    """The name of the robot in the current knowledge base."""
    hint = (
        "found no robot/1 in the current knowledge base; run the plan inside an "
        "environment such as simulated_robot(world, 'pr2')"
    )
    try:
        answer = current_kb().first("robot(R)")
    except UnknownPredicateError as err:
        raise PlanSetupError(hint) from err
    if answer is None:
        raise PlanSetupError(hint)
    return str(answer["R"])


def robot_arms(robot: str) -> list[str]:
    """The robot's manipulating arms, in the KB's order."""
    return [str(a["A"]) for a in current_kb().query("arm(R, A)", R=robot)]
