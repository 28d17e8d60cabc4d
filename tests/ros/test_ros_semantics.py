"""ROS semantics: cancel on stop, timeouts, ABORTED, a dying driver; nothing left running."""

from __future__ import annotations

import math
import multiprocessing
import threading
import time
from collections.abc import Callable

import pytest

from robocram.designators import a
from robocram.execution import perform, pursue, sleep
from robocram.execution.failures import (
    ActionlibActionTimedOut,
    NavigationGoalNotReached,
    TorsoGoalNotReached,
)
from robocram.ros import RosConnectionLost, Roscore, RosJointStateInvalid, ros_robot
from robocram.ros.ros_config import default_facts
from robocram.tf import Pose
from tests.ros.driver_pool import DriverPool

FAR = Pose((-4.0, 3.0, 0.0))  # [m] free floor, far from the robot at the origin
MOVED = 0.05  # [m] the base has clearly started moving


def _going(pose: Pose = FAR) -> None:
    perform(a.motion(type="going", target=a.location(pose=pose)))


def _nothing_left(threads: set[threading.Thread], node: str, nodes: set[str]) -> None:
    """No thread, child process or ROS node of ours is left."""
    assert set(threading.enumerate()) == threads
    assert multiprocessing.active_children() == []
    assert node not in nodes


def test_stopping_mid_navigation_cancels_the_goal_and_the_base_stops(
    roscore: Roscore, drivers: DriverPool, master_nodes: Callable[[], set[str]]
) -> None:
    threads = set(threading.enumerate())
    with drivers(base_speed=0.3), ros_robot("pr2", roscore.uri) as run:
        client = run.environment.client
        start = client.base_pose()

        def until_moving() -> None:
            while client.base_pose().distance_to(start) < MOVED:
                sleep(0.02)

        pursue(_going, until_moving)
        stopped = client.base_pose()
        for _ in range(3):  # several state messages later the base is still there
            assert client.transport.wait_for_state(None, 5.0)
        later = client.base_pose()
        node = client.transport.node_name  # type: ignore[attr-defined]
    assert stopped.distance_to(start) >= MOVED
    assert stopped.distance_to(FAR) > 1.0
    assert later.distance_to(stopped) < 1e-6
    _nothing_left(threads, node, master_nodes())


def _facts_with(line: str) -> str:
    """The PR2's ROS facts with ``line`` put first (its answer wins)."""
    return line + "\n" + default_facts("pr2")


def test_a_driver_that_never_answers_gives_a_timeout_naming_the_controller(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    facts = _facts_with("ros_action_timeout(pr2, navigation, 1.5).")
    with (
        drivers(fault="silent"),
        ros_robot("pr2", roscore.uri, facts),
        pytest.raises(ActionlibActionTimedOut) as failure,
    ):
        _going()
    assert failure.value.action == "/move_base"
    assert failure.value.timeout == 1.5
    assert "/move_base" in str(failure.value)
    assert failure.value.context["process_module"] == "ros_navigation"


def test_a_driver_that_aborts_gives_the_typed_failure_with_the_status_text(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    with drivers(fault="abort"), ros_robot("pr2", roscore.uri):
        with pytest.raises(NavigationGoalNotReached) as going:
            _going()
        with pytest.raises(TorsoGoalNotReached) as torso:
            perform(a.motion(type="moving-torso", joint_angle=0.1))
    for failure, server in (
        (going.value, "/move_base"),
        (torso.value, "/torso_controller/follow_joint_trajectory"),
    ):
        assert failure.context["status"] == "ABORTED"
        assert failure.context["controller"] == server
        assert "aborts every goal" in failure.context["status_text"]
        assert "aborts every goal" in str(failure)
    assert torso.value.goal == 0.1


def test_a_goal_out_of_limits_is_clamped_sent_and_fails_as_in_projection(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    with drivers(), ros_robot("pr2", roscore.uri) as run:
        with pytest.raises(TorsoGoalNotReached) as failure:
            perform(a.motion(type="moving-torso", joint_angle=0.5))
        reached = run.environment.client.joint_states()["torso_lift_joint"]
    assert "torso_lift_joint=0.5 not in [0.0, 0.31]" in str(failure.value)
    assert failure.value.goal == 0.5
    # sent as the safety_controller's soft upper limit, where the real PR2 stops
    assert reached == pytest.approx(0.305)


def test_a_goal_between_the_soft_and_the_hard_limit_ends_at_the_soft_limit(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    with drivers(), ros_robot("pr2", roscore.uri) as run:
        perform(a.motion(type="moving-torso", joint_angle=0.31))  # the hard upper limit
        reached = run.environment.client.joint_states()["torso_lift_joint"]
    assert reached == pytest.approx(0.305)  # the soft upper limit (pr2_description)


def test_a_joint_state_that_is_not_a_number_names_the_topic_and_the_joint(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    with (
        drivers(fault="nan_joint_state"),
        ros_robot("pr2", roscore.uri),
        pytest.raises(RosJointStateInvalid) as failure,
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
    assert (failure.value.topic, failure.value.joint) == ("/joint_states", "torso_lift_joint")
    assert math.isnan(failure.value.value)  # type: ignore[arg-type]
    assert "'torso_lift_joint' at nan on /joint_states" in str(failure.value)
    assert "bug in the module" not in str(failure.value)


def test_a_driver_dying_mid_goal_gives_a_typed_failure_not_a_hang(
    roscore: Roscore, drivers: DriverPool, master_nodes: Callable[[], set[str]]
) -> None:
    threads = set(threading.enumerate())
    # LOST after 1 s without status (the packaged facts: 2 s); a live driver's comes at 5 Hz
    facts = _facts_with("ros_connection_timeout(pr2, 1.0).")
    with drivers(base_speed=0.3) as driver, ros_robot("pr2", roscore.uri, facts) as run:
        client = run.environment.client
        start = client.base_pose()

        def kill_once_moving() -> None:
            while client.base_pose().distance_to(start) < MOVED:
                time.sleep(0.02)
            driver.kill()

        killer = threading.Thread(target=kill_once_moving)
        killer.start()
        try:
            with pytest.raises(RosConnectionLost) as failure:
                _going()
        finally:
            killer.join()
        node = client.transport.node_name  # type: ignore[attr-defined]
    assert failure.value.server == "/move_base"
    assert "no status from /move_base" in failure.value.reason
    assert math.isfinite(start.position[0])
    _nothing_left(threads, node, master_nodes())
