"""What a plan chose, read from its result: the arm, the grasp and the locations it used.

Batch results keep these so a user sees not only which variants failed but what the
successful ones did: which arm took the mug, by which grasp, from where. A plan's result
type is read here by what it is (the tabletop pick-up, a transport); any other result
gives what its ``arm`` and ``grasp`` attributes hold, if it has them.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.batch.breakfast_activity import BreakfastOutcome
from robocram.batch.result import Pose7
from robocram.plans import PickResult
from robocram.plans.transport import TransportResult
from robocram.tf import Pose, PoseStamped


@dataclass(frozen=True)
class Choices:
    """The arm, grasp (name and pose) and named locations (map poses) a plan used."""

    arm: str | None = None
    grasp_name: str | None = None
    grasp: Pose7 | None = None
    grasp_frame: str | None = None
    locations: tuple[tuple[str, Pose7], ...] = ()


def pose7(pose: Pose | PoseStamped) -> Pose7:
    """``(x, y, z, qx, qy, qz, qw)`` of a pose: plain numbers that pickle and compare."""
    plain = pose.pose if isinstance(pose, PoseStamped) else pose
    return (*plain.position, *plain.orientation)


def choices_of(result: object) -> Choices:
    """What ``result`` (a plan's return value) says the plan chose."""
    if isinstance(result, TransportResult):
        held = result.held
        stands = tuple(
            (f"{attempt.stage} stand", pose7(attempt.stand))
            for attempt in result.log.attempts
            if attempt.succeeded and attempt.stand is not None
        )
        return Choices(
            held.arm,
            held.grasp,
            pose7(held.grasp_pose),
            held.grasp_pose.frame_id,
            (*stands, ("placed at", pose7(result.spot))),
        )
    if isinstance(result, BreakfastOutcome):
        return Choices(locations=tuple((f"placed {name}", pose) for name, pose in result.placed))
    if isinstance(result, PickResult):
        return Choices(
            result.arm,
            result.held.grasp,
            pose7(result.grasp),
            result.grasp.frame_id,
        )
    grasp = getattr(result, "grasp", None)
    return Choices(
        arm=getattr(result, "arm", None),
        grasp=pose7(grasp) if isinstance(grasp, Pose | PoseStamped) else None,
        grasp_frame=grasp.frame_id if isinstance(grasp, PoseStamped) else None,
    )
