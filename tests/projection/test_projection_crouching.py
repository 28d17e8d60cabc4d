"""TALOS crouches as a checked, timed motion: its body down and up, its soles kept.

Why: TALOS holds the bowl drawer's handle and lifts the bowl out of the open drawer only
with its body 0.20-0.25 m lower (issue 37). The crouch is one trajectory of the base's
height ``z`` and the leg joints. Judged on raw PyBullet: the trajectory's points are put
on the robot's body by PyBullet's own calls and its feet read by PyBullet's forward
kinematics, the velocity limits read from the URDF as PyBullet loaded it; a recorded
crouch is audited (no collision, no limit exceeded) and replayed.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pybullet
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import TorsoPathBlocked
from robocram.motion import JointTrajectory, joint_limits, trajectory_listener
from robocram.projection import simulated_robot
from robocram.projection.crouching import crouch, crouch_depth, crouch_feet
from robocram.projection.projected_robot import ProjectedRobot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.run_replay import replay_frames
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import World
from tests.bullet_links import link_frame, link_indices

TALOS = Path(__file__).parents[2] / "examples" / "robots" / "talos.py"
DEPTH = 0.25  # [m] the crouch (TALOS opens, fetches from and closes the bowl's drawer so)


@pytest.fixture(scope="module")
def talos() -> Iterator[tuple[World, ProjectedRobot]]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(TALOS))
    yield scene.world, ProjectedRobot(scene.world, scene.robot)
    scene.world.close()


def _raw_put(
    body: int, client: int, names: tuple[str, ...], values: list[float], offset: float
) -> None:
    """Put ``values`` of ``names`` (``z`` first: the base's height; PyBullet's base frame
    is its inertial one, ``offset`` [m] higher) on PyBullet's body."""
    position, turn = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)
    pybullet.resetBasePositionAndOrientation(
        body, (position[0], position[1], values[0] + offset), turn, physicsClientId=client
    )
    index = link_indices(body, client)
    joints = {
        pybullet.getJointInfo(body, i, physicsClientId=client)[1].decode(): i
        for i in index.values()
    }
    for name, value in zip(names[1:], values[1:], strict=True):
        pybullet.resetJointState(body, joints[name], value, physicsClientId=client)


def test_talos_crouches_and_stands_along_timed_ways_its_soles_kept(
    talos: tuple[World, ProjectedRobot],
) -> None:
    world, robot = talos
    client, body = world.physics.client(), world.object(robot.name).body_id
    feet = crouch_feet(robot.description)
    assert sorted(feet) == ["left_sole_link", "right_sole_link"]
    standing = world.joint_states(robot.name)
    start = world.pose(robot.name)
    soles = {f: link_frame(body, client, f) for f in feet}
    moved: list[JointTrajectory] = []
    high = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0]
    offset = high[2] - start.position[2]  # [m] PyBullet's inertial base frame over the link's
    try:
        with trajectory_listener(moved.append):
            assert crouch(robot, DEPTH) == pytest.approx(DEPTH, abs=1e-6)
            root = pybullet.getBasePositionAndOrientation(body, physicsClientId=client)[0]
            assert np.allclose(np.subtract(root, high), (0.0, 0.0, -DEPTH), atol=1e-6)
            assert crouch(robot, 0.0) == pytest.approx(0.0, abs=1e-6)
        assert [t.kind for t in moved] == ["crouch", "crouch"]
        velocity = {
            info[1].decode(): info[11]
            for info in (
                pybullet.getJointInfo(body, i, physicsClientId=client)
                for i in range(pybullet.getNumJoints(body, physicsClientId=client))
            )
        } | {"z": 0.5}  # [rad/s | m/s] the URDF's; the base's height: BASE_LIMITS
        for trajectory in moved:
            names = trajectory.joint_names
            assert names[0] == "z" and len(names) == 13  # the height and 12 leg joints
            positions, times = trajectory.positions(), trajectory.times()
            # no teleport: consecutive samples within the velocity limits
            rates = np.abs(np.diff(positions, axis=0)) / np.diff(times)[:, None]
            bound = np.array([velocity[n] for n in names])
            assert (rates <= bound * 1.001).all()
            limits = joint_limits(robot.description, names)
            speeds = np.diff(positions, axis=0) / np.diff(times)[:, None]
            middles = 0.5 * (times[1:] + times[:-1])  # each speed's time
            accelerations = np.abs(np.diff(speeds, axis=0)) / np.diff(middles)[:, None]
            assert (accelerations <= np.array([x.acceleration for x in limits]) * 1.05).all()
            after = np.vstack([positions[1:], positions[-1:]])
            for values in (*positions, *(0.5 * (positions + after))):  # points, and between
                _raw_put(body, client, names, values.tolist(), offset)
                for foot, (at, _) in soles.items():
                    now, _ = link_frame(body, client, foot)
                    assert np.linalg.norm(now - at) < 1e-3  # [m] the sole kept
        assert moved[0].end["z"] == pytest.approx(start.position[2] - DEPTH, abs=1e-9)
        assert moved[1].end["z"] == pytest.approx(start.position[2], abs=1e-9)
        assert moved[0].duration < 10.0  # [s]
    finally:
        world.set_pose(robot.name, start)
        world.set_joint_states(robot.name, standing)


def test_a_crouch_into_a_box_fails_before_anything_moves(
    talos: tuple[World, ProjectedRobot],
) -> None:
    """Bent, the knees come forward: a box just before them stops the crouch."""
    world, robot = talos
    client, body = world.physics.client(), world.object(robot.name).body_id
    start = world.pose(robot.name)
    knee, _ = link_frame(body, client, "leg_left_4_link")
    ahead = start.orientation
    forward = np.array(pybullet.getMatrixFromQuaternion(ahead)).reshape(3, 3)[:, 0]
    centre = knee + 0.2 * forward  # bent 0.25 m down, the knee comes 0.27 m forward
    box = world.add_box("knee_box", (0.05, 0.4, 0.3), Pose(tuple(centre.tolist())))
    try:
        with pytest.raises(TorsoPathBlocked, match="knee_box") as raised:
            crouch(robot, DEPTH)
        assert raised.value.path_fraction is not None and 0.0 < raised.value.path_fraction < 1.0
        assert world.pose(robot.name).position[2] == pytest.approx(start.position[2], abs=1e-9)
        assert link_frame(body, client, "leg_left_4_link")[0] == pytest.approx(knee, abs=1e-9)
        assert crouch_depth(robot) == pytest.approx(0.0, abs=1e-9)
    finally:
        world.remove(box.name)


def test_a_recorded_crouch_audits_clean_and_replays_the_body_down_and_up(
    tmp_path: Path,
) -> None:
    db_path = tmp_path / "runs.db"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scene = tabletop_scene(str(TALOS))
    robot = scene.robot
    z = scene.world.pose(robot).position[2]
    with trace_to(db_path, world=scene.world), simulated_robot(scene.world, robot):
        perform(a.motion(type="crouching", depth=DEPTH))
        perform(a.motion(type="crouching", depth=0.0))
    scene.world.close()
    with TraceDatabase(db_path, create=False) as db:
        report = audit_runs(db)
        assert report.clean, report.summary_lines()
        assert report.trajectories == 2 and report.configurations > 50
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            replay = tabletop_scene(str(TALOS))
        heights = [
            replay.world.pose(replay.robot).position[2]
            for frame in replay_frames(db, 1, replay.world)
            if frame.trajectory is not None
        ]
        replay.world.close()
    assert min(heights) == pytest.approx(z - DEPTH, abs=1e-6)
    assert heights[-1] == pytest.approx(z, abs=1e-6)
