"""Load a description for checking: every name problem fails the card, bad values are fixed.

A parking, carrying or neck value outside its joint's limits is reported and clamped, so
the card goes on to drive the robot and can name every other fault in the same run.
"""

from __future__ import annotations

from dataclasses import replace

from robocram.robot_check.report_card import CheckResult
from robocram.robots import (
    DescriptionCheckError,
    Finding,
    JointValueError,
    LoadedDescription,
    RobotDescription,
    load_description,
)
from robocram.robots.errors import NameProblem, Problem

MAX_FIXES = 50  # one per joint value out of limits; a description has fewer


def _clamped(desc: RobotDescription, err: JointValueError) -> tuple[RobotDescription, str]:
    """``desc`` with ``err.joint`` clamped wherever it was given, and where that was."""
    value = min(max(err.value, err.lower), err.upper)
    arms, where = dict(desc.arms), "neck_parking"
    for key, arm in desc.arms.items():
        if arm.parking.get(err.joint) == err.value:
            arms[key] = replace(arm, parking={**arm.parking, err.joint: value})
            where = f"arms[{key!r}].parking"
        elif arm.carrying.get(err.joint) == err.value:
            arms[key] = replace(arm, carrying={**arm.carrying, err.joint: value})
            where = f"arms[{key!r}].carrying"
    neck = dict(desc.neck_parking)
    if where == "neck_parking":
        neck[err.joint] = value
    return replace(desc, arms=arms, neck_parking=neck), where


def _problem(problem: Problem, model_name: str) -> CheckResult:
    """One problem of the checker as a failed check: its field, what is wrong, the fix."""
    if isinstance(problem, Finding):
        return CheckResult(f"description: {problem.subject}", False, problem.problem, problem.fix)
    where = problem.where if isinstance(problem, NameProblem) else "names"
    text = problem.message(model_name)
    return CheckResult(f"description: {where}", False, text, "use the names the URDF has")


def load_for_check(desc: RobotDescription, results: list[CheckResult]) -> LoadedDescription | None:
    """The loaded description (values clamped into limits), or None if names are wrong."""
    for _ in range(MAX_FIXES):
        try:
            loaded = load_description(desc)
        except DescriptionCheckError as err:
            results += [_problem(problem, err.model_name) for problem in err.problems]
            return None
        except JointValueError as err:
            desc, where = _clamped(desc, err)
            results.append(
                CheckResult(
                    f"{where}: {err.joint}",
                    False,
                    f"{err.value} is outside the limits [{err.lower}, {err.upper}]",
                    f"give {err.joint} a value within [{err.lower}, {err.upper}] in {where}",
                )
            )
            continue
        results.append(
            CheckResult("description", True, f"names and values agree with {loaded.model.source}")
        )
        return loaded
    return None
