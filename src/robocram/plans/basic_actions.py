"""The small actions every fetch-and-deliver plan is made of: each PERFORMs one kind of motion.

Everything robot-specific (which arms there are, their parking joints, the torso) comes
from the interface predicates in the current knowledge base.
"""

from __future__ import annotations

from typing import Any

from robocram.designators import ObjectDesignator, a, an
from robocram.execution import perform
from robocram.logic import current_kb
from robocram.plans.errors import PlanSetupError
from robocram.plans.robot_facts import current_robot


def navigate(target: Any) -> Any:
    """Drive the base to ``target`` (a pose, a PoseStamped or a location designator)."""
    return perform(a.motion(type="going", target=target))


def park_arms(arm: str | None = None) -> list[str]:
    """Put ``arm`` (default: every arm) into its parking configuration; return the arms."""
    robot = current_robot()
    parked = []
    query = "arm(R, A), robot_arms_parking_joint_states(R, A, S)"
    for answer in current_kb().query(query, R=robot):
        if arm is not None and answer["A"] != arm:
            continue
        if answer["S"]:
            perform(a.motion(type="moving-arm-joints", arm=answer["A"], configuration=answer["S"]))
        parked.append(str(answer["A"]))
    if arm is not None and not parked:
        raise PlanSetupError(f"{robot} has no arm {arm!r} with a parking configuration")
    return parked


def move_torso(joint_angle: float | str) -> Any:
    """Move the torso to ``joint_angle`` [m | rad], or to its ``upper``/``lower`` limit."""
    if isinstance(joint_angle, str):
        robot = current_robot()
        limit = {"upper": "joint_upper_limit", "lower": "joint_lower_limit"}.get(joint_angle)
        answer = None
        if limit is not None:
            answer = current_kb().first(
                f"robot_torso_link_joint(R, _, J), {limit}(R, J, V)", R=robot
            )
        if answer is None:
            raise PlanSetupError(
                f"torso goal {joint_angle!r} is no number and not upper/lower of a torso "
                f"joint of {robot}"
            )
        joint_angle = float(answer["V"])
    return perform(a.motion(type="moving-torso", joint_angle=joint_angle))


def look(target: Any) -> Any:
    """Point the camera at ``target``."""
    return perform(a.motion(type="looking", target=target))


def detect(object: ObjectDesignator | str) -> ObjectDesignator:  # noqa: A002 - CRAM's key
    """Detect the object (a designator, or an object type); the perceived designator."""
    desig = object if isinstance(object, ObjectDesignator) else an.object(type=object)
    return perform(a.motion(type="detecting", object=desig))
