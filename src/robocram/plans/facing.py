"""Facing: turn the base where it stands until it faces a point, CRAM's ``facing`` action.

The target is anything a location resolves to (a pose, a PoseStamped, a location
designator) or an object's name; the base keeps its place and turns about its vertical
axis along a checked base path, so a turn that would sweep the robot into something
fails as driving there would (``NavigationPoseUnreachable``).
"""

from __future__ import annotations

import math

from robocram.plans.basic_actions import navigate
from robocram.plans.errors import PlanSetupError
from robocram.plans.known_robot import current_robot
from robocram.plans.location_poses import as_map_pose, location_poses
from robocram.plans.stands import map_pose, planar_pose
from robocram.tf import Pose, PoseStamped

CLOSE = 1e-3  # [m] a target this near the base's axis has no bearing to face


def target_point(target: object) -> tuple[float, float, float]:
    """The map point of ``target``: a pose, a location designator's first pose, an object."""
    if isinstance(target, str):
        return as_map_pose(PoseStamped(target)).position
    return next(location_poses(target)).position


def face(target: object) -> Pose:
    """Turn the base in place to face ``target``; the base pose reached (map).

    Raises:
        NavigationPoseUnreachable: the turn would collide.
        PlanSetupError: the target lies on the base's own axis.
    """
    here = map_pose(current_robot().base_frame())
    x, y, _ = here.position
    tx, ty, _ = target_point(target)
    if math.hypot(tx - x, ty - y) < CLOSE:
        raise PlanSetupError(
            f"the target ({tx:.3f}, {ty:.3f}) m is where the base stands; give a point away "
            "from it to face"
        )
    turned = planar_pose(x, y, math.atan2(ty - y, tx - x))
    navigate(PoseStamped.from_pose("map", turned))
    return turned
