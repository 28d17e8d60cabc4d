"""The real PR2's controllers (the driver's ``controllers="pr2"``): a gripper that reads a
gap in metres and reports holding as ABORTED with ``stalled``, joints clamped to the soft
limits, results without status text, and a robot clock 10 s off ours."""

from __future__ import annotations

import logging
import re
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.execution import perform, pursue, sleep
from robocram.execution.failures import (
    ActionlibActionTimedOut,
    GripperClosedCompletely,
    TorsoGoalNotReached,
)
from robocram.plans import pick_up
from robocram.ros import RosCancelIgnored, Roscore, RosMasterUnreachable, ros_robot
from robocram.ros.ros_config import default_facts
from robocram.ros.roscore import free_port
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from tests.ros.driver_pool import DriverPool

RIGHT_GRIPPER = "/r_gripper_controller/gripper_action"
OPEN_GAP = 0.085  # [m] what the PR2's facts send for opening
FINGER_UPPER = 0.548  # [rad] the description's finger joint at the open limit
GAP_AT_UPPER = 0.09  # [m] the PR2's gap there (pr2_description's gripper_joint)
SKEW = 0.5  # [s] a measured clock offset is this close to the driver's


@pytest.mark.parametrize("offset", [-10.0, 10.0], ids=["clock_behind", "clock_ahead"])
def test_pick_up_succeeds_on_the_real_pr2_controllers_with_a_skewed_clock(
    roscore: Roscore,
    drivers: DriverPool,
    tmp_path: Path,
    offset: float,
    caplog: pytest.LogCaptureFixture,
) -> None:
    look = tabletop_scene("pr2").look_target
    log = tmp_path / "goals.jsonl"
    with (
        caplog.at_level(logging.WARNING, logger="robocram.ros"),
        drivers(controllers="pr2", clock_offset=offset, goal_log=log) as driver,
        ros_robot("pr2", roscore.uri) as run,
    ):
        result = pick_up(look)
        mug = run.transforms.lookup("map", "mug-1")
        skew = run.environment.client.clock_skew
        gaps = [g["command"]["position"] for g in driver.received_goals(RIGHT_GRIPPER)]
    assert run.tree.root.status.name == "SUCCEEDED"
    assert result.arm == "right"
    assert mug.position[2] > look.position[2] + 0.09  # lifted
    assert gaps and all(g in (0.0, OPEN_GAP) for g in gaps)  # gaps [m], never radians
    assert gaps[-1] == 0.0  # the grip that held
    assert skew == pytest.approx(offset, abs=SKEW)
    assert any("robot's clock is" in r.getMessage() for r in caplog.records)


def test_opening_sends_a_gap_in_metres_and_returns_the_finger_joint(
    roscore: Roscore, drivers: DriverPool
) -> None:
    with drivers(controllers="pr2"), ros_robot("pr2", roscore.uri) as run:
        opened = perform(a.motion(type="opening", gripper="right"))
        finger = run.environment.client.joint_states()["r_gripper_l_finger_joint"]
    assert opened == pytest.approx(FINGER_UPPER, abs=1e-3)  # the description's open value
    assert finger == pytest.approx(OPEN_GAP * FINGER_UPPER / GAP_AT_UPPER, abs=1e-3)


def test_gripping_nothing_closes_completely(roscore: Roscore, drivers: DriverPool) -> None:
    with (
        drivers(controllers="pr2"),
        ros_robot("pr2", roscore.uri),
        pytest.raises(GripperClosedCompletely) as failure,
    ):
        perform(a.motion(type="gripping", gripper="right"))
    assert failure.value.position == pytest.approx(0.0, abs=1e-3)
    assert "SUCCEEDED, stalled=False" in str(failure.value)


