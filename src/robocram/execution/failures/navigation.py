"""Navigation failures: moving the robot base."""

from __future__ import annotations

from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import LowLevelFailure


class NavigationLowLevelFailure(LowLevelFailure):
    """A base motion failed."""

    summary = "the base motion failed"


class NavigationPoseUnreachable(NavigationLowLevelFailure):
    """The base cannot get to the target pose, e.g. it is in collision."""

    target: object | None = None
    colliding: list[str] | None = None
    robot_links: list[str] | None = None  # the robot's own links that would collide there
    summary = "the navigation target is unreachable"
    hint = "sample another base pose from the location designator"


class NavigationGoalOutsideArea(NavigationPoseUnreachable):
    """The goal lies farther outside the world's obstacles than any drive plans (a typo in
    a coordinate, a pose in another frame): refused before any grid is made for it."""

    area: tuple[tuple[float, float], tuple[float, float]] | None = None  # [m] low, high x y
    margin: float | None = None  # [m] how far outside the area a goal may be
    summary = "the navigation goal is outside the area the robot drives in"
    hint = "give a goal near the environment (in map), or check the pose's frame and units"


class NavigationPathBlocked(NavigationPoseUnreachable):
    """The goal is free, but no collision-free path of the base leads there."""

    path_fraction: float | None = None  # [0..1] how far along the straight path it is blocked
    summary = "the base's path to its goal is blocked"
    hint = "clear the blocker (close the drawer, move the object) or choose another stand"


class NavigationGoalNotReached(NavigationLowLevelFailure):
    """The base moved but stopped away from its target."""

    target: object | None = None
    reached: object | None = None
    error: float | None = None
    summary = "the base did not reach its goal"
    hint = "retry, or check the path for obstacles"


class NavigationGoalInCollision(HighLevelFailure):
    """The navigation goal puts the robot into collision."""

    target: object | None = None
    colliding: list[str] | None = None
    summary = "the navigation goal is in collision"
    hint = "take the next solution of the location designator"
