"""A tool line of the parked PR2: the tool follows the straight line, between waypoints too.

The line is cut into steps of :data:`MAX_STEP`; between two waypoints the arm moves in
joint space, so the tool leaves the line a little. Sampled along every segment, it stays
within 1 mm of the line (IK's own position tolerance), and it ends at the target.
"""

from __future__ import annotations

import math

import numpy as np

from robocram.kinematics import forward_kinematics
from robocram.motion import plan_tool_line
from robocram.motion.cartesian_path import MAX_STEP
from robocram.tf import Pose
from robocram.world import RobotHandle, World

LINE_TOLERANCE = 0.001  # [m] IK's position tolerance


def _tool_in_base(world: World, values: dict[str, float]) -> np.ndarray:
    desc = world.robot("pr2").description
    return np.array(forward_kinematics(desc, values, desc.arms["right"].tool_frame).position)


def test_the_tool_stays_on_its_line_between_waypoints(kitchen: World) -> None:
    world = kitchen
    desc = world.robot("pr2").description
    before = world.joint_states("pr2")
    tool = world.pose("pr2").inverse() * world.link_pose("pr2", desc.arms["right"].tool_frame)
    length = 0.09  # [m] forward and down, as an approach (4.5 steps: 5)
    shift = np.array((0.072, 0.0, -0.054))
    target = Pose(tuple((np.array(tool.position) + shift).tolist()), tool.orientation)
    line = plan_tool_line(RobotHandle.of(world, "pr2"), "right", target)
    assert line.fraction == 1.0
    assert world.joint_states("pr2") == before  # planning moves nothing
    waypoints = [np.array(w) for w in line.path.waypoints]
    assert len(waypoints) == math.ceil(length / MAX_STEP) + 1
    held = {"torso_lift_joint": before["torso_lift_joint"]}
    start, direction = np.array(tool.position), shift / np.linalg.norm(shift)
    worst = 0.0
    for a, b in zip(waypoints, waypoints[1:], strict=False):
        for s in np.linspace(0.0, 1.0, 11):
            q = (a + (b - a) * s).tolist()
            offset = _tool_in_base(world, {**held, **dict(zip(line.path.joints, q, strict=True))})
            offset -= start
            worst = max(worst, float(np.linalg.norm(offset - direction * (offset @ direction))))
    assert worst < LINE_TOLERANCE
    end = {**held, **dict(zip(line.path.joints, waypoints[-1].tolist(), strict=True))}
    assert np.linalg.norm(_tool_in_base(world, end) - np.array(target.position)) < LINE_TOLERANCE
