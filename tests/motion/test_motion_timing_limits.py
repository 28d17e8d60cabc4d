"""Every kind of path keeps its joints' velocity, acceleration and jerk limits when timed.

Judged independently of the timing's own numbers (``timing_judge.py``): each motion is
timed twice, at the usual period (0.05 s) and every 2 ms (under 5 mm / 0.005 rad between
samples at these speeds). The usual points must be among the dense ones (the same
motion); the dense positions' finite differences must stay within the limits and imply
the stored velocities and accelerations; and the usual points alone, replayed by their
divided differences and by a controller's quintic interpolation, must too.

Covered: a PR2 tool line in the kitchen, an arm path of several waypoints, a holonomic
base path round a crate that turns, and a car's (``holonomic=False``) Reeds-Shepp path
with a cusp.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np
import pytest

from robocram.motion import (
    BASE_JOINTS,
    JointTrajectory,
    MotionSettings,
    joint_limits,
    plan_base_path,
    plan_tool_line,
    time_parameterize,
)
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle, World


@pytest.fixture
def world(kitchen: World) -> Iterator[World]:
    with kitchen.snapshots.stored_state():
        yield kitchen


def _pose(x: float, y: float, yaw: float) -> Pose:
    return Pose((x, y, 0.0), quat.from_euler(0.0, 0.0, yaw))


def test_a_pr2_tool_line_in_the_kitchen_keeps_its_limits(world: World, timing_judge: Any) -> None:
    desc = world.robot("pr2").description
    tool = world.pose("pr2").inverse() * world.link_pose("pr2", desc.arms["right"].tool_frame)
    shift = np.array((0.12, 0.0, -0.08))  # forward and down, as an approach: 8 waypoints
    target = Pose(tuple((np.array(tool.position) + shift).tolist()), tool.orientation)

    def line(period: float) -> JointTrajectory:
        settings = MotionSettings(period=period)
        motion = plan_tool_line(RobotHandle.of(world, "pr2"), "right", target, settings=settings)
        assert motion.fraction == 1.0 and len(motion.path.waypoints) >= 8
        return motion.trajectory

    coarse, dense = line(0.05), line(timing_judge.DENSE)
    assert coarse.kind == "cartesian"
    timing_judge.assert_keeps_limits(coarse, dense, joint_limits(desc, coarse.joint_names))


def test_an_arm_path_of_several_waypoints_keeps_its_limits(world: World, timing_judge: Any) -> None:
    """A lift, a crossing and a lowering (a detour's shape), then a gentle curve of 1 cm
    steps (a planner's dense corner)."""
    desc = world.robot("pr2").description
    joints = desc.arms["right"].joints
    limits = joint_limits(desc, joints)
    s = np.linspace(0.0, 0.3, 31)
    curve = np.stack(
        [-0.9 + s, 0.5 * s**2, -0.5 - 0.3 * s, -1.0 + 0.2 * s, 0.3 + 0 * s, -0.6 + 0.1 * s, s],
        axis=1,
    )
    path = np.vstack(
        [
            [[-1.0, 0.2, -0.5, -1.2, 0.3, -0.6, 0.0]],
            [[-1.0, -0.2, -0.5, -1.2, 0.3, -0.6, 0.0]],
            [[-0.9, -0.2, -0.5, -1.0, 0.3, -0.6, 0.0]],
            curve[1:],
        ]
    )
    coarse = time_parameterize("pr2", joints, path, limits)
    dense = time_parameterize("pr2", joints, path, limits, period=timing_judge.DENSE)
    timing_judge.assert_keeps_limits(coarse, dense, limits)


def _base(world: World, goal: Pose, **options: object) -> Callable[[float], JointTrajectory]:
    def timed(period: float) -> JointTrajectory:
        return plan_base_path(
            RobotHandle.of(world, "pr2"), goal, period=period, **options
        ).trajectory  # type: ignore[arg-type]

    return timed


def test_a_holonomic_base_path_round_a_crate_that_turns_keeps_its_limits(
    world: World, timing_judge: Any
) -> None:
    world.set_pose("pr2", _pose(-1.0, 0.2, math.pi / 2))
    world.add_box("crate", (0.3, 0.3, 0.8), (-0.2, 0.2, 0.4))
    try:
        goal = _pose(0.6, 0.2, math.pi / 2 + 0.8)
        path = plan_base_path(RobotHandle.of(world, "pr2"), goal)
        assert path.planner in ("detour", "RRTConnect") and len(path.poses) >= 3
        timed = _base(world, goal)
        coarse, dense = timed(0.05), timed(timing_judge.DENSE)
    finally:
        world.remove("crate")
    limits = joint_limits(world.robot("pr2").description, BASE_JOINTS)
    timing_judge.assert_keeps_limits(coarse, dense, limits)


def test_a_car_path_with_a_cusp_keeps_its_limits(world: World, timing_judge: Any) -> None:
    """Sideways by 0.3 m: a Reeds-Shepp path that reverses (a cusp) and changes curvature."""
    world.set_pose("pr2", _pose(-0.8, 0.2, math.pi / 2))
    goal = _pose(-0.5, 0.3, math.pi / 2)
    path = plan_base_path(RobotHandle.of(world, "pr2"), goal, holonomic=False)
    poses = np.array(path.poses)
    step = np.diff(poses, axis=0)
    forward = np.cos(poses[:-1, 2]) * step[:, 0] + np.sin(poses[:-1, 2]) * step[:, 1]
    assert np.any(forward > 1e-4) and np.any(forward < -1e-4)  # it reverses somewhere
    timed = _base(world, goal, holonomic=False)
    coarse, dense = timed(0.05), timed(timing_judge.DENSE)
    limits = joint_limits(world.robot("pr2").description, BASE_JOINTS)
    timing_judge.assert_keeps_limits(coarse, dense, limits)
    assert coarse.end == pytest.approx({"x": -0.5, "y": 0.3, "yaw": math.pi / 2}, abs=1e-6)
