"""Motions over ROS are whole timed trajectories, planned round what the given world holds.

The driver node logs every goal it receives (``goal_log``); the plan side reports each
trajectory it sent to the motion layer's listeners. The two must agree point by point.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import (
    ManipulationPathBlocked,
    NavigationPathBlocked,
    ProcessModuleInputError,
    TorsoPathBlocked,
)
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.ros import Roscore, ros_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped
from robocram.world import World
from tests.ros.driver_pool import DriverPool

RIGHT_ARM = "/r_arm_controller/follow_joint_trajectory"
TORSO = "/torso_controller/follow_joint_trajectory"
HEAD = "/head_traj_controller/follow_joint_trajectory"
SAME = 1e-9  # [rad | s] what crosses ROS unchanged (float64; times to the nanosecond)
SWEEP = {"r_shoulder_pan_joint": -1.2}  # the stretched right arm swings to the right
INTO_SHELF = {"r_shoulder_pan_joint": -0.6}  # halfway: the forearm is in the shelf
BENT = 0.1  # [rad] a planned path leaves the straight segment by more than this
# the straight elbow and wrist of _right_arm lie beyond the PR2's soft limits (its URDF's
# safety_controller): they are sent as these
SOFTENED = {"r_elbow_flex_joint": -0.15, "r_wrist_flex_joint": -0.1}


def _world_with_shelf() -> World:
    """The driver's tabletop scene plus a shelf on the table in the forearm's sweep."""
    world = tabletop_scene("pr2").world
    top = world.aabb("table")[1][2]
    world.add_box("shelf", (0.1, 0.1, 0.3), Pose((0.52, -0.56, top + 0.15)))
    return world


def _seconds(duration: dict[str, int]) -> float:
    return duration["secs"] + duration["nsecs"] * 1e-9


def _right_arm(values: dict[str, float]) -> dict[str, float]:
    joints = [
        "r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
        "r_elbow_flex_joint", "r_forearm_roll_joint", "r_wrist_flex_joint", "r_wrist_roll_joint",
    ]  # fmt: skip
    return {j: values.get(j, 0.0) for j in joints}  # the others at 0: stretched forward


def _assert_same(received: dict[str, Any], sent: JointTrajectory) -> None:
    """The goal the driver got is ``sent``: names, points, times, velocities, accelerations."""
    trajectory = received["trajectory"]
    assert trajectory["joint_names"] == list(sent.joint_names)
    assert len(trajectory["points"]) == len(sent.points)
    for got, want in zip(trajectory["points"], sent.points, strict=True):
        assert _seconds(got["time_from_start"]) == pytest.approx(want.time_from_start, abs=SAME)
        for key in ("positions", "velocities", "accelerations"):
            assert got[key] == pytest.approx(list(getattr(want, key)), abs=SAME)


def _assert_tolerances(received: dict[str, Any], expected: dict[str, float]) -> None:
    tolerances = {t["name"]: t["position"] for t in received["goal_tolerance"]}
    assert tolerances == pytest.approx(expected, abs=SAME)
    assert _seconds(received["goal_time_tolerance"]) == pytest.approx(0.5, abs=SAME)


def _off_straight(trajectory: JointTrajectory) -> float:
    """How far [rad] the trajectory's points leave the straight segment start-end."""
    points = trajectory.positions()
    start, end = points[0], points[-1]
    direction = (end - start) / np.linalg.norm(end - start)
    offsets = (points - start) - np.outer((points - start) @ direction, direction)
    return float(np.max(np.linalg.norm(offsets, axis=1)))


def test_a_path_round_a_shelf_is_sent_whole_timed_with_goal_tolerances(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    sent: list[JointTrajectory] = []
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=_world_with_shelf()) as run,
        trajectory_listener(sent.append),
    ):
        stretched = _right_arm({})  # the scene parks the arms: stretch the right one first
        perform(a.motion(type="moving-arm-joints", arm="right", configuration=stretched))
        perform(a.motion(type="moving-arm-joints", arm="right", configuration=_right_arm(SWEEP)))
        reached = run.environment.client.joint_states()
    _, goal = driver.received_goals(RIGHT_ARM)
    expected = _right_arm(SWEEP) | SOFTENED  # sent inside the PR2's soft limits
    _, trajectory = sent
    _assert_same(goal, trajectory)
    assert len(trajectory.points) > 2
    assert _off_straight(trajectory) > BENT  # round the shelf, not through it
    wrist_roll = {"r_wrist_roll_joint": 0.05}  # the PR2's facts; the others: 0.02 rad
    _assert_tolerances(goal, {j: 0.02 for j in trajectory.joint_names} | wrist_roll)
    for joint, value in expected.items():
        assert reached[joint] == pytest.approx(value, abs=1e-6)


def test_arm_joints_take_projection_collision_modes_and_refuse_an_unknown_one(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    sent: list[JointTrajectory] = []
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=tabletop_scene("pr2").world),
        trajectory_listener(sent.append),
    ):
        stretched = a.motion(
            type="moving-arm-joints", arm="right", configuration=_right_arm({}),
            collision_mode="allow_elbow",
        )  # fmt: skip
        with pytest.raises(ProcessModuleInputError, match="unknown collision mode 'allow_elbow'"):
            perform(stretched)
        assert not sent  # refused before anything was planned or sent
        perform(
            a.motion(
                type="moving-arm-joints",
                arm="right",
                configuration=_right_arm({}),
                collision_mode="allow_hand",
                touching="mug-1",
            )
        )
    (trajectory,) = sent
    (goal,) = driver.received_goals(RIGHT_ARM)
    _assert_same(goal, trajectory)
    assert {c.other for c in trajectory.allowed_contacts} == {"mug-1"}  # the hand bounded
    assert {c.depth for c in trajectory.allowed_contacts} == {HAND_CONTACT_DEPTH}


