"""A trajectory followed after the world changed is checked again (issue 42, item 4).

A body added (or moved) into a path after it was planned stops the robot before the
first point where it would touch the body, with the typed failure naming it; judged by
PyBullet's own closest points between the robot and the body where it stopped. A change
away from the path, or none, lets the robot follow to the end as before.
"""

from __future__ import annotations

import numpy as np
import pybullet
import pytest

from robocram.execution.failures import (
    ManipulationPathBlocked,
    NavigationPathBlocked,
    TorsoPathBlocked,
)
from robocram.motion import plan_arm_motion, plan_base_path
from robocram.projection import navigation
from robocram.projection.path_watch import planned_against
from robocram.projection.projected_robot import ProjectedRobot
from robocram.projection.trajectory_follower import follow
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import World

ARM = {"r_shoulder_pan_joint": -1.2}  # the right arm swings from its side to the front


@pytest.fixture
def robot() -> ProjectedRobot:
    world = kitchen_scene("pr2").world
    yield ProjectedRobot.of(world, "pr2")
    world.close()


def _gap(world: World, a: str, b: str) -> float:
    """The least distance [m] between two bodies, from PyBullet itself."""
    cid = world.physics.client()
    points = pybullet.getClosestPoints(
        world.object(a).body_id, world.object(b).body_id, 1.0, physicsClientId=cid
    )
    return min((p[8] for p in points), default=1.0)


def _drive(robot: ProjectedRobot) -> tuple[object, object]:
    """A planned 1 m drive ahead (+x in map) and what it was checked against."""
    start = robot.world.pose("pr2")
    checked = planned_against(robot)
    goal = Pose((start.position[0] + 1.0, start.position[1], 0.0), start.orientation)
    return plan_base_path(robot.handle, goal).trajectory, checked


def test_a_body_added_after_planning_stops_the_drive_before_it(robot: ProjectedRobot) -> None:
    world = robot.world
    trajectory, checked = _drive(robot)
    y = world.pose("pr2").position[1]
    world.add_box("crate", (0.2, 0.2, 0.6), Pose((0.0, y, 0.3)))
    with pytest.raises(NavigationPathBlocked, match="'crate'") as caught:
        follow(robot, trajectory, checked)
    assert caught.value.colliding == ["crate"]
    assert 0.0 < caught.value.path_fraction < 1.0
    stopped = world.pose("pr2").position
    assert _gap(world, "pr2", "crate") > 0.0  # it stopped short of the crate
    assert stopped[0] > trajectory.points[0].positions[0] + 0.05  # ... after driving on
    reached = [tuple(p.positions[:2]) for p in trajectory.points]
    assert any(np.allclose(stopped[:2], xy, atol=1e-9) for xy in reached)  # at a point


def test_a_body_moved_into_the_arm_path_stops_the_arm(robot: ProjectedRobot) -> None:
    world = robot.world
    checked = planned_against(robot)
    motion = plan_arm_motion(robot.handle, ARM)
    start = world.joint_states("pr2")
    world.set_joint_states("pr2", ARM)  # where the forearm ends up, to put a box there
    wrist = world.link_pose("pr2", "r_wrist_flex_link").position
    world.set_joint_states("pr2", {j: start[j] for j in ARM})
    world.set_pose("milk-1", Pose(wrist))  # moved into the arm's way after planning
    with pytest.raises(ManipulationPathBlocked, match="'milk-1'") as caught:
        follow(robot, motion.trajectory, checked)
    assert caught.value.colliding_pairs[0][1] == "milk-1"
    assert _gap(world, "pr2", "milk-1") > 0.0
    low, high = sorted((start["r_shoulder_pan_joint"], ARM["r_shoulder_pan_joint"]))
    moved = world.joint_states("pr2")["r_shoulder_pan_joint"]
    assert low <= moved <= high and moved != pytest.approx(ARM["r_shoulder_pan_joint"], abs=1e-3)


def test_a_change_away_from_the_path_lets_the_robot_follow_to_the_end(
    robot: ProjectedRobot,
) -> None:
    world = robot.world
    trajectory, checked = _drive(robot)
    world.add_box("crate", (0.2, 0.2, 0.2), Pose((2.5, -2.0, 0.1)))  # far off
    follow(robot, trajectory, checked)
    end = trajectory.points[-1].positions
    assert world.pose("pr2").position[:2] == pytest.approx(end[:2], abs=1e-9)


def test_nothing_changed_costs_no_check(robot: ProjectedRobot) -> None:
    world = robot.world
    trajectory, _ = _drive(robot)
    before = world.versions.tick
    follow(robot, trajectory)  # checked against the world as it stands
    end = trajectory.points[-1].positions
    assert world.pose("pr2").position[:2] == pytest.approx(end[:2], abs=1e-9)
    assert world.versions.tick == before + 1  # the one write: the robot put at the end


def test_a_board_put_over_the_head_after_planning_stops_the_torso_as_a_torso_failure(
    robot: ProjectedRobot,
) -> None:
    world = robot.world
    checked = planned_against(robot)
    start = world.joint_states("pr2")["torso_lift_joint"]
    goal = start + 0.15  # [m] up
    lift = plan_arm_motion(robot.handle, {"torso_lift_joint": goal}, kind="torso")
    x, y, _ = world.link_pose("pr2", "head_tilt_link").position
    top = world.aabb("pr2")[1][2]
    world.add_box("board", (0.6, 0.6, 0.02), Pose((x, y, top + 0.08)))  # rising into it
    with pytest.raises(TorsoPathBlocked, match="'board'") as caught:
        follow(robot, lift.trajectory, checked)
    assert caught.value.colliding_pairs[0][1] == "board"
    assert _gap(world, "pr2", "board") > 0.0  # stopped short of it
    assert start < world.joint_states("pr2")["torso_lift_joint"] < goal


def test_a_drive_is_watched_from_when_it_was_planned(
    robot: ProjectedRobot, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A body added while the planner worked (as another task may do) stops the drive: the
    mark is taken before planning, not when following starts."""
    world = robot.world
    start = world.pose("pr2")
    goal = Pose((start.position[0] + 1.0, start.position[1], 0.0), start.orientation)

    def planned_then_crate_added(*args: object, **kwargs: object) -> object:
        path = plan_base_path(*args, **kwargs)  # the real planner, on the world as it was
        y = start.position[1]
        world.add_box("crate", (0.2, 0.2, 0.6), Pose((start.position[0] + 0.7, y, 0.3)))
        return path

    monkeypatch.setattr(navigation, "plan_base_path", planned_then_crate_added)
    with pytest.raises(NavigationPathBlocked, match="'crate'"):
        navigation.drive(robot, goal)
    assert _gap(world, "pr2", "crate") > 0.0  # it stopped short of the crate
    assert world.pose("pr2").position[0] > start.position[0] + 0.05  # after driving on
