"""A tool path the arm cannot follow alone is followed by base and arm in one trajectory.

The HSR's five-joint arm moves its hand in a plane through the base; a straight line of
the hand 12 cm sideways, its orientation kept, is beyond it (the arm alone reaches a few
per cent of it). Planned whole-body, base and arm move together and the hand stays on the
line: replayed with raw PyBullet (the base reset to each point's x, y, yaw, the joints
reset by their indices, between the points too), the tool frame is never more than 3 mm
off the line nor turned more than 0.03 rad, and the robot touches nothing but the floor.
The Stretch's base is differential: its whole-body steps only drive along its heading,
so at every trajectory point the base's velocity across its heading is zero.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.motion.errors import MotionInputError
from robocram.motion.tool_path import plan_tool_path
from robocram.motion.whole_body_tool_path import plan_whole_body_tool_path
from robocram.robots import load_description
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import RobotHandle

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
OFF_LINE = 0.003  # [m] the tool frame off the line at most (IK's 1 mm and the chords)
TURNED = 0.03  # [rad]


def _scene(robot: str) -> tuple[RobotHandle, str]:
    scene = tabletop_scene(robot if robot != "stretch" else load_description(STRETCH))
    world = scene.world
    for name in ("mug-1", "bottle-1"):
        world.remove(name)
    handle = RobotHandle.of(world, scene.robot)
    return handle, next(iter(handle.description.arms))


def _sideways_line(handle: RobotHandle, arm: str, shift: tuple[float, float, float]) -> list[Pose]:
    """The tool frame's pose now (root link), moved by ``shift`` in 1 cm steps."""
    world = handle.world
    frame = handle.description.arms[arm].tool_frame
    tcp = world.pose(handle.name).inverse() * world.link_pose(handle.name, frame)
    (x, y, z), (dx, dy, dz), n = tcp.position, shift, 12
    return [
        Pose((x + dx * k / n, y + dy * k / n, z + dz * k / n), tcp.orientation)
        for k in range(1, n + 1)
    ]


def _raw_put(handle: RobotHandle, names: tuple[str, ...], q: np.ndarray, height: float) -> None:
    cid, body = handle.world.physics.client(), handle.body.body_id
    values = dict(zip(names, q.tolist(), strict=True))
    yaw = values.pop("yaw")
    pybullet.resetBasePositionAndOrientation(
        body, (values.pop("x"), values.pop("y"), height),
        (0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)), physicsClientId=cid,
    )  # fmt: skip
    index = {
        pybullet.getJointInfo(body, j, physicsClientId=cid)[1].decode(): j
        for j in range(pybullet.getNumJoints(body, physicsClientId=cid))
    }
    for name, value in values.items():
        pybullet.resetJointState(body, index[name], value, physicsClientId=cid)


def _raw_link(handle: RobotHandle, link: str) -> tuple[np.ndarray, np.ndarray]:
    cid, body = handle.world.physics.client(), handle.body.body_id
    for j in range(pybullet.getNumJoints(body, physicsClientId=cid)):
        if pybullet.getJointInfo(body, j, physicsClientId=cid)[12].decode() == link:
            state = pybullet.getLinkState(
                body, j, computeForwardKinematics=True, physicsClientId=cid
            )
            return np.array(state[4]), np.array(state[5])
    raise AssertionError(f"no link {link}")


def test_the_hsr_keeps_its_hand_on_a_sideways_line_moving_base_and_arm() -> None:
    handle, arm = _scene("hsrb")
    world = handle.world
    line = _sideways_line(handle, arm, (0.0, 0.12, 0.0))
    alone = plan_tool_path(handle, arm, line)
    assert alone.fraction < 0.5  # the arm alone leaves the line early
    planned = plan_whole_body_tool_path(handle, arm, line)
    assert planned.fraction == 1.0, planned.stopped_by
    trajectory = planned.motion.trajectory
    assert trajectory.joint_names[:3] == ("x", "y", "yaw")
    base = world.pose(handle.name)
    start = world.link_pose(handle.name, handle.description.arms[arm].tool_frame)
    goal = base * line[-1]
    a, b = np.array(start.position), np.array(goal.position)
    frame = handle.description.arms[arm].tool_frame
    height, cid = base.position[2], world.physics.client()
    points = np.array([p.positions for p in trajectory.points])
    for p, q in zip(points, points[1:], strict=False):
        for s in (0.0, 0.5):
            _raw_put(handle, trajectory.joint_names, p + (q - p) * s, height)
            position, orientation = _raw_link(handle, frame)
            t = np.clip(np.dot(position - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0)
            assert np.linalg.norm(position - (a + t * (b - a))) < OFF_LINE
            dot = abs(float(np.dot(orientation, np.array(start.orientation))))
            assert 2 * math.acos(min(dot, 1.0)) < TURNED
            touching = {
                pybullet.getBodyInfo(c[2], physicsClientId=cid)[1].decode()
                for c in pybullet.getContactPoints(bodyA=handle.body.body_id, physicsClientId=cid)
                if c[8] < -0.001
            }
            assert touching <= {"floor", "plane"}, touching
    moved = np.ptp(points[:, :2], axis=0)
    assert max(moved) > 0.05  # the base really went along


def test_the_stretch_drives_only_along_its_heading_in_whole_body_steps() -> None:
    handle, arm = _scene("stretch")
    line = _sideways_line(handle, arm, (0.1, 0.0, 0.0))
    planned = plan_whole_body_tool_path(handle, arm, line)
    assert planned.fraction == 1.0, planned.stopped_by
    trajectory = planned.motion.trajectory
    points = np.array([p.positions for p in trajectory.points])
    speeds = np.array([p.velocities for p in trajectory.points])
    across = -np.sin(points[:, 2]) * speeds[:, 0] + np.cos(points[:, 2]) * speeds[:, 1]
    assert np.abs(across).max() < 1e-9
    assert np.ptp(points[:, 2]) < 1e-9  # it never turns while it drives
    assert np.ptp(points[:, 0]) + np.ptp(points[:, 1]) > 0.02  # it drove


def test_an_empty_whole_body_path_is_refused_naming_the_arm() -> None:
    handle, arm = _scene("hsrb")
    with pytest.raises(MotionInputError, match=f"{arm} arm needs at least one pose"):
        plan_whole_body_tool_path(handle, arm, [])
