"""Going: a collision-free path of the base to a goal pose, timed as a trajectory.

The robot goes as it stands: its arms where they are, what it holds riding along, at its
height. First the direct motion (straight for a holonomic base, the shortest Reeds-Shepp
curve for a car) is checked densely. When it is blocked, a holonomic base tries the two
detours a driver would take before planning: leave backwards along its heading, and
arrive straight ahead along the goal's (the direct motion of a long drive mostly fails
by turning while close to the furniture it leaves or reaches). Only when those are
blocked too does OMPL plan around (:mod:`robocram.motion.ompl_base_planner`). A goal in collision is
``NavigationPoseUnreachable``; a goal no path reaches within the budget is
``NavigationPathBlocked``, naming what the direct motion runs into first, where, and
which of the robot's links meet it there.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, replace

import numpy as np

from robocram.execution.failures import NavigationPathBlocked, NavigationPoseUnreachable
from robocram.motion.base_collision import (
    ESCAPE,
    BaseCollisionChecker,
    blocking_pairs_at,
    yaw_of,
)
from robocram.motion.car_timing import time_car_path
from robocram.motion.errors import MotionError, MotionInputError
from robocram.motion.joint_limits import joint_limits
from robocram.motion.joint_trajectory import BASE_JOINTS, JointTrajectory
from robocram.motion.ompl_base_planner import Area, motion_poses, planned_waypoints
from robocram.motion.time_parameterization import time_parameterize
from robocram.tf import Pose
from robocram.world import RobotHandle

DEFAULT_BUDGET = 20_000  # fast checks OMPL may spend planning (a quarter more for shortening)
DEFAULT_TURNING_RADIUS = 0.5  # [m] of a base that is not holonomic
DETOURS = (  # [m] (backing out of the start, arriving straight at the goal), tried in order
    (0.0, 0.3),
    (0.3, 0.0),
    (0.3, 0.3),
    (0.0, 0.6),
    (0.6, 0.6),
)
COARSE = 5  # a holonomic base's tree edges are checked at every 5th pose while planning
PLANNING_ATTEMPTS = 3  # seeds tried when the dense check refuses a coarsely planned path
# [m] OMPL first samples only within the start's and goal's box grown by this, then (if
# that finds nothing and the world reaches farther) everywhere: a flat's walls span many
# metres of open floor that would draw the trees away from a narrow way round furniture
NEAR_MARGIN = 2.0


@dataclass(frozen=True)
class BasePath:
    """Base poses ``(x, y, yaw)`` [m, m, rad] in map, straight between them, and their timing.

    ``planner`` says how it was found: ``straight``, ``reeds_shepp`` (the direct curve of a
    car), ``detour`` (backing out and arriving straight, :data:`DETOURS`), or the OMPL
    planner's name (``RRTConnect``, ``RRTConnect/ReedsShepp``). Headings are continuous
    along the path (not wrapped), as the trajectory's ``yaw`` joint is.
    """

    robot: str
    poses: tuple[tuple[float, float, float], ...]
    planner: str
    trajectory: JointTrajectory  # joints x, y, yaw; kind "base"
    fast_checks: int
    exact_checks: int


def plan_base_path(
    robot: RobotHandle,
    goal: Pose,
    *,
    seed: int = 0,
    budget: int = DEFAULT_BUDGET,
    holonomic: bool | None = None,
    turning_radius: float = DEFAULT_TURNING_RADIUS,
    period: float = 0.05,
    allowed_links: Collection[str] = (),
) -> BasePath:
    """A checked path of ``robot``'s base from where it stands to ``goal`` (map x, y, yaw).

    Args:
        robot: The robot (its handle); it is back at its start when this returns or raises.
        goal: Where the base should end; only x, y and the yaw count.
        seed: Seeds OMPL when the direct motion is blocked: same seed, same path.
        budget: Fast checks OMPL may spend (counted, never timed).
        holonomic: Whether the base drives sideways; None: the description says.
        turning_radius: [m] of a base that is not holonomic.
        period: Sampling period [s] of the trajectory.
        allowed_links: Robot links that may touch anything on the way (a hand holding a
            handle while the base follows a door's arc).

    The trajectory stores the contacts the robot started with as allowances no deeper
    than they started (:meth:`BaseCollisionChecker.start_allowances`).

    Raises:
        NavigationPoseUnreachable: the robot would collide at ``goal`` (named).
        NavigationPathBlocked: no path within the budget; names the direct motion's first
            obstacle and how far along it is.
        MotionError: a non-finite goal or a non-positive budget or turning radius.
    """
    drive = robot.description.drive
    car = holonomic is False or (holonomic is None and drive != "holonomic")
    _check_request(goal, budget, turning_radius)
    radius = turning_radius if car else None
    allowed = frozenset(allowed_links)
    goal_checked = _refuse_blocked_goal(robot, goal, allowed)
    with BaseCollisionChecker.build(robot, goal.position[:2], allowed) as checker:
        start_yaw = yaw_of(checker.start)
        start = np.array([*checker.start.position[:2], start_yaw])
        end = np.array([goal.position[0], goal.position[1], yaw_of(goal)])
        end[2] = start_yaw + _wrap(end[2] - start_yaw)
        checker.anchors = (start, end)
        fits = not checker.fast_hits(end[None, :], boundary=False)[0]
        colliding = [] if fits or goal_checked else checker.blockers(end)
        if colliding:
            raise NavigationPoseUnreachable(
                f"{robot.name} at {_shown(end)} would collide with {colliding}",
                target=goal,
                colliding=colliding,
            )
        direct = motion_poses(checker, start, end, radius)
        if goal_checked and not car:  # the straight way ends where the goal was checked
            direct[-1] = end
            checker.known_free(end)
        blocked = checker.first_blocked(direct)
        if blocked is None:
            waypoints = list(direct) if car else [start, end]
            planner = "reeds_shepp" if car else "straight"
        else:
            found = None if car else _detour(checker, start, end)
            planner = "detour"
            if found is None:
                found = _planned(checker, start, end, radius, seed, budget)
                planner = "RRTConnect/ReedsShepp" if car else "RRTConnect"
            if found is None:
                pairs = checker.blocking_pairs(direct[blocked])
                names = sorted({other for _, other in pairs})
                fraction = blocked / max(len(direct) - 1, 1)
                raise NavigationPathBlocked(
                    f"no path of {robot.name} to {_shown(end)} within {budget} checks; the "
                    f"direct way runs into {names} {fraction:.0%} of the way",
                    target=goal,
                    colliding=names,
                    robot_links=_own_links(robot.name, pairs),
                    path_fraction=fraction,
                )
            waypoints = found
        poses = tuple((float(p[0]), float(p[1]), float(p[2])) for p in waypoints)
        limits = joint_limits(robot.description, BASE_JOINTS)
        if car:  # on its curves, resting where the curvature changes
            trajectory = time_car_path(robot.name, poses, limits, period=period)
        else:
            trajectory = time_parameterize(
                robot.name, BASE_JOINTS, poses, limits, kind="base", period=period
            )
        trajectory = replace(trajectory, allowed_contacts=checker.start_allowances())
        return BasePath(
            robot.name, poses, planner, trajectory, checker.fast_checks, checker.exact_checks
        )


def _refuse_blocked_goal(robot: RobotHandle, goal: Pose, allowed: frozenset[str]) -> bool:
    """Raise before any grid is built when the robot plainly collides at ``goal``; a goal
    within :data:`ESCAPE` of the start is left to the checker (start contacts count there).
    Whether the goal was checked (and is free), so the checker need not ask again."""
    world = robot.world
    here = world.pose(robot.name)
    end = np.array([goal.position[0], goal.position[1], yaw_of(goal)])
    if np.hypot(end[0] - here.position[0], end[1] - here.position[1]) <= ESCAPE:
        return False
    pairs = blocking_pairs_at(robot, end, allowed)
    if pairs:
        colliding = sorted({other for _, other in pairs})
        raise NavigationPoseUnreachable(
            f"{robot.name} at {_shown(end)} would collide with {colliding}",
            target=goal,
            colliding=colliding,
            robot_links=_own_links(robot.name, pairs),
        )
    return True


def _own_links(robot_name: str, pairs: Collection[tuple[str, str]]) -> list[str]:
    """The robot's own links among the ``(body/link, other)`` pairs (what it carries left
    out): which part of it met something, for a plan to judge what would clear it."""
    own = f"{robot_name}/"
    return sorted({p.removeprefix(own) for p, _ in pairs if p.startswith(own)})


def _detour(
    checker: BaseCollisionChecker, start: np.ndarray, end: np.ndarray
) -> list[np.ndarray] | None:
    """The first of :data:`DETOURS` whose straight pieces are free, densely checked, or
    None. Each costs one dense check, a fraction of planning; deterministic."""
    for back, ahead in DETOURS:
        leave = start - back * np.array([np.cos(start[2]), np.sin(start[2]), 0.0])
        arrive = end - ahead * np.array([np.cos(end[2]), np.sin(end[2]), 0.0])
        points = [start, *(p for p, d in ((leave, back), (arrive, ahead)) if d > 0.0), end]
        if _dense_free(checker, points):
            return points
    return None


def _planned(
    checker: BaseCollisionChecker,
    start: np.ndarray,
    end: np.ndarray,
    radius: float | None,
    seed: int,
    budget: int,
) -> list[np.ndarray] | None:
    """A planned path that passes the dense check, or None. A holonomic base's tree edges
    are checked :data:`COARSE` times coarser while planning, then the path densely, with
    the next seed if that fails (a car's curves are checked densely from the start).
    Each of :func:`_areas` gets the whole budget."""
    coarse = 1 if radius is not None else COARSE
    for area in _areas(checker, start, end):
        for attempt in range(PLANNING_ATTEMPTS):
            found = planned_waypoints(
                checker, start, end, turning_radius=radius, seed=seed + attempt,
                budget=budget, coarse=coarse, area=area,
            )  # fmt: skip
            if found is None:
                break
            if coarse == 1 or _dense_free(checker, found):
                return found
    return None


def _areas(checker: BaseCollisionChecker, start: np.ndarray, end: np.ndarray) -> list[Area]:
    """Where OMPL samples, in turn: near the start and goal (:data:`NEAR_MARGIN`), then
    the checker's whole area, if that is larger and the move is longer than the margin.
    A shorter move that finds no way within its near box (a detour up to the margin
    beyond either end) finds none farther out either: a robot wedged where it stands (its
    hand in an open drawer) spent the whole budget twice on each parking back-off."""
    (x0, y0), (x1, y1) = checker.bounds
    low = (
        max(x0, min(start[0], end[0]) - NEAR_MARGIN),
        max(y0, min(start[1], end[1]) - NEAR_MARGIN),
    )
    high = (
        min(x1, max(start[0], end[0]) + NEAR_MARGIN),
        min(y1, max(start[1], end[1]) + NEAR_MARGIN),
    )
    near = ((float(low[0]), float(low[1])), (float(high[0]), float(high[1])))
    short = float(np.hypot(end[0] - start[0], end[1] - start[1])) <= NEAR_MARGIN
    return [near] if near == checker.bounds or short else [near, checker.bounds]


def _dense_free(checker: BaseCollisionChecker, waypoints: list[np.ndarray]) -> bool:
    """Whether the path is free, densely and straight between its waypoints."""
    return all(
        checker.first_blocked(motion_poses(checker, a, b, None)) is None
        for a, b in zip(waypoints[:-1], waypoints[1:], strict=True)
    )


def _wrap(angle: float) -> float:
    return float((angle + np.pi) % (2.0 * np.pi) - np.pi)


def _check_request(goal: Pose, budget: int, turning_radius: float) -> None:
    if not all(np.isfinite(goal.position)) or not all(np.isfinite(goal.orientation)):
        raise MotionInputError(f"base goal {goal} is not finite; give a pose in map")
    if budget <= 0:
        raise MotionError(f"planning budget must be a positive number of checks, got {budget}")
    if not turning_radius > 0.0:
        raise MotionError(f"turning radius must be positive [m], got {turning_radius}")


def _shown(pose: np.ndarray) -> str:
    return "({:.3f}, {:.3f}, {:.3f})".format(*(float(v) for v in pose))
