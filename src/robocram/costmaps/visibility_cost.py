"""Visibility: cells from which a camera at the robot's camera heights sees the target.

Computed from the target outwards: with the target and the robot moved out of the way,
rays fan out from the target's centre to a camera point over each cell, at a few heights
between the description's camera minimum and maximum (and the camera's height now). A
cell's weight is the share of its rays nothing stops. The rays are cast lazily, only for
the cells a pose stream draws (the whole grid only for a picture). A cell whose every ray
is stopped blames what stopped them (``query.blame``), so a failure can name it.
"""

from __future__ import annotations

from contextlib import AbstractContextManager

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.camera_aim import camera_description
from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.distance_costs import ring
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grid import BoolGrid
from robocram.costmaps.out_of_the_way import out_of_the_way
from robocram.costmaps.rays import cast_rays

VIEW_DISTANCE = (0.4, 2.5)  # [m] nearest and farthest horizontal distance to look from
HEIGHTS = 3  # camera heights sampled between the description's minimum and maximum


def camera_heights(query: LocationQuery) -> list[float]:
    """Heights [m] over the robot's base to cast to: the description's range and now."""
    robot = query.robot
    if robot is None:
        raise CostmapInputError(f"{query.designator.description} names no robot", None)
    camera = camera_description(query.world, robot)
    spec = robot.description.cameras[0]
    base_z = query.world.pose(robot).position[2]
    heights = np.linspace(*spec.height_range(), HEIGHTS).tolist()
    return [*heights, camera.pose.position[2] - base_z]


def visibility_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """Cells in viewing range; the share of free lines of sight is computed lazily."""
    heights = camera_heights(query)
    target = query.point(query.designator.get("object") or query.designator.get("target"), "object")
    near, far = VIEW_DISTANCE
    in_range = ring(query.grid, target[:2], near, far)
    x, y = query.centres()

    def free_share(cells: NDArray[np.int64]) -> NDArray[np.float64]:
        ends = [(float(x[r, c]), float(y[r, c]), h) for r, c in cells for h in heights]
        with _out_of_sight(query):
            hits = cast_rays(query.world, [target] * len(ends), ends)
        free = np.array([hit is None for hit in hits], dtype=float)
        share = free.reshape(len(cells), len(heights)).mean(axis=1)
        for k in np.flatnonzero(share == 0.0).tolist():  # refused for sure: blame what hid it
            rays = hits[k * len(heights) : (k + 1) * len(heights)]
            query.blame.occluding(hit.obj.name for hit in rays if hit is not None)
        return np.asarray(share, dtype=np.float64)

    return CostLayer(in_range, refine=free_share)


def _out_of_sight(query: LocationQuery) -> AbstractContextManager[None]:
    """Lift the robot and the target object out of the rays' way for the block."""
    target = query.designator.get("object")
    obj = query.object(target, "object") if target is not None else None
    return out_of_the_way(query.world, [query.robot, obj])
