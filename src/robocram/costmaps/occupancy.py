"""Occupancy: cells where the robot's base would overlap something in its height band.

The footprint radius comes from the robot itself: the links fixed to its root link (the
mobile base) as loaded from its URDF, measured in the world. Every other object whose
bounds reach into the robot's height band blocks the cells within that radius of it.
Articulated objects (a kitchen) block link by link, so a counter does not block the room;
a part wider than :data:`LARGE_PART` both ways (all of a room's walls in one link, whose
bounds would cover the room) is probed instead, one ray down each cell. A long, thin part
(one wall, a counter top) blocks by its bounds: a probe ray starting inside a wall taller
than the robot would not see it. When the location fails, the movable objects whose bounds
ruled out cells are recorded (``query.blame``), so the failure names them.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np

from robocram.costmaps.cost_layer import CostLayer, LocationQuery
from robocram.costmaps.errors import CostmapInputError
from robocram.costmaps.grasps import arm_working_yaw
from robocram.costmaps.grid import BoolGrid, FloatGrid, dilate, erode
from robocram.costmaps.out_of_the_way import out_of_the_way
from robocram.robots.model_pose import subtree_links
from robocram.tf import Pose, Vector3
from robocram.world import RobotObject, World
from robocram.world.ray_hit import first_hit_bodies

FLOOR_CLEARANCE = 0.02  # [m] bounds lower than this are the floor, not obstacles
LARGE_PART = 1.5  # [m] parts wider than this both ways (a room's walls) are probed by rays

Box = tuple[Vector3, Vector3]


def base_links(robot: RobotObject) -> list[str]:
    """The root link and every link fixed to it: the part that is the mobile base."""
    model = robot.description.model
    if model is None:
        raise CostmapInputError(f"robot {robot.name!r} has no loaded model", robot.name)
    return model.base_links()


def footprint_radius(world: World, robot: RobotObject) -> float:
    """Radius [m] around the base origin that holds the base links' x-y extents."""
    return footprint_radii(world, robot)[1]


def footprint_extents(world: World, robot: RobotObject) -> tuple[float, float, float, float]:
    """``(low_x, low_y, high_x, high_y)`` [m] of the base links about the base origin, in
    the base's axes (zeros for a base without geometry).

    Measured with the base turned to the map's axes for a moment (bounds are axis-aligned:
    a base turned by 45 degrees would seem 1.4 times as wide), then put back exactly.
    """
    base = world.pose(robot)
    upright = Pose(base.position)
    x0, y0 = upright.position[:2]
    lows: list[tuple[float, float]] = []
    highs: list[tuple[float, float]] = []
    with placed_for_a_moment(world, robot, upright):
        for link in base_links(robot):
            low, high = world.contacts.link_aabb(robot, link)
            if high[2] - low[2] <= 0 or high[0] - low[0] > 5:  # frames without geometry
                continue
            lows.append((low[0] - x0, low[1] - y0))
            highs.append((high[0] - x0, high[1] - y0))
    if not lows:
        return 0.0, 0.0, 0.0, 0.0
    low_x, low_y = min(p[0] for p in lows), min(p[1] for p in lows)
    high_x, high_y = max(p[0] for p in highs), max(p[1] for p in highs)
    return low_x, low_y, high_x, high_y


def footprint_radii(world: World, robot: RobotObject) -> tuple[float, float]:
    """Radii [m] about the base origin of the largest circle inside the base links' x-y
    extents and of the smallest around them."""
    low_x, low_y, high_x, high_y = footprint_extents(world, robot)
    outer = max(math.hypot(x, y) for x in (low_x, high_x) for y in (low_y, high_y))
    inner = max(0.0, min(-low_x, high_x, -low_y, high_y))
    return inner, outer


def facing_radius(world: World, robot: RobotObject) -> float:
    """How close [m] the base origin comes to an obstacle the robot works at.

    The inner radius, except for a robot whose arms all work sideways (Stretch's, along
    its base's -y): it stands with that side to the counter, so the base's extent that way
    counts, not the inner circle about an origin near the front of its base (6 cm).
    """
    inner = footprint_radii(world, robot)[0]
    desc = robot.description
    turns = {
        arm_working_yaw(desc, k) for k, a in desc.arms.items() if k != desc.neck_arm and a.joints
    }
    if not turns or 0.0 in turns:
        return max(inner, _legs_ahead(world, robot))
    low_x, low_y, high_x, high_y = footprint_extents(world, robot)
    ways = {0.0: high_x, math.pi / 2: high_y, -math.pi / 2: -low_y, math.pi: -low_x}
    return max(inner, min(ways.get(turn, inner) for turn in turns))


