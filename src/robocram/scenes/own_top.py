"""Where a robot's fixed camera looks onto the robot's own top: its items lie there.

A robot built on a table (Tracy: two arms on a 1.18 x 1.60 m table, a camera on a pole
looking 72 degrees down onto it) works on that table: nothing else can stand where its
camera looks, so the tabletop scene lays the mug on the robot's own top instead. Found,
not named: the camera's optical axis, from the camera, first meets the robot itself on a
face that looks up.
"""

from __future__ import annotations

from robocram.robots.looking_means import looking_means
from robocram.tf import Vector3
from robocram.world import World

SIGHT = 2.0  # [m] along the optical axis: farther, the camera cannot make a mug out
UP = 0.9  # z of a face's unit normal above which it is a top a mug stands on


def seen_on_own_top(world: World, robot: str) -> Vector3 | None:
    """The point [m, map] where ``robot``'s camera, which nothing turns, looks onto the
    robot's own upward face, as it stands now; None for a camera that turns, one looking
    elsewhere, or no camera."""
    desc = world.robot(robot).description
    if not desc.cameras or desc.pan_tilt is not None or looking_means(desc) is not None:
        return None
    eye = world.link_pose(robot, desc.cameras[0].frame)
    hit = world.view.ray_cast(eye.position, eye.transform_point((0.0, 0.0, SIGHT)))
    if hit is None or hit.obj.name != robot or hit.normal[2] < UP:
        return None
    return hit.position
