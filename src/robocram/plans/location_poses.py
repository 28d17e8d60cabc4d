"""A location designator's solutions as a lazy stream of map poses, for retry loops."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from robocram.designators import LocationDesignator
from robocram.designators.errors import DesignatorError
from robocram.tf import Pose, PoseStamped, transform_pose


def as_map_pose(value: Any) -> Pose:
    """A pose in map from a Pose, a PoseStamped (any frame) or a pose-like tuple."""
    if isinstance(value, PoseStamped):
        return transform_pose(value, "map").pose
    return Pose.coerce(value)


def location_poses(target: object) -> Iterator[Pose]:
    """Each solution of a location designator in turn; a plain pose is its only solution.

    A designator's stream may end with a ``DesignatorError`` (the resolver found no more
    poses); it propagates from ``next()`` so the caller records it as a cause.
    """
    if not isinstance(target, LocationDesignator):
        yield as_map_pose(target)
        return
    current: Any = target
    while isinstance(current, LocationDesignator):
        yield as_map_pose(current.reference())
        current = current.next_solution()


def next_pose(poses: Iterator[Pose], causes: list[Exception]) -> Pose | None:
    """The next pose of ``poses``, or None when it ends (its error appended to ``causes``)."""
    try:
        return next(poses)
    except StopIteration:
        return None
    except DesignatorError as failure:
        causes.append(failure)
        return None
