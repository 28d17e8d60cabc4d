"""Looking with a camera nothing turns (a fixed station's camera on a pole, Tracy's).

Such a robot has no head to turn, yet plans look before they detect; the look found no
process module and stopped the plan with a message about the plan's machinery. A look
now moves nothing: it succeeds when the target is within the camera's fields of view
and otherwise fails (``PtuGoalNotReached``) saying how far off the optical axis it lies.
"""

from __future__ import annotations

import math

from robocram.execution.failures import PtuGoalNotReached
from robocram.projection.projected_robot import ProjectedRobot
from robocram.tf import Vector3


def look_fixed(robot: ProjectedRobot, target_in_map: Vector3) -> dict[str, float]:
    """Nothing turned (no joint set) when ``target_in_map`` [m] is in the first camera's view.

    Raises:
        PtuGoalNotReached: the target lies outside the camera's view, which nothing turns.
    """
    camera = robot.description.cameras[0]
    eye = robot.world.link_pose(robot.name, camera.frame)
    x, y, z = eye.inverse().transform_point(target_in_map)  # optical: z ahead, x right
    if z > 0.0 and (
        abs(math.atan2(x, z)) <= camera.horizontal_fov / 2
        and abs(math.atan2(y, z)) <= camera.vertical_fov / 2
    ):
        return {}
    off = math.degrees(math.atan2(math.hypot(x, y), z))
    raise PtuGoalNotReached(
        f"{robot.name}'s camera {camera.frame!r} cannot turn (no pan-tilt, neck, arm or pan "
        f"joint carries it) and the target lies {off:.0f} deg off its optical axis, outside "
        f"its {math.degrees(camera.horizontal_fov):.0f} x "
        f"{math.degrees(camera.vertical_fov):.0f} deg view: put the target in its view, or "
        "check the camera frame (z = optical axis)",
        target=tuple(target_in_map),
        reached={},
    )