def leg_links(robot: RobotObject) -> list[str]:
    """Links neither of the base (fixed to the root) nor moved by a joint the description
    names (arms, grippers, torso, pan-tilt): a legged robot's legs, a wheeled one's wheels."""
    desc, model = robot.description, robot.description.model
    if model is None:
        raise CostmapInputError(f"robot {robot.name!r} has no loaded model", robot.name)
    named = {j for arm in desc.arms.values() for j in (*arm.joints, *arm.gripper_joints)}
    named |= {desc.torso_joint} if desc.torso_joint is not None else set()
    pan_tilt = desc.pan_tilt
    named |= {pan_tilt.pan_joint, pan_tilt.tilt_joint} if pan_tilt is not None else set()
    moved = {
        link
        for j in named
        if j in model.joints
        for link in subtree_links(model, model.joints[j].child)
    }
    base = set(model.base_links())
    return [link for link in robot.link_index if link not in base and link not in moved]


def _legs_ahead(world: World, robot: RobotObject) -> float:
    """How far [m] ahead of the base origin its legs reach (0 without legs): B1's feet,
    at its URDF's zero stance, stand 0.58 m ahead of its origin, its trunk 0.39 m."""
    base = world.pose(robot)
    ahead = 0.0
    with placed_for_a_moment(world, robot, Pose(base.position)):
        for link in leg_links(robot):
            low, high = world.contacts.link_aabb(robot, link)
            if high[2] - low[2] > 0 and high[0] - low[0] <= 5:  # frames have no geometry
                ahead = max(ahead, high[0] - base.position[0])
    return ahead


@contextmanager
def placed_for_a_moment(world: World, robot: RobotObject, pose: Pose) -> Iterator[None]:
    """``robot`` (and what it carries) at ``pose`` for the block; back where it was after."""
    before = world.pose(robot)
    if before == pose:
        yield
        return
    world.set_pose(robot, pose)
    try:
        yield
    finally:
        world.set_pose(robot, before)


def robot_top(world: World, robot: RobotObject) -> float:
    """Top [m, map] of the robot's bounds: from the floor up to there it can hit things.

    In the map, not over the base origin: a legged robot's origin (its trunk) stands
    0.6 m over its feet, and a counter's top under its parked arm is in its way.
    """
    return world.aabb(robot)[1][2]


def obstacle_boxes(world: World, robot: RobotObject | None, top: float) -> tuple[list[Box], bool]:
    """Bounds of every object (link by link) reaching into the band ``FLOOR_CLEARANCE..top``,
    and whether some part is too large for its bounds to stand for it (a room's walls)."""
    named, large = named_obstacle_boxes(world, robot, top)
    return [box for _, box in named], large


def named_obstacle_boxes(
    world: World, robot: RobotObject | None, top: float
) -> tuple[list[tuple[str, Box]], bool]:
    """:func:`obstacle_boxes`, each box with the name of its object."""
    carried = set(world.bodies.attachments(robot)) if robot is not None else set()
    boxes: list[tuple[str, Box]] = []
    large = False
    for obj in world.objects():
        if obj is robot or obj.type == "floor" or obj.name in carried:
            continue
        links = world.link_names(obj) if len(obj.link_index) > 1 else []
        parts = [world.contacts.link_aabb(obj, link) for link in links]
        for low, high in parts or [world.aabb(obj)]:
            if not (high[2] > FLOOR_CLEARANCE and low[2] < top):
                continue
            if min(high[0] - low[0], high[1] - low[1]) > LARGE_PART:
                large = True
            else:
                boxes.append((obj.name, (low, high)))
    return boxes, large


def probed_free(
    query: LocationQuery, robot: RobotObject, top: float, where: BoolGrid | None = None
) -> BoolGrid:
    """Cells whose column ``FLOOR_CLEARANCE..top`` holds nothing, by one ray down each.

    Only the cells of ``where`` (default all) are probed; the others count as free.
    """
    x, y = query.centres()
    cells = np.ones(query.grid.shape, dtype=bool) if where is None else where
    xs, ys = x[cells], y[cells]
    starts = np.column_stack([xs, ys, np.full(len(xs), top)])
    ends = np.column_stack([xs, ys, np.full(len(xs), FLOOR_CLEARANCE)])
    carried = [query.world.object(name) for name in query.world.bodies.attachments(robot)]
    with out_of_the_way(query.world, [robot, *carried]):
        bodies = first_hit_bodies(query.world, starts, ends)
    free = np.ones(query.grid.shape, dtype=bool)
    free[cells] = bodies < 0
    return free


