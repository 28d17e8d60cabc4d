"""Is the robot, as it stands, free at a base pose? Fast 2.5-D checks confirmed exactly.

The fast check (:class:`~robocram.motion.robot_footprint.RobotFootprint` against an
:class:`~robocram.motion.obstacle_grid.ObstacleGrid`) costs microseconds per pose and is
conservative: when it says free, the robot's and held objects' boxes touch nothing. Boxes
are coarser than the shapes, so where it says "collides" near the start or the goal the
exact PyBullet check decides (the robot put there, then back), and a goal that fits is not
refused; away from them the fast answer stands. Both kinds of check are counted.

Contacts the robot already has where it stands (a finger on a handle) are tolerated for
its first :data:`ESCAPE` of travel, to get away; the floor and objects of type ``floor``
may always be touched.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from robocram.motion.cleared_poses import ClearedPoses
from robocram.motion.height_bins import HeightBins
from robocram.motion.kept_grids import kept_grids
from robocram.motion.obstacle_grid import ObstacleGrid
from robocram.motion.robot_footprint import FloatArray, RobotFootprint
from robocram.motion.standing_footprint import CONTACT, standing_footprint
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import ObstacleBoxes, World

CELL = 0.01  # [m] obstacle grid cells
CHUNK = 128  # poses per batch of fast checks along a motion
MARGIN = 0.5  # [m] room around the obstacles, start and goal for going around
ESCAPE = 0.1  # [m] travel from the start during which its contacts are tolerated
CONFIRM_NEAR = 0.3  # [m] travel from the start or goal within which exact checks decide
GAP_QUERY = 0.05  # [m] how far an exact check looks for the gap that lets it skip poses
LOCAL_MARGIN = 0.6  # [m] the first grid covers the start's and goal's box grown by this
WIDE = 0.1  # [m] a pose free on the wide grid frees the poses that move no point farther


@dataclass
class BaseCollisionChecker:
    """Checks base poses ``(x, y, yaw)`` (map) of ``robot`` in ``world``; counts its checks.

    Use it as a context manager: on leaving, the robot is back at its start pose.
    """

    world: World
    robot: str
    start: Pose
    carried: tuple[str, ...]
    footprint: RobotFootprint
    grid: ObstacleGrid
    bounds: tuple[tuple[float, float], tuple[float, float]]  # [m] lower, upper x y to plan in
    tolerated: frozenset[tuple[str, str]] = frozenset()
    anchors: tuple[FloatArray, ...] = ()  # start and goal (x, y, unwrapped yaw)
    confirm_everywhere: bool = True  # False while planning: exact checks near anchors only
    allowed_links: frozenset[str] = frozenset()  # robot links that may touch (a hand holding)
    fast_checks: int = 0
    exact_checks: int = field(default=0)
    covered: tuple[tuple[float, float], tuple[float, float]] = ((0.0, 0.0), (0.0, 0.0))
    _obstacles: ObstacleBoxes | None = field(default=None, repr=False)  # read once
    _bins: HeightBins | None = field(default=None, repr=False)
    _wide: ObstacleGrid | None = field(default=None, repr=False)  # of _surely_free, lazily
    _cleared_poses: ClearedPoses | None = field(default=None, repr=False)  # exact answers

    @classmethod
    def build(
        cls,
        world: World,
        robot: str,
        goal_xy: tuple[float, float],
        allowed_links: frozenset[str] = frozenset(),
    ) -> BaseCollisionChecker:
        """Rasterise the robot as it stands and the world around it and the goal;
        ``allowed_links`` may touch anything (the exact check leaves them out).

        The grid first covers only the box round the start and the goal (what the direct
        motion sweeps); a pose beyond it widens the grid to the whole world at its first
        fast check (:meth:`_widen`), so detours and planning see everything.
        """
        start = world.pose(robot)
        carried = _carried(world, robot)
        bins, footprint = standing_footprint(world, robot, carried, start)
        skip = {robot, *carried} | {o.name for o in world.objects("floor")}
        obstacles = world.obstacle_boxes(skip)
        ends = np.array([start.position[:2], goal_xy], dtype=float)
        low = np.minimum(ends.min(axis=0), obstacles.low[:, :2].min(axis=0, initial=np.inf))
        high = np.maximum(ends.max(axis=0), obstacles.high[:, :2].max(axis=0, initial=-np.inf))
        bounds = (
            (float(low[0]) - MARGIN, float(low[1]) - MARGIN),
            (float(high[0]) + MARGIN, float(high[1]) + MARGIN),
        )
        near = (
            (float(ends[:, 0].min()) - LOCAL_MARGIN, float(ends[:, 1].min()) - LOCAL_MARGIN),
            (float(ends[:, 0].max()) + LOCAL_MARGIN, float(ends[:, 1].max()) + LOCAL_MARGIN),
        )
        covered = (
            (max(near[0][0], bounds[0][0]), max(near[0][1], bounds[0][1])),
            (min(near[1][0], bounds[1][0]), min(near[1][1], bounds[1][1])),
        )
        grid = _grid(world, obstacles, covered, footprint, bins)
        checker = cls(world, robot, start, carried, footprint, grid, bounds)
        checker.allowed_links = allowed_links
        checker.covered = covered
        checker._obstacles = obstacles
        checker._bins = bins
        checker.tolerated = frozenset(checker._contacts())
        return checker

    def __enter__(self) -> BaseCollisionChecker:
        return self

    def __exit__(self, *exc: object) -> None:
        self.world.set_pose(self.robot, self.start)

    def fast_hits(self, poses: FloatArray, boundary: bool) -> np.ndarray:
        """Per pose, whether the fast check finds a possible collision."""
        self.fast_checks += len(poses)
        return self._lookup(poses, boundary)

    def _lookup(self, poses: FloatArray, boundary: bool) -> np.ndarray:
        """:meth:`fast_hits`, not counted."""
        inside = self._on_grid(poses)
        fp = self.footprint
        points = fp.boundary_points if boundary else fp.points
        masks = fp.boundary_masks if boundary else fp.masks
        return self.grid.hits(poses, points, masks, inside)

    def _on_grid(self, poses: FloatArray) -> bool:
        """Whether the grid holds ``poses``, after widening it to the world if they leave
        it (False: some lie beyond even that, the lookups clip)."""
        inside = self._covers(poses)
        if not inside and self.covered != self.bounds:
            self._widen()
            inside = self._covers(poses)
        return inside

    def _stride(self, poses: FloatArray) -> int:
        """How many poses either side of one the wide grid frees with it: as many as move
        no point of the robot farther than :data:`WIDE` (0: the steps are too long)."""
        if len(poses) < 2:
            return 0
        step = np.diff(poses, axis=0)
        turn = np.abs((step[:, 2] + np.pi) % (2.0 * np.pi) - np.pi)
        longest = float(np.max(np.hypot(step[:, 0], step[:, 1]) + self.footprint.reach * turn))
        return len(poses) if longest <= 0.0 else int(WIDE / longest)

    def _surely_free(self, poses: FloatArray, stride: int) -> npt.NDArray[np.bool_]:
        """Per pose, whether it is free by the wide grid, whose boxes are grown by
        :data:`WIDE` more (and a cell): every point of the robot free there at one pose
        is free on the fine grid at every pose within ``stride`` of it (their points are
        at most :data:`WIDE` apart). Every ``2 * stride + 1``-th pose is looked up."""
        if stride < 1:
            return np.zeros(len(poses), dtype=bool)
        period = 2 * stride + 1
        centres = np.minimum(np.arange(stride, len(poses) + stride, period), len(poses) - 1)
        inside = self._on_grid(poses[centres])
        if self._wide is None:
            assert self._obstacles is not None and self._bins is not None  # set by build
            self._wide = _grid(
                self.world, self._obstacles, self.covered, self.footprint, self._bins, WIDE
            )
        fp = self.footprint
        hit = self._wide.hits(poses[centres], fp.points, fp.masks, inside)
        return np.repeat(~hit, period)[: len(poses)]

    def _covers(self, poses: FloatArray) -> bool:
        """Whether the grid holds every base position of ``poses`` (its cells reach past
        them by the robot's reach, so every sample point falls on the grid)."""
        (x0, y0), (x1, y1) = self.covered
        xs, ys = poses[:, 0], poses[:, 1]
        return bool(xs.min() >= x0 and xs.max() <= x1 and ys.min() >= y0 and ys.max() <= y1)

    def _widen(self) -> None:
        """Rasterise the whole world: a pose left the box round the start and goal."""
        assert self._obstacles is not None and self._bins is not None  # set by build
        self.grid = _grid(self.world, self._obstacles, self.bounds, self.footprint, self._bins)
        self.covered = self.bounds
        self._wide = None

    def pose_free(self, pose: FloatArray) -> bool:
        """Whether the robot is free at ``pose`` (fast, then exact where it may collide)."""
        if not self.fast_hits(pose[None, :], boundary=False)[0]:
            return True
        return self._cleared(pose)

    def first_blocked(self, poses: FloatArray) -> int | None:
        """Index of the first pose of a dense motion where the robot collides, or None.

        The first pose and every pose after one the exact check had to clear get the full
        fast check; the others only the boundary's. A pose the exact check clears also
        says how far the robot is from everything there: the poses after it that move no
        point of the robot farther than that are free without a check. Poses the wide grid
        frees (:meth:`_surely_free`) are free without either lookup; they are counted as
        the lookups they spare, so a budget of fast checks means what it meant.
        """
        full_next = True
        cleared: tuple[FloatArray, float] | None = None  # (pose, gap [m]) of the last exact
        stride = self._stride(poses)
        for begin in range(0, len(poses), CHUNK):
            chunk = poses[begin : begin + CHUNK]
            free = self._surely_free(chunk, stride)
            self.fast_checks += len(chunk)
            edge = np.zeros(len(chunk), dtype=bool)
            ask = np.flatnonzero(~free)
            if ask.size:
                edge[ask] = self._lookup(chunk[ask], boundary=True)
            k = -1
            while k + 1 < len(chunk):
                k += 1
                if not full_next and cleared is None:  # on to the next boundary hit
                    ahead = np.flatnonzero(edge[k:])
                    if not ahead.size:
                        break
                    k += int(ahead[0])
                pose = chunk[k]
                if cleared is not None and self._travel(cleared[0], pose) < cleared[1]:
                    continue  # within the cleared pose's gap; the next checked one is full
                cleared = None
                if full_next:
                    self.fast_checks += 1
                    hit = not free[k] and bool(self._lookup(pose[None, :], boundary=False)[0])
                else:
                    hit = bool(edge[k])
                full_next = False
                if hit:
                    gap = self._exact_gap(pose)
                    if gap is None:
                        return begin + k
                    cleared = (pose, gap) if gap > 0.0 else None
                    full_next = True
        return None

    def _travel(self, a: FloatArray, b: FloatArray) -> float:
        """How far [m] any point of the robot moves at most from base pose ``a`` to ``b``."""
        return math.hypot(b[0] - a[0], b[1] - a[1]) + self.footprint.reach * abs(_turn(b[2] - a[2]))

    def _exact_gap(self, pose: FloatArray) -> float | None:
        """None when the exact check does not clear a pose the fast check flagged; else
        how much farther [m] than the contact distance the robot is from everything (up
        to :data:`GAP_QUERY`). Near the start, where its contacts are tolerated, the gap
        is 0: the tolerance ends within :data:`ESCAPE` of travel.

        While planning (``confirm_everywhere`` False) it is asked only near the start and
        the goal (within :data:`CONFIRM_NEAR` of travel), where the robot must get close to
        furniture; elsewhere a planned path keeps the fast check's few centimetres of extra
        clearance, and planning stays fast. The direct motion is confirmed everywhere.
        """
        near = self.confirm_everywhere or any(
            self._travel(a, pose) <= CONFIRM_NEAR for a in self.anchors
        )
        if not near:
            return None
        if self._cleared_poses is None:
            self._cleared_poses = ClearedPoses(self.footprint.reach)
        known, gap = self._cleared_poses.known(pose)
        if not known:
            gap = self._measured_gap(pose)
            self._cleared_poses.add(pose, gap)
        return gap

    def _measured_gap(self, pose: FloatArray) -> float | None:
        """:meth:`_exact_gap` by the exact check itself."""
        self.exact_checks += 1
        self._place(pose)
        start = np.array([*self.start.position[:2], yaw_of(self.start)])
        if self.tolerated and self._travel(start, pose) <= ESCAPE:
            return None if self._touching(self.tolerated) else 0.0
        nearest = min(self._distances(), default=GAP_QUERY)
        return None if nearest <= CONTACT else nearest - CONTACT

    def _place(self, pose: FloatArray) -> None:
        x, y, yaw = (float(v) for v in pose)
        self.world.set_pose(
            self.robot, Pose((x, y, self.start.position[2]), quat.from_euler(0.0, 0.0, yaw))
        )

    def _touching(self, tolerated: frozenset[tuple[str, str]]) -> bool:
        return any(pair not in tolerated for pair in self._contacts())

    def _distances(self) -> Iterator[float]:
        """Distances [m] below :data:`GAP_QUERY` from the robot (and what it carries, but
        not its ``allowed_links``) to every obstacle, where the robot is now."""
        assert self._obstacles is not None  # read by build
        group = [self.robot, *self.carried]
        floors = [o.name for o in self.world.objects("floor")]
        for body in group:
            ignore = floors + [g for g in group if g != body]
            for link, _, _, distance in self.world.link_distances(
                body, ignore=ignore, distance=GAP_QUERY, obstacles=self._obstacles
            ):
                if body != self.robot or link not in self.allowed_links:
                    yield distance

    def _cleared(self, pose: FloatArray) -> bool:
        """Whether the exact check clears a pose the fast check flagged (see
        :meth:`_exact_gap`)."""
        return self._exact_gap(pose) is not None

    def blockers(self, pose: FloatArray) -> list[str]:
        """What the robot touches at ``pose`` by the exact check (``object/link`` names)."""
        self.exact_checks += 1
        self._place(pose)
        start = np.array([*self.start.position[:2], yaw_of(self.start)])
        tolerated = self.tolerated if self._travel(start, pose) <= ESCAPE else frozenset()
        return sorted({other for pair in self._contacts() if pair not in tolerated
                       for other in pair[1:]})  # fmt: skip

    def _contacts(self) -> Iterator[tuple[str, str]]:
        """``(part of the robot, object/link it touches)`` pairs where the robot is now."""
        if self._obstacles is None:  # only the robot and what it carries move here
            floors = [o.name for o in self.world.objects("floor")]
            self._obstacles = self.world.obstacle_boxes([self.robot, *self.carried, *floors])
        return _contacts_now(
            self.world, self.robot, self.carried, self.allowed_links, self._obstacles
        )


def _grid(
    world: World,
    obstacles: ObstacleBoxes,
    area: tuple[tuple[float, float], tuple[float, float]],
    footprint: RobotFootprint,
    bins: HeightBins,
    wider: float = 0.0,
) -> ObstacleGrid:
    """The obstacle grid over ``area`` (base positions [m]) grown by the robot's reach:
    only the boxes that reach into it are rasterised (the furniture's kept by the world,
    :mod:`~robocram.motion.kept_grids`). Its corner lies on the lattice of :data:`CELL`
    through the map's origin, so a local grid and the whole world's share their cells.
    ``wider`` [m] > 0: the wide grid, its boxes grown by that and a cell more (the cell a
    point may lie across from the box it hits)."""
    pad = footprint.reach + footprint.dilation + 2 * CELL
    lower = (
        math.floor((area[0][0] - pad) / CELL) * CELL,
        math.floor((area[0][1] - pad) / CELL) * CELL,
    )
    upper = (area[1][0] + pad, area[1][1] + pad)
    dilation = footprint.dilation + (wider + CELL if wider > 0.0 else 0.0)
    kept = world.derived(kept_grids)
    return kept.window(obstacles, lower, upper, CELL, dilation, bins)


def _contacts_now(
    world: World,
    robot: str,
    carried: tuple[str, ...],
    allowed_links: frozenset[str],
    obstacles: ObstacleBoxes | None = None,
) -> Iterator[tuple[str, str]]:
    """``(part of the robot, object/link it touches)`` pairs where the robot is now, the
    floor and the ``allowed_links`` left out."""
    floors = [o.name for o in world.objects("floor")]
    group = [robot, *carried]
    for body in group:
        ignore = floors + [g for g in group if g != body]
        for link, other, other_link in world.link_pairs_in_contact(
            body, ignore=ignore, distance=CONTACT, obstacles=obstacles
        ):
            if body == robot and link in allowed_links:
                continue
            several = len(other.link_index) > 1
            yield f"{body}/{link}", f"{other.name}/{other_link}" if several else other.name


def blockers_at(
    world: World, robot: str, pose: FloatArray, allowed_links: frozenset[str] = frozenset()
) -> list[str]:
    """What the robot (and what it carries) touches standing at ``pose`` (map x, y, yaw),
    by the exact check, without the grid a path needs: a goal that is plainly blocked (a
    stand under a table's edge) costs a millisecond, not a checker. It is put back."""
    start = world.pose(robot)
    x, y, yaw = (float(v) for v in pose)
    world.set_pose(robot, Pose((x, y, start.position[2]), quat.from_euler(0.0, 0.0, yaw)))
    try:
        pairs = _contacts_now(world, robot, _carried(world, robot), allowed_links)
        return sorted({other for _, other in pairs})
    finally:
        world.set_pose(robot, start)


def _carried(world: World, robot: str) -> tuple[str, ...]:
    """Objects the robot holds, and what they hold, recursively."""
    found: list[str] = []
    frontier = [robot]
    while frontier:
        held = list(world.attachments(frontier.pop()))
        found += held
        frontier += held
    return tuple(found)


def yaw_of(pose: Pose) -> float:
    """The heading [rad] of ``pose`` about the map's z axis."""
    return float(quat.to_euler(pose.orientation)[2])


def planar_steps(delta_xy: float, delta_yaw: float, reach: float) -> int:
    """Checks needed so no point within ``reach`` moves > 1 cm, nor the heading > 0.02 rad."""
    travel = delta_xy + reach * abs(delta_yaw)
    return max(1, math.ceil(travel / 0.01), math.ceil(abs(delta_yaw) / 0.02))


def _turn(angle: float) -> float:
    """``angle`` [rad] as the shortest turn, in [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi
