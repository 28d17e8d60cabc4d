"""Fetching: stand where the object is reachable, look, detect it again, pick it up.

As CRAM's fetch plan does, each try takes the next solution of a ``reachable_for``
location designator, so a stand whose grasp fails gives way to another one; the tries are
bounded (``stand_retries``). When all fail, :class:`FetchExhausted` (an
``ObjectUnfetchable``) carries every cause in order.
"""

from __future__ import annotations

from typing import Any

from robocram.designators import ObjectDesignator, a, an
from robocram.execution.failures import PlanFailure
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import detect, look, navigate, park_arms
from robocram.plans.errors import FetchExhausted
from robocram.plans.location_poses import location_poses, next_pose
from robocram.plans.pick_object import Held, pick_up_object
from robocram.plans.robot_facts import current_robot
from robocram.tf import Pose, transform_pose

STAND_RETRIES = 3  # stands tried before fetching gives up


def perceived(object: ObjectDesignator | str) -> ObjectDesignator:  # noqa: A002 - CRAM's key
    """``object`` if perception already filled it in, else what detecting it now gives."""
    if isinstance(object, ObjectDesignator) and object.get("pose") is not None:
        return object
    return detect(object)


def _pick_from(
    stand: Pose, seen: ObjectDesignator, arm: str | None, grasp: str | None
) -> Held:
    """Drive to ``stand``, look at the object, detect it again and pick it up."""
    where = transform_pose(seen.get("pose"), "map")
    park_arms()
    navigate(stand)
    look(where)
    again = detect(an.object(type=seen.get("type"), name=seen.get("name")))
    return pick_up_object(again, arm=arm, grasp=grasp)


def fetch(
    object: ObjectDesignator | str,  # noqa: A002 - CRAM's key
    arm: str | None = None,
    grasp: str | None = None,
    stand_retries: int = STAND_RETRIES,
    log: AttemptLog | None = None,
) -> Held:
    """Pick up the (perceived) object from a stand that reaches it; what the hand holds.

    Raises:
        FetchExhausted: no stand within ``stand_retries`` led to the object being held.
    """
    if stand_retries < 1:
        raise ValueError(f"stand_retries must be at least 1, got {stand_retries}")
    log = log if log is not None else AttemptLog()
    seen = perceived(object)
    keys: dict[str, Any] = {"arm": arm} if arm is not None else {}
    stand = a.location(reachable_for=current_robot(), object=seen.get("name"), **keys)
    causes: list[Exception] = []
    poses = location_poses(stand)
    for _ in range(stand_retries):
        pose = next_pose(poses, causes)
        if pose is None:
            break
        try:
            held = _pick_from(pose, seen, arm, grasp)
        except PlanFailure as failure:
            causes.append(failure)
            log.record("fetch", pose, failure)
            continue
        log.record("fetch", pose, None)
        return held
    raise FetchExhausted(
        f"could not fetch {seen.get('name')} from {len(causes)} stands: "
        + "; ".join(type(c).__name__ for c in causes),
        object_designator=seen,
        causes=tuple(causes),
        attempts=len(causes),
    )