def free_cells(
    query: LocationQuery, boxes: list[Box], radius: float, where: BoolGrid | None = None
) -> FloatGrid:
    """1 in cells farther than ``radius`` [m] from every box, 0 elsewhere.

    Each box is only measured against the window of cells its ``radius`` reaches, and
    only boxes whose window holds a cell of ``where`` (default all) are measured.
    """
    grid = query.grid
    x0, y0 = grid.origin
    res, (rows, cols) = grid.resolution, grid.shape
    free = np.ones(grid.shape)
    for low, high in boxes:
        c0 = max(0, math.floor((low[0] - radius - x0) / res))
        c1 = min(cols, math.ceil((high[0] + radius - x0) / res) + 1)
        r0 = max(0, math.floor((low[1] - radius - y0) / res))
        r1 = min(rows, math.ceil((high[1] + radius - y0) / res) + 1)
        if c0 >= c1 or r0 >= r1 or (where is not None and not where[r0:r1, c0:c1].any()):
            continue
        xs = x0 + res * np.arange(c0, c1)
        ys = y0 + res * np.arange(r0, r1)
        dx = np.maximum(np.maximum(low[0] - xs, xs - high[0]), 0.0)
        dy = np.maximum(np.maximum(low[1] - ys, ys - high[1]), 0.0)
        near = np.hypot(dx[None, :], dy[:, None]) < radius
        free[r0:r1, c0:c1][near] = 0.0
    return free


def occupancy_cost(query: LocationQuery, value: object, alive: BoolGrid) -> CostLayer:
    """Rule out cells where the robot's base (radius from its URDF) would hit an obstacle.

    The radius is the base's inner one (half a square base's width): a robot facing a
    counter stands that close, and the circle round its corners would keep it 14 cm
    further away from a PR2's reach; for an arm working sideways, the base's extent that
    way (:func:`facing_radius`). Whether the base, turned as the stand is, fits is the
    ``robot_collision_free`` validator's exact check, which every key that asks for
    occupancy also asks for. Only the cells earlier layers left ``alive`` are decided (the
    probes reach the cells around them that the base would cover).
    """
    robot = query.robot
    if robot is None:
        return CostLayer(np.ones(query.grid.shape))
    radius = facing_radius(query.world, robot)
    top = robot_top(query.world, robot)
    named, large = named_obstacle_boxes(query.world, robot, top)
    free = free_cells(query, [box for _, box in named], radius, alive)
    if large:  # parts whose bounds would cover the room are probed cell by cell
        reach = radius / query.grid.resolution
        around = dilate(alive & (free > 0), reach)
        probed = erode(probed_free(query, robot, top, around), reach, True)
        free = free * probed
    query.blame.later(lambda blame: blame_movable(query, named, radius, alive))
    return CostLayer(free)


def blame_movable(
    query: LocationQuery, named: list[tuple[str, Box]], radius: float, alive: BoolGrid
) -> None:
    """Record, per movable object, the ``alive`` cells (those earlier layers, reachability,
    left) its bounds alone rule out: the stands it took. Run only when the location fails;
    an environment's own parts (a counter) rule out cells in every scene, so cells they rule
    out are nobody's fault here."""
    environments = {o.name for o in query.world.objects(type="environment")}
    fixed = [box for name, box in named if name in environments]
    open_floor = alive & (free_cells(query, fixed, radius, alive) > 0)
    if not open_floor.any():
        return
    counts: dict[str, int] = {}
    taken = np.zeros(query.grid.shape, dtype=bool)
    for owner in sorted({name for name, _ in named} - environments):
        boxes = [box for name, box in named if name == owner]
        ruled_out = open_floor & (free_cells(query, boxes, radius, open_floor) == 0)
        if ruled_out.any():
            counts[owner] = int(np.count_nonzero(ruled_out))
            taken |= ruled_out
    query.blame.blocking_cells(counts, int(np.count_nonzero(taken)))
