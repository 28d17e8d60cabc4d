"""Where a tool action works from: where the robot stands, else a stand that reaches the work.

A tool path is asked of the arm with the share it must reach (``needed``); the process
module refuses a path it can follow only part of the way before following any of it
(``ToolPathUnreachable``: the arm has only moved to the path's start). Then the robot
carries the tool (its holding arm parked) to stands from which the arm reaches the work,
a ``reachable_for`` location of a point over it (CRAM's ``(a location (reachable-for
?robot) (location ?work))``), and tries again from each, at most :data:`REACH_STANDS`.
A robot that reaches the whole path from where it stands never moves: what worked
before works the same.
"""

from __future__ import annotations

import contextlib
import itertools
from collections.abc import Callable
from typing import TypeVar

from robocram.designators import a
from robocram.designators.errors import DesignatorError
from robocram.execution.failures import (
    ManipulationPoseUnreachable,
    NavigationLowLevelFailure,
    ToolPathUnreachable,
)
from robocram.plans.carrying import carry
from robocram.plans.known_robot import current_robot
from robocram.plans.location_poses import location_poses
from robocram.plans.tool_failures import ToolPathIncomplete
from robocram.tf import Pose, PoseStamped, Vector3

T = TypeVar("T")
REACH_STANDS = 6  # stands of the reachable_for costmap tried, at most
OVER_THE_WORK = 0.1  # [m] the point the stands must reach lies this far over the work


def from_a_stand(action: str, work: Vector3, arm: str, attempt: Callable[[], T]) -> T:
    """``attempt()`` (which asks its tool path with a ``needed`` share) from here, else from
    stands that reach over ``work`` (map), carrying the tool there.

    Raises:
        ToolPathIncomplete: no stand tried reaches enough of the path; names the best
            share reached and why it stopped, every stand's failure chained.
    """
    try:
        return attempt()
    except ToolPathUnreachable as here:
        causes: list[Exception] = [here]
    robot = current_robot()
    over = PoseStamped.from_pose("map", Pose((work[0], work[1], work[2] + OVER_THE_WORK)))
    stands = location_poses(a.location(reachable_for=robot.name, target=over, arm=arm))
    with contextlib.suppress(DesignatorError):  # the stream ended: no more stands
        for stand in itertools.islice(stands, REACH_STANDS):
            try:
                carry(stand, arm)
                return attempt()
            except (ManipulationPoseUnreachable, NavigationLowLevelFailure) as failure:
                causes.append(failure)  # the path, its start, or the way there
    best = max(
        (c for c in causes if isinstance(c, ToolPathUnreachable)),
        key=lambda c: c.fraction or 0.0,
    )
    raise ToolPathIncomplete(
        f"{action}: {robot.name}'s {arm} arm reaches at most {best.fraction or 0.0:.0%} of the "
        f"tool path, from where it stood and {len(causes) - 1} other stands; stopped by "
        f"{best.stopped_by}",
        action=action,
        fraction=best.fraction,
        needed=best.needed,
        stopped_by=best.stopped_by,
    ) from causes[-1]
