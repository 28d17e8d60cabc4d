"""Base paths in the kitchen: straight when clear, around a box, never through a drawer."""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence

import numpy as np
import pytest

from robocram.execution.failures import NavigationPathBlocked, NavigationPoseUnreachable
from robocram.motion.base_path import BasePath, plan_base_path
from robocram.motion.planar_motion import straight_poses
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World

DRAWER = "drawer_unit_drawer_3"
FAST_CLEARANCE = 0.05  # [m] the fast check's 2 cm squares on 1 cm cells flag nearer poses


def _pose(x: float, y: float, yaw: float) -> Pose:
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))


@pytest.fixture
def world(kitchen: World) -> Iterator[World]:
    with kitchen.snapshots.stored_state():
        yield kitchen


def _exactly_free(world: World, path: BasePath) -> list[tuple[float, float, float]]:
    """Poses 1 cm apart along the path where the exact PyBullet check finds a collision."""
    return _collisions_along(world, path.poses)


def _collisions_along(
    world: World, poses: Sequence[tuple[float, float, float]], within: float = 0.0
) -> list[tuple[float, float, float]]:
    """Poses 1 cm apart along the polyline ``poses`` where PyBullet finds a collision (or,
    ``within`` > 0 [m], something that near)."""
    start = world.pose("pr2")
    floors = [o.name for o in world.objects("floor")]
    bad = []
    try:
        for a, b in zip(poses[:-1], poses[1:], strict=True):
            for x, y, yaw in straight_poses(np.array(a), np.array(b), 1.0):
                world.set_pose("pr2", _pose(x, y, yaw))
                near = within > 0.0 and world.contacts.link_distances("pr2", floors, within)
                if near or world.contacts.collisions("pr2", ignore=floors):
                    bad.append((x, y, yaw))
    finally:
        world.set_pose("pr2", start)
    return bad


def test_a_clear_drive_is_one_straight_segment(world: World) -> None:
    start = world.pose("pr2")
    path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(0.3, 0.1, 0.0))
    assert path.planner == "straight" and len(path.poses) == 2
    assert path.poses[0] == pytest.approx((-0.8, 0.2, math.pi / 2))
    assert path.poses[1] == pytest.approx((0.3, 0.1, 0.0))
    assert path.trajectory.joint_names == ("x", "y", "yaw") and path.trajectory.kind == "base"
    assert path.trajectory.end == pytest.approx({"x": 0.3, "y": 0.1, "yaw": 0.0}, abs=1e-9)
    assert path.fast_checks > 100 and path.exact_checks == 0
    assert world.pose("pr2") == start


def test_a_box_in_the_way_is_driven_around(world: World) -> None:
    world.add_box("crate", (0.5, 0.5, 0.6), (-0.2, 0.2, 0.3))
    world.set_pose("pr2", _pose(-1.2, 0.2, 0.0))
    goal = _pose(0.9, 0.2, 0.0)
    path = plan_base_path(RobotHandle.of(world, "pr2"), goal, seed=3)
    assert path.planner == "RRTConnect" and len(path.poses) >= 3
    assert path.poses[-1][:2] == pytest.approx((0.9, 0.2))
    assert _exactly_free(world, path) == []
    again = plan_base_path(RobotHandle.of(world, "pr2"), goal, seed=3)
    assert again.poses == path.poses and again.fast_checks == path.fast_checks


def test_no_waypoint_of_a_planned_drive_can_be_dropped(world: World) -> None:
    """The planned path is simplified until every inner waypoint is needed: without any
    of them, the straight drive between its neighbours comes within the fast check's few
    centimetres of the crate (judged by PyBullet, every 1 cm; away from the start and goal
    a planned path keeps that clearance), and it is hardly longer than the way round."""
    world.add_box("crate", (0.5, 0.5, 0.6), (-0.2, 0.2, 0.3))
    world.set_pose("pr2", _pose(-1.2, 0.2, 0.0))
    path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(0.9, 0.2, 0.0), seed=3)
    poses = list(path.poses)
    assert path.planner == "RRTConnect" and len(poses) >= 3
    assert _collisions_along(world, poses) == []
    for k in range(1, len(poses) - 1):
        assert _collisions_along(world, poses[:k] + poses[k + 1 :], FAST_CLEARANCE) != [], k
    xy = np.array(poses)[:, :2]
    length = float(np.linalg.norm(np.diff(xy, axis=0), axis=1).sum())
    assert 2.1 < length < 1.4 * 2.1  # 2.1 m straight through the crate