def test_a_bare_abort_carries_the_error_code_and_string(
    roscore: Roscore, drivers: DriverPool
) -> None:
    with (
        drivers(controllers="pr2", fault="abort"),
        ros_robot("pr2", roscore.uri),
        pytest.raises(TorsoGoalNotReached) as failure,
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
    context = failure.value.context
    assert context["status_text"] == ""
    assert context["error_code"] == -5
    assert "aborts every goal" in str(context["error_string"])
    assert "error_code -5 (GOAL_TOLERANCE_VIOLATED)" in str(failure.value)
    assert "aborts every goal" in str(failure.value)
    assert "no status text" not in str(failure.value)


def test_a_cancel_the_server_ignores_raises_that_the_robot_may_still_move(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    facts = (
        "ros_action_timeout(pr2, navigation, 1.0).\nros_cancel_timeout(pr2, 0.5).\n"
        + default_facts("pr2")
    )
    with (
        drivers(fault="ignore_cancel"),
        ros_robot("pr2", roscore.uri, facts),
        pytest.raises(RosCancelIgnored) as failure,
    ):
        perform(a.motion(type="going", target=a.location(pose=Pose((-1.0, 0.0, 0.0)))))
    assert failure.value.server == "/move_base"
    assert failure.value.timeout == 0.5
    assert failure.value.stopping is False  # the goal's time ran out; nothing stopped it
    assert "may still be moving" in str(failure.value)
    assert not isinstance(failure.value, ActionlibActionTimedOut)


def test_no_master_is_a_typed_error_naming_the_uri(roscore: Roscore) -> None:
    uri = f"http://127.0.0.1:{free_port()}"  # nobody listens there
    with pytest.raises(RosMasterUnreachable) as error, ros_robot("pr2", uri, master_timeout=0.5):
        pass
    assert uri in str(error.value)
    assert "0.5 s" in str(error.value)
    assert "start roscore" in str(error.value)


NATIVE = """
ros_action(pr2, navigation, '/move_base', 'move_base_msgs/MoveBase').
ros_action(pr2, torso, '/torso_controller/position_joint_action',
           'pr2_controllers_msgs/SingleJointPosition').
ros_action(pr2, arm(left), '/l_arm_controller/joint_trajectory_action',
           'pr2_controllers_msgs/JointTrajectory').
ros_action(pr2, arm(right), '/r_arm_controller/joint_trajectory_action',
           'pr2_controllers_msgs/JointTrajectory').
ros_action(pr2, head, '/head_traj_controller/point_head_action', 'pr2_controllers_msgs/PointHead').
ros_action(pr2, gripper(left), '/l_gripper_controller/gripper_action',
           'pr2_controllers_msgs/Pr2GripperCommand').
ros_action(pr2, gripper(right), '/r_gripper_controller/gripper_action',
           'pr2_controllers_msgs/Pr2GripperCommand').
ros_action(pr2, perception, '/robocram/detect_objects', 'robocram_msgs/DetectObjects').
"""


def _native_facts() -> str:
    """The PR2's facts with its native pr2_controllers_msgs action servers."""
    rest = re.sub(r"ros_action\(pr2,[^.]*\)\.\s*", "", default_facts("pr2"))
    return NATIVE + rest


def test_pick_up_succeeds_on_the_pr2s_native_action_types(
    roscore: Roscore, drivers: DriverPool, tmp_path: Path
) -> None:
    facts = tmp_path / "pr2_native.pl"
    facts.write_text(_native_facts())
    log = tmp_path / "goals.jsonl"
    look = tabletop_scene("pr2").look_target
    with (
        drivers(controllers="pr2", ros_facts=facts, goal_log=log) as driver,
        ros_robot("pr2", roscore.uri, facts.read_text()) as run,
    ):
        result = pick_up(look)
        mug = run.transforms.lookup("map", "mug-1")
        torso = driver.received_goals("/torso_controller/position_joint_action")
        arm = driver.received_goals("/r_arm_controller/joint_trajectory_action")
    assert run.tree.root.status.name == "SUCCEEDED"
    assert result.arm == "right"
    assert mug.position[2] > look.position[2] + 0.09  # lifted
    assert torso and set(torso[0]) == {"position", "min_duration", "max_velocity"}
    assert torso[-1]["position"] == pytest.approx(0.305)  # the soft limit, not 0.31
    assert arm and set(arm[0]) == {"trajectory"}  # no control_msgs tolerances
    assert len(arm[0]["trajectory"]["points"]) > 2  # a timed trajectory, not one point


def test_a_stopped_task_whose_cancel_is_ignored_does_not_end_silently(
    roscore: Roscore, drivers: DriverPool
) -> None:
    facts = "ros_cancel_timeout(pr2, 0.5).\n" + default_facts("pr2")
    far = a.location(pose=Pose((-1.0, 0.0, 0.0)))
    with (
        drivers(fault="ignore_cancel"),
        pytest.raises(RosCancelIgnored) as failure,
        ros_robot("pr2", roscore.uri, facts),
    ):
        pursue(lambda: perform(a.motion(type="going", target=far)), lambda: sleep(0.3))
    assert failure.value.server == "/move_base"
    assert "may still be moving" in str(failure.value)
    assert failure.value.stopping
