"""Visibility: cells from which a camera at the robot's camera heights sees the target.

Computed from the target outwards: with the target and the robot moved out of the way,
one batch of rays fans out from the target's centre to a camera point over every cell
still possible, at a few heights between the description's camera minimum and maximum
(and the camera's height now). A cell's weight is the share of its rays nothing stops.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from typing import Any

import numpy as np

from robocram.costmaps.camera_aim import camera_description
from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.distance_costs import ring
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grid import BoolGrid
from robocram.costmaps.rays import cast_rays
from robocram.tf import Pose
from robocram.world import World, WorldObject

VIEW_DISTANCE = (0.4, 2.5)  # [m] nearest and farthest horizontal distance to look from
HEIGHTS = 3  # camera heights sampled between the description's minimum and maximum
_AWAY = 1000.0  # [m] how far up the target and the robot wait while the rays are cast


@contextmanager
def _lifted(world: World, obj: WorldObject, index: int) -> Iterator[None]:
    """Move ``obj`` far up (``index`` keeps several apart) and back exactly."""
    pose = world.pose(obj)
    x, y, z = pose.position
    world.set_pose(obj, Pose((x + 10.0 * index, y, z + _AWAY), pose.orientation))
    try:
        yield
    finally:
        world.set_pose(obj, pose)


def camera_heights(query: LocationQuery) -> list[float]:
    """Heights [m] over the robot's base to cast to: the description's range and now."""
    robot = query.robot
    if robot is None:
        raise CostmapInputError(f"{query.designator.description} names no robot", None)
    camera = camera_description(query.world, robot)
    spec = robot.description.cameras[0]
    base_z = query.world.pose(robot).position[2]
    heights = np.linspace(spec.minimal_height, spec.maximal_height, HEIGHTS).tolist()
    return [*heights, camera.pose.position[2] - base_z]


def visibility_cost(query: LocationQuery, value: Any, alive: BoolGrid) -> CostLayer:
    """Share of camera heights over each cell with a free line of sight to the target."""
    heights = camera_heights(query)
    target_value = query.designator.get("object") or query.designator.get("target")
    target = query.point(target_value, "object")
    near, far = VIEW_DISTANCE
    alive = alive & (ring(query.grid, target[:2], near, far) > 0)
    cells = np.argwhere(alive)
    x, y = query.centres()
    ends = [(float(x[r, c]), float(y[r, c]), h) for r, c in cells for h in heights]
    movers: list[WorldObject] = [query.robot] if query.robot is not None else []
    if query.designator.get("object") is not None:
        movers.append(query.object(query.designator.get("object"), "object"))
    with ExitStack() as stack:
        for index, obj in enumerate(movers):
            stack.enter_context(_lifted(query.world, obj, index + 1))
        hits = cast_rays(query.world, [target] * len(ends), ends)
    free = np.array([hit is None for hit in hits], dtype=float).reshape(len(cells), len(heights))
    weights = np.zeros(query.grid.shape)
    if len(cells):
        weights[cells[:, 0], cells[:, 1]] = free.mean(axis=1)
    return CostLayer(weights)