def test_a_crate_beside_the_way_is_passed_backing_out_and_arriving_straight(world: World) -> None:
    """The detour before planning: back out along the start heading, drive, arrive
    straight along the goal's; here only the 0.6 m one clears the crate."""
    world.set_pose("pr2", _pose(-1.0, 0.2, math.pi / 2))
    world.add_box("crate", (0.3, 0.3, 0.8), (-0.2, 0.2, 0.4))
    path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(0.6, 0.2, math.pi / 2))
    assert path.planner == "detour"
    expected = [(-1.0, 0.2), (-1.0, -0.4), (0.6, -0.4), (0.6, 0.2)]
    assert [p[:2] for p in path.poses] == [pytest.approx(xy) for xy in expected]
    assert all(p[2] == pytest.approx(math.pi / 2) for p in path.poses)
    assert _exactly_free(world, path) == []


def test_an_open_drawer_is_never_driven_through(world: World) -> None:
    world.set_pose("pr2", _pose(-2.5, 1.05, 0.0))
    goal = _pose(-0.5, 1.05, 0.0)
    assert (
        plan_base_path(RobotHandle.of(world, "pr2"), goal).planner == "straight"
    )  # drawer shut: clear
    world.set_joint_states("kitchen", {f"{DRAWER}_joint": 0.4})
    try:
        path = plan_base_path(RobotHandle.of(world, "pr2"), goal)
    except NavigationPathBlocked as blocked:
        assert f"kitchen/{DRAWER}" in (blocked.colliding or [])
        assert 0.2 < (blocked.path_fraction or 0.0) < 0.6
    else:
        assert path.planner == "RRTConnect"
        assert _exactly_free(world, path) == []


def test_a_path_blocked_within_the_budget_names_the_drawer(world: World) -> None:
    world.set_pose("pr2", _pose(-2.5, 1.05, 0.0))
    world.set_joint_states("kitchen", {f"{DRAWER}_joint": 0.4})
    with pytest.raises(NavigationPathBlocked) as raised:
        plan_base_path(RobotHandle.of(world, "pr2"), _pose(-0.5, 1.05, 0.0), budget=50)
    assert f"kitchen/{DRAWER}" in (raised.value.colliding or [])
    assert raised.value.path_fraction == pytest.approx(0.33, abs=0.1)


def test_a_goal_in_collision_is_unreachable(world: World) -> None:
    with pytest.raises(NavigationPoseUnreachable) as raised:
        plan_base_path(RobotHandle.of(world, "pr2"), _pose(-1.4, 1.9, math.pi / 2))
    assert not isinstance(raised.value, NavigationPathBlocked)
    assert any(name.startswith("kitchen/") for name in raised.value.colliding or [])


def test_a_car_follows_reeds_shepp_curves(world: World) -> None:
    radius = 0.5
    path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(0.4, -0.3, -math.pi / 2),
                          holonomic=False, turning_radius=radius)  # fmt: skip
    assert path.planner in ("reeds_shepp", "RRTConnect/ReedsShepp")
    poses = np.array(path.poses)
    step = np.diff(poses, axis=0)
    travel = np.hypot(step[:, 0], step[:, 1])
    heading = poses[:-1, 2] + 0.5 * step[:, 2]
    forward = np.cos(heading) * step[:, 0] + np.sin(heading) * step[:, 1]
    sideways = -np.sin(heading) * step[:, 0] + np.cos(heading) * step[:, 1]
    cusp = np.zeros(len(step), dtype=bool)  # where it reverses, a step's chord is short
    flips = np.nonzero(np.sign(forward[1:]) != np.sign(forward[:-1]))[0]
    cusp[flips] = cusp[flips + 1] = True
    assert np.all(np.abs(sideways[~cusp]) <= 1e-3 * travel[~cusp] + 1e-9)  # never sideways
    assert np.all(np.abs(step[~cusp, 2]) <= travel[~cusp] / radius * 1.01 + 1e-9)
    assert np.count_nonzero(np.abs(step[:, 2]) > 1e-9) > 10  # it does turn
    assert poses[-1, :2] == pytest.approx((0.4, -0.3), abs=1e-6)
    assert _exactly_free(world, path) == []


