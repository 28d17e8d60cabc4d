"""Taking a thing where the search saw it, from a stand whose camera cannot have it in view.

A camera high over a counter, on a head that tilts down only so far (TALOS's stops 45
degrees down), sees the counter's mug from 0.6 m back or more, where the arm does not
reach it; from 0.35-0.45 m, where the arm reaches it, the mug lies 1.05-1.6 half fields
under the axis tilted to its limit: out of the view by geometry, not hidden. After every
usual stand failed, the fetch drives to such near stands and takes the thing where it was
seen, if the look there stopped at the tilt limit with the target outside the view and the
thing still lies where it was seen (``fetch._still_there``). A look that turned to the
target, or had it in view, detects as always: a thing occluded or gone is not taken blind.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.known_robot import KnownRobot
from robocram.plans.stands import front_stands, map_pose
from robocram.tf import Pose, PoseStamped

NEAR_DISTANCES = (0.45, 0.40)  # [m] base to the object: nearer than the reach costmap's
# stands (TALOS's arm reaches the counter's mug's handle from 0.45 m, not from 0.50 m)
VIEW_EDGE = 1.0  # a target this far off the axis, in half fields, lies at the view's edge


def out_of_view(failure: PtuGoalNotReached) -> bool:
    """Whether ``failure``'s head, stopped at its tilt limit above the target, has it
    outside its view by geometry: under the axis by more than the half field."""
    if not failure.below_tilt or failure.view_share is None:
        return False
    return failure.view_share[1] > VIEW_EDGE


def near_stands(
    robot: KnownRobot, where: PoseStamped, arm: str | None
) -> Iterator[tuple[Pose, str | None]]:
    """Stands facing the object (``where``, map) from where the robot stands now, each arm's
    shoulder in line with it, :data:`NEAR_DISTANCES` away, arm by arm."""
    here = map_pose(robot.base_frame()).position
    x, y, _ = where.pose.position
    towards = math.atan2(here[1] - y, here[0] - x)
    arms = [arm] if arm is not None else robot.arms()
    for stand in front_stands(robot, arms, where.pose, towards, NEAR_DISTANCES):
        yield stand.pose, stand.arm
