"""The robot's footprint as it stands, and the height bins it is drawn in, kept per posture.

A robot drives in few postures (arms parked, or carrying), so the footprint
(:class:`~robocram.motion.robot_footprint.RobotFootprint`) of each of its last few is kept
with the world. The height bins reach the robot's top rounded up to :data:`TOP_STEP`, so
postures whose tops differ a little (the torso IK raised) share bins, and with them the
obstacle grids the world keeps (:mod:`~robocram.motion.kept_grids`).
"""

from __future__ import annotations

import math

from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import Box
from robocram.motion.robot_footprint import RobotFootprint
from robocram.tf import Pose
from robocram.world import World

SPACING = 0.02  # [m] robot sample squares: more than the 1 cm a dense check moves
CONTACT = 0.002  # [m] nearer than this counts as touching, as in World.collisions
FOOTPRINTS_KEPT = 8  # robot postures whose footprints a world keeps
TOP_STEP = 0.5  # [m] height bins reach the robot's top rounded up to this


def standing_footprint(
    world: World, robot: str, carried: tuple[str, ...], start: Pose
) -> tuple[HeightBins, RobotFootprint]:
    """The height bins and footprint of the robot as it stands, kept with the world for
    the last few postures: a robot drives in few postures (arms parked, or carrying), so
    most drives find theirs. The key is everything the footprint depends on: the joints,
    the height of the base and where each carried object is in the base frame."""
    base_z = start.position[2]
    key = (
        robot,
        tuple(world.joint_states(robot).items()),
        base_z,
        tuple((name, _in_base(start, world.pose(name))) for name in carried),
    )
    kept = world.derived(_kept_footprints)
    found = kept.pop(key, None)
    if found is None:
        boxes = _boxes_in_base(world, robot, carried, start)
        top = base_z + max(b[1][2] for b in boxes) + CONTACT
        bins = HeightBins.up_to(math.ceil(top / TOP_STEP) * TOP_STEP)  # shared by postures
        found = (bins, RobotFootprint.build(boxes, base_z, bins, SPACING, CONTACT))
    kept[key] = found  # most recent last
    while len(kept) > FOOTPRINTS_KEPT:
        kept.pop(next(iter(kept)))
    return found


def _in_base(base: Pose, pose: Pose) -> tuple[float, ...]:
    relative = base.inverse() * pose
    return (*relative.position, *relative.orientation)


def _kept_footprints(world: World) -> dict[tuple[object, ...], tuple[HeightBins, RobotFootprint]]:
    """The footprints a world keeps (the key under which :meth:`World.derived` keeps them)."""
    return {}


def _boxes_in_base(world: World, robot: str, carried: tuple[str, ...], start: Pose) -> list[Box]:
    """Every link box of the robot and what it holds, in the base frame (robot at yaw 0)."""
    x, y, z = start.position
    world.set_pose(robot, Pose((x, y, z)))
    try:
        found = [box for body in (robot, *carried) for box in world.link_aabbs(body).values()]
    finally:
        world.set_pose(robot, start)
    return [((lo[0] - x, lo[1] - y, lo[2] - z), (hi[0] - x, hi[1] - y, hi[2] - z))
            for lo, hi in found]  # fmt: skip