def test_a_goal_turned_half_round_is_planned_to_without_waiting() -> None:
    """Unwrapping a goal yaw of pi against a start yaw of -2.36 rounds to just below -pi,
    which wrapped once to +pi: OMPL refused that goal and waited out the budget's polls."""
    from robocram.motion.planar_motion import wrapped

    start_yaw = -2.36
    goal_yaw = start_yaw + wrapped(math.pi - start_yaw)
    assert goal_yaw < -math.pi  # the rounding this guards against
    assert -math.pi <= wrapped(goal_yaw) < math.pi
    assert wrapped(goal_yaw) == pytest.approx(-math.pi)


def test_a_way_round_far_beyond_the_start_and_goal_is_still_found() -> None:
    """OMPL samples near the start and goal first (NEAR_MARGIN); a wall whose only way
    round lies farther out is passed by planning in the whole area next."""
    from robocram.motion.base_path import NEAR_MARGIN

    with World() as world:
        world.bodies.add_floor()
        world.add_box("wall", (0.1, 8.6, 1.0), (1.0, 1.7, 0.5))  # y -2.6 .. 6.0
        world.add_box("marker", (0.2, 0.2, 0.2), (0.0, -6.0, 0.1))  # the area reaches y -6.1
        world.add_robot("pr2", _pose(-0.5, 0.0, 0.0))
        for arm in world.robot("pr2").description.arms.values():
            world.set_joint_states("pr2", dict(arm.parking))
        path = plan_base_path(RobotHandle.of(world, "pr2"), _pose(2.5, 0.0, 0.0), seed=1)
    assert path.planner == "RRTConnect"
    assert min(y for _, y, _ in path.poses) < -2.6 < -NEAR_MARGIN
    assert path.poses[-1][:2] == pytest.approx((2.5, 0.0))


def test_a_short_move_with_no_way_in_its_near_box_is_not_planned_again_everywhere(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A goal walled in all round, 1.7 m away (within NEAR_MARGIN): no way exists. The
    planner is asked once, near the start and goal, not a second time over the whole area
    (a robot wedged where it stands spent the budget twice on each parking back-off)."""
    import robocram.motion.base_path as base_path

    areas: list[tuple[tuple[float, float], tuple[float, float]]] = []
    plan = base_path.planned_waypoints

    def counted(*args: object, **kwargs: object) -> object:
        areas.append(kwargs["area"])  # type: ignore[arg-type]
        return plan(*args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(base_path, "planned_waypoints", counted)
    with World() as world:
        world.bodies.add_floor()
        for name, size, at in (
            ("west", (0.1, 1.9, 1.0), (0.0, 0.0, 0.5)),
            ("east", (0.1, 1.9, 1.0), (1.8, 0.0, 0.5)),
            ("north", (1.9, 0.1, 1.0), (0.9, 0.9, 0.5)),
            ("south", (1.9, 0.1, 1.0), (0.9, -0.9, 0.5)),
        ):
            world.add_box(name, size, at)
        world.add_box("marker", (0.2, 0.2, 0.2), (0.0, -6.0, 0.1))  # the area reaches y -6.1
        world.add_robot("pr2", _pose(-0.8, 0.0, 0.0))
        for arm in world.robot("pr2").description.arms.values():
            world.set_joint_states("pr2", dict(arm.parking))
        with pytest.raises(NavigationPathBlocked) as raised:
            plan_base_path(RobotHandle.of(world, "pr2"), _pose(0.9, 0.0, 0.0), budget=500)
    assert "west" in (raised.value.colliding or [])
    assert len(areas) == 1
    low, _ = areas[0]
    assert low[1] > -6.0  # the near box, not the whole area down to the marker
