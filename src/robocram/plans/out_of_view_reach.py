"""Taking a thing where the search saw it, from a stand whose camera cannot have it in view.

A camera high over a counter, on a head that tilts down only so far (TALOS's stops 45
degrees down), sees the counter's mug from 0.6 m back or more, where the arm does not
reach it; from 0.35-0.45 m, where the arm reaches it, the mug lies 1.05-1.6 half fields
under the axis tilted to its limit: out of the view by geometry, not hidden. After every
usual stand failed, the fetch drives to such near stands and takes the thing where it was
seen, if the look there stopped at the tilt limit with the target outside the view and the
thing still lies where it was seen (``fetch._still_there``). A look that turned to the
target, or had it in view, detects as always: a thing occluded or gone is not taken blind.

After those, stands squared to the counter (:func:`~robocram.plans.flank_stands.squared`)
:data:`SQUARED_DISTANCES` away, nearest first, facing the object and :data:`ASIDE` of it
along the counter: a body reaching far ahead of its base's origin stands clear only
farther out, turned off square its corners meet the counter's drawers, and aside its front
may pass between two handles. The B1's hips stand 0.44 m ahead of its trunk's origin: from
the costmap's stands (0.75 m, 13 degrees off square) its Z1 falls 8 cm short of the mug's
handle; squared, 0.70 m out is the nearest it stands clear in line with the mug (0.68 m:
a hip meets the bowl drawer's handle), 0.65 m with its hips 0.15 m aside, between that
handle and the stove unit's, from where it takes the handle (docs/new_robot.md, zoo24).
Stands the base cannot take are refused to the drive, which costs no try.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

from robocram.execution.failures import PtuGoalNotReached
from robocram.plans.flank_stands import squared
from robocram.plans.known_robot import KnownRobot
from robocram.plans.stands import front_stands, map_pose
from robocram.tf import Pose, PoseStamped

NEAR_DISTANCES = (0.45, 0.40)  # [m] base to the object: nearer than the reach costmap's
# stands (TALOS's arm reaches the counter's mug's handle from 0.45 m, not from 0.50 m)
SQUARED_DISTANCES = (0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8)  # [m] base to the object
ASIDE = (0.0, 0.15, -0.15)  # [m] the stand's line beside the object's, along the counter
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
    shoulder in line with it, :data:`NEAR_DISTANCES` away, arm by arm; then squared to the
    counter, :data:`SQUARED_DISTANCES` away."""
    here = map_pose(robot.base_frame()).position
    x, y, _ = where.pose.position
    towards = math.atan2(here[1] - y, here[0] - x)
    arms = [arm] if arm is not None else robot.arms()
    for stand in front_stands(robot, arms, where.pose, towards, NEAR_DISTANCES):
        yield stand.pose, stand.arm
    out = squared(towards)
    along = (-math.sin(out), math.cos(out))
    for distance in SQUARED_DISTANCES:
        for aside in ASIDE:
            point = Pose((x + along[0] * aside, y + along[1] * aside, where.pose.position[2]))
            for stand in front_stands(robot, arms, point, out, (distance,)):
                yield stand.pose, stand.arm
