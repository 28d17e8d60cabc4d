"""A driver's reset: the world back as the scene built it, the per-run settings taken, and
the reset lines on its standard input answered (in this process, no ROS master)."""

from __future__ import annotations

import io
import threading
from pathlib import Path

import genpy
import pybullet
import pytest

from robocram.robots import load_description
from robocram.ros.ros_config import install_ros_facts, read_ros_config
from robocram.ros_driver.driver_reset import DriverBusy, DriverSettings, serve_resets
from robocram.ros_driver.errors import DriverArgumentError
from robocram.ros_driver.projection_driver import ProjectionDriver
from robocram.ros_driver.robot_clock import RobotClock
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from robocram.world import World

SAME = 1e-9  # [m | rad] a reset world is the built one
Raw = dict[str, list[tuple[float, ...]]]


class Recorder:
    """A publisher keeping what it was given."""

    def __init__(self) -> None:
        self.sent: list[genpy.Message] = []

    def publish(self, message: genpy.Message) -> None:
        self.sent.append(message)


class StillClock(RobotClock):
    """The robot's clock, stopped at 1 s (no ROS time in this process)."""

    def now(self) -> genpy.Time:
        return genpy.Time(1)


def _driver() -> ProjectionDriver:
    scene = tabletop_scene("pr2")
    install_ros_facts(scene.world.kb, scene.robot, None)
    config = read_ros_config(scene.world.kb, load_description(scene.robot))
    driver = ProjectionDriver(scene.world, config)
    driver._publishers = {"tf": Recorder(), "joints": Recorder()}  # no environments here
    driver.clock = StillClock(0.0)
    return driver


def _raw(world: World) -> Raw:
    """Every body's base pose and joint positions, as PyBullet holds them."""
    client = world.physics.client()
    out: Raw = {}
    for obj in world.objects():
        rows: list[tuple[float, ...]] = []
        for body in obj.bodies:
            position, orientation = pybullet.getBasePositionAndOrientation(
                body, physicsClientId=client
            )
            count = pybullet.getNumJoints(body, physicsClientId=client)
            joints = [
                pybullet.getJointState(body, i, physicsClientId=client)[0] for i in range(count)
            ]
            rows.append((*position, *orientation, *joints))
        out[obj.name] = rows
    return out


def test_a_reset_puts_the_world_back_as_built_and_takes_the_settings(tmp_path: Path) -> None:
    driver = _driver()
    world, robot = driver.world, driver.robot.name
    hand = world.robot(robot).description.arms["right"].end_effector_link
    world.set_joint_states(robot, {"torso_lift_joint": 0.2, "r_shoulder_pan_joint": -0.5})
    world.set_pose(robot, Pose((-0.4, 0.3, 0.0)))
    world.attach("mug-1", robot, hand)
    world.set_pose("mug-1", Pose((0.0, 0.0, 1.5)))
    world.add_box("board", (0.1, 0.1, 0.1), Pose((2.0, 0.0, 0.05)))
    driver.robot.held_rolls[("kitchen", "handle")] = 1.0
    settings = DriverSettings(str(tmp_path / "g"), 3.0, 0.4, 2.0, "abort")
    driver.reset(settings)
    fresh = tabletop_scene("pr2").world
    got, want = _raw(world), _raw(fresh)
    assert got.keys() == want.keys()
    for name, rows in want.items():
        for mine, built in zip(got[name], rows, strict=True):
            assert mine == pytest.approx(built, abs=SAME), name
    assert world.bodies.attachments(robot) == {}
    assert driver.handles.held == [] and driver.robot.held_rolls == {}
    sent = driver._publishers["joints"].sent[-1]  # published as the reset ends
    assert dict(zip(sent.name, sent.position, strict=True)) == pytest.approx(
        fresh.joint_states(robot), abs=SAME
    )
    assert (driver.options.base_speed, driver.options.time_scale) == (0.4, 2.0)
    assert (driver.fault, driver.clock.offset, driver.goal_log) == ("abort", 3.0, tmp_path / "g")
    fresh.close()
    world.close()


def test_a_reset_waits_for_running_goals_and_refuses_a_bad_fault() -> None:
    driver = _driver()
    driver._goal_started()
    with pytest.raises(DriverBusy, match="1 goal"):
        driver.reset(DriverSettings(), timeout=0.05)
    driver._goal_finished()
    with pytest.raises(DriverArgumentError, match="bogus"):
        driver.reset(DriverSettings(fault="bogus"))
    driver.reset(DriverSettings())
    driver.world.close()


def test_reset_lines_are_answered_in_order(capsys: pytest.CaptureFixture[str]) -> None:
    seen: list[DriverSettings] = []

    def reset(settings: DriverSettings) -> None:
        if settings.fault == "busy":
            raise DriverBusy("1 goal(s) still running")
        seen.append(settings)

    lines = [
        'reset 1 {"clock_offset": -10.0, "goal_log": "/tmp/g"}',
        "reset 2 not json",
        "something else",
        'reset 3 {"fault": "busy"}',
        'reset 4 {"no_such_setting": 1}',
        "reset 5 {}",
    ]
    thread = serve_resets(reset, io.StringIO("\n".join(lines) + "\n"))
    thread.join(10.0)
    assert not thread.is_alive()  # the end of the input ends it
    said = capsys.readouterr().out.splitlines()
    assert said[0] == "reset 1 done"
    assert said[1].startswith("reset 2 failed: DriverArgumentError")
    assert said[2] == "reset 3 failed: DriverBusy: 1 goal(s) still running"
    assert said[3].startswith("reset 4 failed: DriverArgumentError")
    assert said[4:] == ["reset 5 done"]
    assert seen == [DriverSettings(goal_log="/tmp/g", clock_offset=-10.0), DriverSettings()]
    assert seen[0].goal_log_path == Path("/tmp/g")
    assert isinstance(thread, threading.Thread)