def test_without_a_world_goals_are_straight_timed_trajectories(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    sent: list[JointTrajectory] = []
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri),
        trajectory_listener(sent.append),
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.2))
        perform(a.motion(type="moving-arm-joints", arm="right", configuration=_right_arm(SWEEP)))
    torso, arm = sent
    (torso_goal,) = driver.received_goals(TORSO)
    (arm_goal,) = driver.received_goals(RIGHT_ARM)
    _assert_same(torso_goal, torso)
    _assert_same(arm_goal, arm)
    assert torso.joint_names == ("torso_lift_joint",)
    assert torso.end["torso_lift_joint"] == pytest.approx(0.2, abs=SAME)
    _assert_tolerances(torso_goal, {"torso_lift_joint": 0.005})
    for trajectory in (torso, arm):
        assert len(trajectory.points) > 2
        assert max(abs(v) for p in trajectory.points for v in p.velocities) > 0.0
    assert _off_straight(arm) < 1e-6  # straight through where the shelf would be


def test_a_blocked_arm_path_sends_nothing(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=_world_with_shelf()) as run,
    ):
        before = run.environment.client.joint_states()
        with pytest.raises(ManipulationPathBlocked) as failure:
            perform(
                a.motion(
                    type="moving-arm-joints", arm="right", configuration=_right_arm(INTO_SHELF)
                )
            )
        after = run.environment.client.joint_states()
    assert driver.received_goals() == []
    assert failure.value.arm == "right"
    assert "shelf" in str(failure.value)
    assert after == pytest.approx(before, abs=1e-9)


def test_a_base_goal_no_path_leads_to_in_the_world_is_not_sent(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    world = tabletop_scene("pr2").world
    x, y = -3.0, 2.0  # [m] the goal, walled in on all four sides
    for name, size, centre in (
        ("wall_n", (4.0, 0.1, 1.0), (x, y + 2.0)),
        ("wall_s", (4.0, 0.1, 1.0), (x, y - 2.0)),
        ("wall_e", (0.1, 4.0, 1.0), (x + 2.0, y)),
        ("wall_w", (0.1, 4.0, 1.0), (x - 2.0, y)),
    ):
        world.add_box(name, size, Pose((*centre, 0.5)))
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=world) as run,
        pytest.raises(NavigationPathBlocked) as failure,
    ):
        try:
            perform(a.motion(type="going", target=a.location(pose=Pose((x, y, 0.0)))))
        finally:
            base = run.environment.client.base_pose()
    assert driver.received_goals() == []
    assert "wall_e" in str(failure.value)
    assert base.distance_to(Pose()) < 1e-6


def test_the_pr2_lifts_and_looks_by_checked_trajectories_of_their_kinds(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    sent: list[JointTrajectory] = []
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=tabletop_scene("pr2").world) as run,
        trajectory_listener(sent.append),
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
        perform(a.motion(type="looking", target=PoseStamped("map", (1.0, -0.5, 0.6))))
        reached = run.environment.client.joint_states()
    torso, head = sent
    assert (torso.kind, head.kind) == ("torso", "head")
    (torso_goal,) = driver.received_goals(TORSO)
    (head_goal,) = driver.received_goals(HEAD)  # the trajectory controller's, not PointHead
    _assert_same(torso_goal, torso)
    _assert_same(head_goal, head)
    assert set(head.joint_names) == {"head_pan_joint", "head_tilt_joint"}
    assert len(head.points) > 2
    for joint, value in head.end.items():
        assert reached[joint] == pytest.approx(value, abs=0.02)  # the goal tolerance


def test_a_torso_blocked_by_a_board_in_the_world_sends_nothing(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    world = tabletop_scene("pr2").world
    top = max(world.contacts.link_aabb("pr2", link)[1][2] for link in world.link_names("pr2"))
    world.add_box("board", (0.8, 0.8, 0.02), Pose((0.0, 0.0, top + 0.06)))  # 5 cm above
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=world) as run,
        pytest.raises(TorsoPathBlocked, match="board") as failure,
    ):
        try:
            perform(a.motion(type="moving-torso", joint_angle=0.3))
        finally:
            reached = run.environment.client.joint_states()["torso_lift_joint"]
    assert driver.received_goals() == []
    assert any(other == "board" for _, other in failure.value.colliding_pairs or ())
    assert reached == pytest.approx(0.0, abs=1e-9)


def test_the_pr2_turns_its_head_to_a_configuration_by_a_checked_trajectory(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    sent: list[JointTrajectory] = []
    goal = {"head_pan_joint": 0.4, "head_tilt_joint": 0.3}
    with (
        drivers(goal_log=tmp_path / "goals.jsonl") as driver,
        ros_robot("pr2", roscore.uri, world=tabletop_scene("pr2").world) as run,
        trajectory_listener(sent.append),
    ):
        perform(a.motion(type="looking", configuration=goal))
        reached = run.environment.client.joint_states()
    (head,) = sent
    assert head.kind == "head"
    (head_goal,) = driver.received_goals(HEAD)
    _assert_same(head_goal, head)
    for joint, value in goal.items():
        assert reached[joint] == pytest.approx(value, abs=0.02)  # the goal tolerance
