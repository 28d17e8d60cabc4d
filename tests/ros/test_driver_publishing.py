"""The driver's state publications go out in the order of the world they show.

A publication held up between its snapshot and its sending (the timer's thread on a
loaded machine) must not go out after a later one: else the state from before a goal's
end, stamped after it, is the last one a client hears after the goal's result. Run in
this process with recording publishers and a counting clock (no ROS master).
"""

from __future__ import annotations

import threading

import genpy

from robocram.robots import load_description
from robocram.ros.ros_config import install_ros_facts, read_ros_config
from robocram.ros_driver.projection_driver import ProjectionDriver
from robocram.ros_driver.robot_clock import RobotClock
from robocram.scenes import tabletop_scene

TORSO = "torso_lift_joint"
MOVED = 0.2  # [m] the torso after the goal's jump
HELD_UP = 0.5  # [s] the second publication is given this long to overtake the first


class Recorder:
    """A publisher keeping what it was given; the first message waits for ``release``."""

    def __init__(self, hold_first: bool = False) -> None:
        self.sent: list[genpy.Message] = []
        self.holding = threading.Event()
        self.release = threading.Event()
        if not hold_first:
            self.release.set()

    def publish(self, message: genpy.Message) -> None:
        if not self.sent and not self.release.is_set():
            self.holding.set()
            self.release.wait()
        self.sent.append(message)


class CountingClock(RobotClock):
    """The robot's clock: 1 s, 2 s, ... at each reading."""

    def __init__(self) -> None:
        super().__init__(0.0)
        self.readings = 0

    def now(self) -> genpy.Time:
        self.readings += 1
        return genpy.Time(self.readings)


def test_a_publication_held_up_goes_out_before_the_one_after_the_goal() -> None:
    scene = tabletop_scene("pr2")
    install_ros_facts(scene.world.kb, scene.robot, None)
    config = read_ros_config(scene.world.kb, load_description(scene.robot))
    driver = ProjectionDriver(scene.world, config)
    tf, joints = Recorder(hold_first=True), Recorder()
    driver._publishers = {"tf": tf, "joints": joints}  # the tabletop has no environments
    driver.clock = CountingClock()
    timer = threading.Thread(target=driver.publish_state)  # before the goal: held up
    timer.start()
    assert tf.holding.wait(10.0)
    with driver.lock:  # the goal's jump
        scene.world.set_joint_states(scene.robot, {TORSO: MOVED})
    after_goal = threading.Thread(target=driver.publish_state)
    after_goal.start()
    after_goal.join(HELD_UP)  # it may overtake the held-up one here, if it can
    tf.release.set()
    timer.join()
    after_goal.join()
    stamps = [m.header.stamp.to_sec() for m in joints.sent]
    torso = [dict(zip(m.name, m.position, strict=True))[TORSO] for m in joints.sent]
    assert stamps == sorted(stamps)  # sent in the order they were taken
    assert torso[-1] == MOVED  # the last state heard is the one after the goal
    assert [m.transforms[0].header.stamp.to_sec() for m in tf.sent] == stamps
    scene.world.close()
