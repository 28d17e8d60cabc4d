"""Is the robot, as it stands, free at a base pose? Fast 2.5-D checks confirmed exactly.

The fast check (:class:`~robocram.motion.robot_footprint.RobotFootprint` against an
:class:`~robocram.motion.obstacle_grid.ObstacleGrid`) costs microseconds per pose and is
conservative: when it says free, the robot's and held objects' boxes touch nothing. Boxes
are coarser than the shapes, so where it says "collides" near the start or the goal the
exact PyBullet check decides (the robot put there, then back), and a goal that fits is not
refused; away from them the fast answer stands. Both kinds of check are counted.

Contacts the robot already has where it stands (a finger on a handle) are tolerated for
its first :data:`ESCAPE` of travel, to get away, but never deeper than they start
(:data:`~robocram.motion.hand_contact.KEEP_DEPTH` for numerics): fingers round a handle
once went 5.95 mm into it while the base left (issue 35). :meth:`start_allowances` says
so in the trajectory, so the audit holds the drive to the same bound. The floor and
objects of type ``floor`` may always be touched.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import partial

import numpy as np

from robocram.execution.failures import NavigationGoalOutsideArea
from robocram.motion.cleared_poses import ClearedPoses
from robocram.motion.contact_allowance import ContactAllowance
from robocram.motion.grid_hits_on_demand import GridHitsOnDemand
from robocram.motion.hand_contact import KEEP_DEPTH
from robocram.motion.height_bins import HeightBins
from robocram.motion.obstacle_grid import Box, ObstacleGrid
from robocram.motion.robot_footprint import FloatArray, RobotFootprint
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import (
    Derived,
    ObstacleBoxes,
    PlanningArea,
    RobotHandle,
    Versions,
    World,
    WorldObject,
)

CELL = 0.01  # [m] obstacle grid cells
SPACING = 0.02  # [m] robot sample squares: more than the 1 cm a dense check moves
CONTACT = 0.002  # [m] nearer than this counts as touching, as in World.contacts.collisions
CHUNK = 128  # poses per batch of fast checks along a motion
MARGIN = 0.5  # [m] room around the obstacles, start and goal for going around
ESCAPE = 0.1  # [m] travel from the start during which its contacts are tolerated
CONFIRM_NEAR = 0.3  # [m] travel from the start or goal within which exact checks decide
GAP_QUERY = 0.1  # [m] how far an exact check looks for the gap that lets it skip poses
FOOTPRINTS_KEPT = 8  # robot postures whose footprints a world keeps
LOCAL_MARGIN = 0.6  # [m] the first grid covers the start's and goal's box grown by this
GROWN_ROUNDING = 1e-9  # [m] kept off the grown footprint's reach for rounding of travel


def _refuse_far_goal(
    robot_name: str, start: Pose, goal_xy: tuple[float, float], obstacles: ObstacleBoxes
) -> None:
    """Refuse a goal outside the :class:`PlanningArea` of the obstacles and the start."""
    here = (float(start.position[0]), float(start.position[1]))
    area = PlanningArea.of(obstacles, [here])
    x, y = (float(v) for v in goal_xy)
    if area.contains(x, y):
        return
    raise NavigationGoalOutsideArea(
        f"{robot_name}'s goal ({x:.6g}, {y:.6g}) m is outside the area it drives in: {area}",
        area=(area.low, area.high),
        margin=area.margin,
    )


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
    anchors: tuple[FloatArray, ...] = ()  # start and goal (x, y, unwrapped yaw)
    confirm_everywhere: bool = True  # False while planning: exact checks near anchors only
    allowed_links: frozenset[str] = frozenset()  # robot links that may touch (a hand holding)
    fast_checks: int = 0
    exact_checks: int = field(default=0)
    covered: tuple[tuple[float, float], tuple[float, float]] = ((0.0, 0.0), (0.0, 0.0))
    _obstacles: ObstacleBoxes | None = field(default=None, repr=False)  # read once
    _bins: HeightBins | None = field(default=None, repr=False)
    _cleared_poses: ClearedPoses | None = field(default=None, repr=False)  # exact answers
    _tolerated: dict[_Pair, float] | None = field(default=None, repr=False)  # [m] depths
    _full_answers: dict[bytes, bool] = field(default_factory=dict, repr=False)  # this grid's

    @classmethod
    def build(
        cls,
        robot: RobotHandle,
        goal_xy: tuple[float, float],
        allowed_links: frozenset[str] = frozenset(),
    ) -> BaseCollisionChecker:
        """Rasterise the robot as it stands and the world around it and the goal;
        ``allowed_links`` may touch anything (the exact check leaves them out).

        The grid first covers only the box round the start and the goal (what the direct
        motion sweeps); a pose beyond it widens the grid to the whole world at its first
        fast check (:meth:`_widen`), so detours and planning see everything.

        Raises:
            NavigationGoalOutsideArea: the goal is outside the world's
                :class:`~robocram.world.PlanningArea` (before anything is rasterised).
        """
        world = robot.world
        start = world.pose(robot.name)
        carried = robot.holding()
        bins, footprint = _footprint(robot, carried, start)
        skip = {robot.name, *carried} | {o.name for o in world.objects("floor")}
        obstacles = world.contacts.obstacle_boxes(skip)
        _refuse_far_goal(robot.name, start, goal_xy, obstacles)
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
        grid = _grid(obstacles, covered, footprint, bins)
        checker = cls(world, robot.name, start, carried, footprint, grid, bounds)
        checker.allowed_links = allowed_links
        checker.covered = covered
        checker._obstacles = obstacles
        checker._bins = bins
        return checker

    @property
    def tolerated(self) -> dict[_Pair, float]:
        """The contacts the robot has at its start and how deep [m] each is there (read
        when first asked: most drives never check a pose within :data:`ESCAPE` of it
        exactly). It is left at its start."""
        if self._tolerated is None:
            self.world.set_pose(self.robot, self.start)
            self._tolerated = self._contact_depths()
        return self._tolerated

    def start_allowances(self) -> tuple[ContactAllowance, ...]:
        """The start contacts a drive was allowed, as its trajectory stores them: each
        penetrating one at most as deep as it started (and :data:`KEEP_DEPTH`). Empty when
        no pose near the start needed the exact check: then the robot touched nothing
        there (the fast check is conservative)."""
        if self._tolerated is None:
            return ()
        return tuple(
            ContactAllowance(_robot_side(side, self.robot), other, depth + KEEP_DEPTH)
            for (side, other), depth in sorted(self._tolerated.items())
            if depth > 0.0
        )

    def _deepened(self, tolerated: dict[_Pair, float]) -> list[_Pair]:
        """The contacts where the robot is now that are not among ``tolerated`` or deeper
        than they started (by more than :data:`KEEP_DEPTH`)."""
        return [
            pair
            for pair, depth in self._contact_depths().items()
            if pair not in tolerated or depth > tolerated[pair] + KEEP_DEPTH
        ]

    def __enter__(self) -> BaseCollisionChecker:
        return self

    def __exit__(self, *exc: object) -> None:
        self.world.set_pose(self.robot, self.start)

    def fast_hits(self, poses: FloatArray, boundary: bool) -> np.ndarray:
        """Per pose, whether the fast check finds a possible collision."""
        self.fast_checks += len(poses)
        fp = self.footprint
        if boundary:
            return self._grid_hits(poses, fp.boundary_points, fp.boundary_masks)
        return self._grid_hits(poses, fp.points, fp.masks)

    def _grid_hits(self, poses: FloatArray, points: FloatArray, masks: np.ndarray) -> np.ndarray:
        """Per pose, whether any of ``points`` (base frame) lies in a cell sharing bits with
        its ``masks``; the grid widens first when a pose lies beyond it."""
        return self.grid.hits(poses, points, masks, self._on_grid(poses))

    def _on_grid(self, poses: FloatArray) -> bool:
        """Whether the grid holds every pose of ``poses``, widened first when one lies
        beyond it (:meth:`_covers`)."""
        inside = self._covers(poses)
        if not inside and self.covered != self.bounds:
            self._widen()
            inside = self._covers(poses)
        return inside

    def _covers(self, poses: FloatArray) -> bool:
        """Whether the grid holds every base position of ``poses`` (its cells reach past
        them by the robot's reach, so every sample point falls on the grid)."""
        (x0, y0), (x1, y1) = self.covered
        if len(poses) == 1:  # a tree node's check: plain floats, not four reductions
            x, y = poses[0, :2].tolist()
            return bool(x0 <= x <= x1 and y0 <= y <= y1)
        xs, ys = poses[:, 0], poses[:, 1]
        return bool(xs.min() >= x0 and xs.max() <= x1 and ys.min() >= y0 and ys.max() <= y1)

    def _widen(self) -> None:
        """Rasterise the whole world: a pose left the box round the start and goal."""
        assert self._obstacles is not None and self._bins is not None  # set by build
        self.grid = _grid(self._obstacles, self.bounds, self.footprint, self._bins)
        self.covered = self.bounds
        self._full_answers.clear()  # the new grid's cells are counted from another corner

    def pose_free(self, pose: FloatArray) -> bool:
        """Whether the robot is free at ``pose`` (fast, then exact where it may collide)."""
        if not self._full_hit(pose):
            return True
        return self._cleared(pose)

    def _full_hit(self, pose: FloatArray) -> bool:
        """:meth:`fast_hits` of one pose with the whole footprint, counted as a check; the
        answer is kept while the grid stands: every edge OMPL grows from a tree node checks
        the node again (three in five of a Stretch breakfast's such checks, issue 40)."""
        self.fast_checks += 1
        key = pose.tobytes()
        hit = self._full_answers.get(key)
        if hit is None:
            fp = self.footprint
            hit = bool(self._grid_hits(pose[None, :], fp.points, fp.masks)[0])
            self._full_answers[key] = hit  # after any widening: the answer of this grid
        return hit

    def first_blocked(self, poses: FloatArray) -> int | None:
        """Index of the first pose of a dense motion where the robot collides, or None.

        The first pose and every pose after one the exact check had to clear get the full
        fast check; the others only the boundary's. A pose the exact check clears also
        says how far the robot is from everything there: the poses after it that move no
        point of the robot farther than that are free without a check. Blocks of poses
        the grown footprint proves free at their middle (:meth:`_unproven`) are skipped.
        """
        cleared: tuple[FloatArray, float] | None = None  # (pose, gap [m]) of the last exact
        for first, stop in self._unproven(poses):
            blocked, cleared = self._first_blocked_in(poses[first:stop], cleared)
            if blocked is not None:
                return first + blocked
        return None

    def _first_blocked_in(
        self, poses: FloatArray, cleared: tuple[FloatArray, float] | None
    ) -> tuple[int | None, tuple[FloatArray, float] | None]:
        """:meth:`first_blocked` of a run of poses whose first is checked in full (the pose
        before it, if any, was proven free, not checked on the grid), and the last pose
        the exact check cleared with a gap."""
        full_next = True
        for begin in range(0, len(poses), CHUNK):
            chunk = poses[begin : begin + CHUNK]
            edge = self._boundary_hits(chunk)
            for k, pose in enumerate(chunk):
                if cleared is not None and self._travel(cleared[0], pose) < cleared[1]:
                    continue  # within the cleared pose's gap; the next checked one is full
                cleared = None
                hit = self._full_hit(pose) if full_next else edge[k]
                full_next = False
                if hit:
                    gap = self._exact_gap(pose)
                    if gap is None:
                        return begin + k, cleared
                    cleared = (pose, gap) if gap > 0.0 else None
                    full_next = True
        return None, cleared

    def _boundary_hits(self, poses: FloatArray) -> GridHitsOnDemand:
        """:meth:`fast_hits` of ``poses`` with the boundary, counted (and the grid widened)
        now, each looked up when asked: a motion stops at its first blocked pose."""
        self.fast_checks += len(poses)
        fp = self.footprint
        inside = self._on_grid(poses)
        return GridHitsOnDemand(self.grid, poses, fp.boundary_points, fp.boundary_masks, inside)

    def _unproven(self, poses: FloatArray) -> list[tuple[int, int]]:
        """Ranges ``[first, stop)`` of ``poses`` (a dense motion) that the grown footprint
        (:class:`RobotFootprint`) did not prove free: every pose within ``grown_by`` of
        travel of a pose where the grown points are free is free. The poses are cut into
        blocks, each proven by the grown check at its middle pose; the proven ones count
        as fast checks. Only while the motion is confirmed everywhere: planning keeps its
        own (coarse) checks."""
        count = len(poses)
        fp = self.footprint
        if not self.confirm_everywhere or count < 2:
            return [(0, count)]
        step = poses[1:] - poses[:-1]
        travel = np.hypot(step[:, 0], step[:, 1]) + fp.reach * np.abs(_turns(step[:, 2]))
        most = float(travel.max())  # [m] the longest step
        if most <= 0.0:  # the robot stands still
            return [(0, count)]
        half = int((fp.grown_by - GROWN_ROUNDING) / most)  # steps from a block's middle
        block = 2 * half + 1
        if half < 1 or count < block:
            return [(0, count)]
        centres = np.minimum(np.arange(half, count + half, block), count - 1)
        free = ~self._grid_hits(poses[centres], fp.grown_points, fp.grown_masks)
        proven = np.repeat(free, block)[:count]
        self.fast_checks += len(centres) - int(free.sum()) + int(proven.sum())
        edges = np.flatnonzero(np.diff(np.concatenate([[True], proven, [True]]).view(np.int8)))
        return [(int(a), int(b)) for a, b in zip(edges[::2], edges[1::2], strict=True)]

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

    def known_free(self, pose: FloatArray) -> None:
        """Keep that the exact check found the robot free at ``pose`` (a goal checked
        before the checker was built), with no gap: it is not asked again."""
        if self._cleared_poses is None:
            self._cleared_poses = ClearedPoses(self.footprint.reach)
        self._cleared_poses.add(pose, 0.0)

    def _measured_gap(self, pose: FloatArray) -> float | None:
        """:meth:`_exact_gap` by the exact check itself."""
        self.exact_checks += 1
        start = np.array([*self.start.position[:2], yaw_of(self.start)])
        tolerated = self.tolerated if self._travel(start, pose) <= ESCAPE else {}
        self._place(pose)
        if tolerated:
            return None if self._deepened(tolerated) else 0.0
        nearest = min(self._distances(), default=GAP_QUERY)
        return None if nearest <= CONTACT else nearest - CONTACT

    def _place(self, pose: FloatArray) -> None:
        x, y, yaw = (float(v) for v in pose)
        self.world.set_pose(
            self.robot, Pose((x, y, self.start.position[2]), quat.from_euler(0.0, 0.0, yaw))
        )

    def _distances(self) -> Iterator[float]:
        """Distances [m] below :data:`GAP_QUERY` from the robot (and what it carries, but
        not its ``allowed_links``) to every obstacle, where the robot is now."""
        assert self._obstacles is not None  # read by build
        group = [self.robot, *self.carried]
        floors = [o.name for o in self.world.objects("floor")]
        for body in group:
            ignore = floors + [g for g in group if g != body]
            for link, _, _, distance in self.world.contacts.link_distances(
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
        return sorted({other for _, other in self.blocking_pairs(pose)})

    def blocking_pairs(self, pose: FloatArray) -> list[tuple[str, str]]:
        """``(part of the robot or what it carries, object/link it touches)`` at ``pose``
        by the exact check, as :meth:`blockers` names them: which link of the robot meets
        what (an open hand still round the thing it just let go)."""
        self.exact_checks += 1
        start = np.array([*self.start.position[:2], yaw_of(self.start)])
        tolerated = self.tolerated if self._travel(start, pose) <= ESCAPE else {}
        self._place(pose)
        return sorted(set(self._deepened(tolerated)))

    def _contact_depths(self) -> dict[_Pair, float]:
        """``(part of the robot, object/link it touches)`` pairs where the robot is now,
        each with how deep [m] it penetrates (0: touching, or within :data:`CONTACT`)."""
        floors = [o.name for o in self.world.objects("floor")]
        if self._obstacles is None:  # only the robot and what it carries move here
            self._obstacles = self.world.contacts.obstacle_boxes(
                [self.robot, *self.carried, *floors]
            )
        group = [self.robot, *self.carried]
        depths: dict[_Pair, float] = {}
        for body in group:
            ignore = floors + [g for g in group if g != body]
            for link, other, other_link, gap in self.world.contacts.link_distances(
                body, ignore=ignore, distance=CONTACT, obstacles=self._obstacles
            ):
                if body == self.robot and link in self.allowed_links:
                    continue
                pair = (f"{body}/{link}", _named(other, other_link))
                depths[pair] = max(depths.get(pair, 0.0), -gap)
        return depths


_Pair = tuple[str, str]  # (body/link of the robot or what it carries, object or object/link)


def _named(other: WorldObject, link: str) -> str:
    """``other``'s name, with ``/link`` when it has several links."""
    return f"{other.name}/{link}" if len(other.link_index) > 1 else other.name


def _robot_side(side: str, robot_name: str) -> str:
    """A pair's ``body/link`` as a :class:`ContactAllowance` names it: the robot's link,
    or the held object's name."""
    body, _, link = side.partition("/")
    return link if body == robot_name else body


def _grid(
    obstacles: ObstacleBoxes,
    area: tuple[tuple[float, float], tuple[float, float]],
    footprint: RobotFootprint,
    bins: HeightBins,
) -> ObstacleGrid:
    """The obstacle grid over ``area`` (base positions [m]) grown by the reach of the
    robot's grown squares (:class:`RobotFootprint`): only the boxes that reach into it
    are rasterised. Its corner lies on the lattice of :data:`CELL` through the map's
    origin, so a local grid and the whole world's share their cells."""
    pad = footprint.grown_reach + footprint.dilation + 2 * CELL  # the grown squares too
    lower = (
        math.floor((area[0][0] - pad) / CELL) * CELL,
        math.floor((area[0][1] - pad) / CELL) * CELL,
    )
    upper = (area[1][0] + pad, area[1][1] + pad)
    inside = np.flatnonzero(
        (obstacles.low[:, 0] <= upper[0]) & (obstacles.high[:, 0] >= lower[0])
        & (obstacles.low[:, 1] <= upper[1]) & (obstacles.high[:, 1] >= lower[1])
    )  # fmt: skip
    boxes = np.stack([obstacles.low[inside], obstacles.high[inside]], axis=1)
    return ObstacleGrid.build(boxes, lower, upper, CELL, footprint.dilation, bins)


def _contacts_now(
    robot: RobotHandle,
    carried: tuple[str, ...],
    allowed_links: frozenset[str],
    obstacles: ObstacleBoxes | None = None,
) -> Iterator[tuple[str, str]]:
    """``(part of the robot, object/link it touches)`` pairs where the robot is now, the
    floor and the ``allowed_links`` left out."""
    world, name = robot.world, robot.name
    floors = [o.name for o in world.objects("floor")]
    group = [name, *carried]
    for body in group:
        ignore = floors + [g for g in group if g != body]
        for link, other, other_link in world.contacts.link_pairs_in_contact(
            body, ignore=ignore, distance=CONTACT, obstacles=obstacles
        ):
            if body == name and link in allowed_links:
                continue
            yield f"{body}/{link}", _named(other, other_link)


def blockers_at(
    robot: RobotHandle, pose: FloatArray, allowed_links: frozenset[str] = frozenset()
) -> list[str]:
    """What the robot (and what it carries) touches standing at ``pose`` (map x, y, yaw),
    by the exact check, without the grid a path needs: a goal that is plainly blocked (a
    stand under a table's edge) costs a millisecond, not a checker. It is put back."""
    return sorted({other for _, other in blocking_pairs_at(robot, pose, allowed_links)})


def blocking_pairs_at(
    robot: RobotHandle, pose: FloatArray, allowed_links: frozenset[str] = frozenset()
) -> list[tuple[str, str]]:
    """``(part of the robot, object/link it touches)`` pairs standing at ``pose``, as
    :func:`blockers_at` finds them: which of its own links meet what (a torso lowered to
    look into a drawer puts the arms' shoulders at the opened drawer's height)."""
    world = robot.world
    start = world.pose(robot.name)
    carried = robot.holding()
    floors = [o.name for o in world.objects("floor")]
    obstacles = world.contacts.obstacle_boxes([robot.name, *carried, *floors])  # as drives
    x, y, yaw = (float(v) for v in pose)
    world.set_pose(robot.name, Pose((x, y, start.position[2]), quat.from_euler(0.0, 0.0, yaw)))
    try:
        return sorted(set(_contacts_now(robot, carried, allowed_links, obstacles)))
    finally:
        world.set_pose(robot.name, start)


def _footprint(
    robot: RobotHandle, carried: tuple[str, ...], start: Pose
) -> tuple[HeightBins, RobotFootprint]:
    """The height bins and footprint of the robot as it stands, kept with the world for
    the last few postures: a robot drives in few postures (arms parked, or carrying), so
    most drives find theirs. The key is everything the footprint depends on: the joints,
    the height of the base and where each carried object is in the base frame."""
    world = robot.world
    base_z = start.position[2]
    key = (
        robot.name,
        tuple(world.joint_states(robot.name).items()),
        base_z,
        tuple((name, _in_base(start, world.pose(name))) for name in carried),
    )
    build = partial(_built_footprint, robot, carried, start)
    return world.derived(_kept_footprints).get(key, build, world.versions)


def _built_footprint(
    robot: RobotHandle, carried: tuple[str, ...], start: Pose
) -> tuple[HeightBins, RobotFootprint]:
    base_z = start.position[2]
    boxes = _boxes_in_base(robot, carried, start)
    bins = HeightBins.up_to(base_z + max(b[1][2] for b in boxes) + CONTACT)
    return bins, RobotFootprint.build(boxes, base_z, bins, SPACING, CONTACT)


def _in_base(base: Pose, pose: Pose) -> tuple[float, ...]:
    relative = base.inverse() * pose
    return (*relative.position, *relative.orientation)


def _kept_footprints(world: World) -> Derived[_PostureKey, tuple[HeightBins, RobotFootprint]]:
    """The footprints a world keeps (the key under which :meth:`World.derived` keeps them):
    the robot's posture is their key, and they stay while its body is the same."""
    return Derived(_robot_created, size=FOOTPRINTS_KEPT, lru=True)


_PostureKey = tuple[object, ...]  # the robot's name first


def _robot_created(versions: Versions, key: _PostureKey) -> int:
    return versions.created(str(key[0]))


def _boxes_in_base(robot: RobotHandle, carried: tuple[str, ...], start: Pose) -> list[Box]:
    """Every link box of the robot and what it holds, in the base frame (robot at yaw 0)."""
    world = robot.world
    x, y, z = start.position
    world.set_pose(robot.name, Pose((x, y, z)))
    try:
        found = [
            box
            for body in (robot.name, *carried)
            for box in world.contacts.link_aabbs(body).values()
        ]
    finally:
        world.set_pose(robot.name, start)
    return [((lo[0] - x, lo[1] - y, lo[2] - z), (hi[0] - x, hi[1] - y, hi[2] - z))
            for lo, hi in found]  # fmt: skip


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


def _turns(angles: FloatArray) -> FloatArray:
    """:func:`_turn` of every angle [rad]."""
    return np.asarray((angles + math.pi) % (2.0 * math.pi) - math.pi)
