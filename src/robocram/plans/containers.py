"""Opening and closing containers (drawers, doors), robot-independently.

The container is named by its link or its handle link; the knowledge base says which
environment it belongs to, which joint opens it, which handle to pull and how far opening
goes (``container/4``, ``container_opening/3``), so no link name is hard-coded here. The
arms are tried in the KB's order unless one is given; the first that can hold the handle
all the way does it.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import EnvironmentManipulationImpossible
from robocram.knowledge.scene_predicates import CONTAINER, CONTAINER_OPENING
from robocram.logic import current_kb
from robocram.plans.errors import PlanSetupError
from robocram.plans.known_robot import current_robot

VERBS = {"opening": "open", "closing": "close"}  # an action and what its arm does


@dataclass(frozen=True)
class Container:
    """A container as the KB describes it."""

    environment: str
    link: str
    joint: str
    handle: str
    opened: float  # [m | rad] the joint value that opens it


def container(name: str) -> Container:
    """The container whose link or handle is ``name``."""
    kb = current_kb()
    for fact in CONTAINER.answers(kb):
        if name not in (fact.link, fact.handle):
            continue
        opening = CONTAINER_OPENING.first(kb, environment=fact.environment, link=fact.link)
        if opening is not None:
            return Container(fact.environment, fact.link, fact.joint, fact.handle, opening.opened)
    known = sorted({fact.link for fact in CONTAINER.answers(kb)})
    raise PlanSetupError(
        f"{name!r} is no container or handle in the knowledge base; containers: "
        f"{', '.join(known) or 'none (load a scene with container/4 facts)'}"
    )


def move_container(name: str, goal: float, arm: str | None, action: str) -> float:
    """Move the container's joint to ``goal`` with ``arm`` or the first arm that can; an
    arm that holds something is not asked (its hand would let go of it on the handle).

    Raises:
        PlanSetupError: ``arm`` holds something, or every arm does (named).
    """
    part = container(name)
    robot = current_robot()
    holding = robot.held_objects(robot.arms())
    if arm is not None and arm in holding:
        raise PlanSetupError(
            f"{robot.name}'s {arm} arm holds {holding[arm]!r} and cannot "
            f"{VERBS.get(action, action)} {part.link!r}; put it down first or use another arm"
        )
    arms = [arm] if arm is not None else [a for a in robot.arms() if a not in holding]
    if not arms:
        raise PlanSetupError(
            f"every arm of {robot.name} holds something ({holding}); put a thing down "
            f"before you {VERBS.get(action, action)} {part.link!r}"
        )
    failures: list[EnvironmentManipulationImpossible] = []
    for choice in arms:
        motion = a.motion(
            type="moving-articulation",
            arm=choice,
            part=part.environment,
            joint=part.joint,
            handle=part.handle,
            joint_angle=goal,
        )
        try:
            return float(perform(motion))
        except EnvironmentManipulationImpossible as failure:
            failures.append(failure)
    raise EnvironmentManipulationImpossible(
        f"no arm of {arms} could {VERBS.get(action, action)} {part.link!r}: "
        + "; ".join(str(f) for f in failures),
        environment_part=part.link,
        action=action,
        reached=failures[-1].reached,  # where the last arm left the part
    )


def open_container(
    object: str,  # noqa: A002 - CRAM's key
    distance: float | None = None,
    angle: float | None = None,
    arm: str | None = None,
) -> float:
    """Open a drawer (by ``distance`` [m]) or a door (by ``angle`` [rad]), default fully."""
    goal = distance if distance is not None else angle
    return move_container(
        object, goal if goal is not None else container(object).opened, arm, "opening"
    )


def close_container(object: str, arm: str | None = None) -> float:  # noqa: A002
    """Close a drawer or a door."""
    return move_container(object, 0.0, arm, "closing")
