"""ROS facts per robot, set-up errors and the optional extra (no ROS master needed)."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest

from robocram.logic import KnowledgeBase
from robocram.robots import load_description
from robocram.ros import (
    GoalOutcome,
    GoalState,
    RosConfig,
    RosConfigError,
    RosExtraMissing,
    availability,
    install_ros_facts,
    read_ros_config,
    ros_environment,
)
from robocram.ros.ros_config import default_facts


def _config(robot: str, facts: str | None = None) -> RosConfig:
    kb = KnowledgeBase()
    install_ros_facts(kb, robot, facts)
    return read_ros_config(kb, load_description(robot))


def test_pr2_defaults_name_cram_s_controllers() -> None:
    config = _config("pr2")
    assert config.action("arm(left)").server == "/l_arm_controller/follow_joint_trajectory"
    assert config.action("gripper(right)").action_type == "control_msgs/GripperCommand"
    head = config.action("head")  # the trajectory robocram plans and checks, not PointHead
    assert head.server == "/head_traj_controller/follow_joint_trajectory"
    assert head.action_type == "control_msgs/FollowJointTrajectory"
    assert config.action("navigation").timeout == 120.0
    assert config.action("arm(right)").timeout == 30.0
    assert config.joint_states_topic == "/joint_states"


def test_hsr_is_configured_by_facts_only() -> None:
    config = _config("hsrb")
    assert config.joint_states_topic == "/hsrb/joint_states"
    assert config.action("head").action_type == "control_msgs/FollowJointTrajectory"
    assert config.action("torso").server == config.action("arm(arm)").server


def test_a_missing_fact_is_named() -> None:
    facts = default_facts("pr2").replace("ros_topic(pr2, joint_states, '/joint_states').", "")
    with pytest.raises(RosConfigError, match=r"ros_topic\(pr2, joint_states, Topic\)"):
        _config("pr2", facts)
    no_torso = re.sub(r"ros_action\(pr2, torso,[^.]*\.", "", default_facts("pr2"))
    with pytest.raises(RosConfigError, match=r"no ros_action\(pr2, torso, Server, Type\) fact"):
        _config("pr2", no_torso).action("torso")


def test_an_unknown_action_type_says_which_are_known() -> None:
    facts = default_facts("pr2").replace("'control_msgs/GripperCommand'", "'pr2_msgs/Gripper'")
    with pytest.raises(RosConfigError, match="unknown action type; use one of"):
        _config("pr2", facts)


def test_robots_without_packaged_facts_need_them_passed() -> None:
    with pytest.raises(RosConfigError, match="ships no ROS facts for 'boxy'"):
        default_facts("boxy")


def test_no_master_uri_says_how_to_give_one(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_MASTER_URI", raising=False)
    with pytest.raises(RosConfigError, match="pass master_uri= or set ROS_MASTER_URI"):
        ros_environment("pr2")


def test_a_missing_extra_says_how_to_install_it(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(availability, "REQUIRED", (*availability.REQUIRED, "no_such_ros_pkg"))
    with pytest.raises(RosExtraMissing, match="no_such_ros_pkg.*tools/setup_ros.sh"):
        availability.require_ros_extra()
    assert availability.missing_modules() == ["no_such_ros_pkg"]


def test_the_core_imports_without_ros() -> None:
    code = (
        "import sys, robocram.plans, robocram.projection, robocram.execution\n"
        "assert not {'rospy', 'actionlib', 'robocram.ros'} & set(sys.modules), sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_goal_tolerances_come_from_facts_else_from_the_joint_type() -> None:
    tolerances = _config("pr2").goal_tolerances
    assert tolerances.position("torso_lift_joint") == pytest.approx(0.005)  # a fact
    assert tolerances.position("r_wrist_roll_joint") == pytest.approx(0.05)  # a fact
    assert tolerances.position("r_elbow_flex_joint") == pytest.approx(0.02)  # revolute
    assert tolerances.time == pytest.approx(0.5)
    fields = tolerances.to_ros(["torso_lift_joint"])
    assert fields["goal_tolerance"] == [
        {"name": "torso_lift_joint", "position": 0.005, "velocity": 0.0, "acceleration": 0.0}
    ]
    assert fields["goal_time_tolerance"] == {"secs": 0, "nsecs": 500_000_000}


def test_a_goal_tolerance_of_an_unknown_joint_or_not_positive_is_named() -> None:
    typo = "ros_goal_tolerance(pr2, torso_lift, 0.01).\n" + default_facts("pr2")
    with pytest.raises(RosConfigError, match=r"torso_lift, _\) names no movable joint"):
        _config("pr2", typo)
    negative = "ros_goal_time_tolerance(pr2, -1.0).\n" + default_facts("pr2")
    with pytest.raises(RosConfigError, match=r"ros_goal_time_tolerance\(pr2, S\) gives -1.0"):
        _config("pr2", negative)


def test_the_pr2_gripper_takes_a_gap_in_metres_and_holds_when_aborted_stalled() -> None:
    gripper = _config("pr2").grippers["right"]
    assert (gripper.joint, gripper.unit) == ("r_gripper_l_finger_joint", "gap")
    assert gripper.command(0.548) == pytest.approx(0.085)  # open: the finger joint's limit
    assert gripper.command(0.0) == pytest.approx(0.0)
    assert gripper.joint_value(0.0425) == pytest.approx(0.274)
    assert gripper.holding_status.name == "ABORTED"
    assert gripper.holding_min == pytest.approx(0.002)
    hsr = _config("hsrb").grippers["arm"]
    assert (hsr.unit, hsr.holding_status.name) == ("joint", "SUCCEEDED")
    assert hsr.command(1.24) == pytest.approx(1.24)  # the joint value itself


@pytest.mark.parametrize(
    ("state", "stalled", "gap", "holding"),
    [
        ("ABORTED", True, 0.03, True),  # stalled on a mug
        ("SUCCEEDED", False, 0.0088, True),  # a bowl's rim, within the goal threshold
        ("SUCCEEDED", False, 0.0005, False),  # closed on nothing
        ("ABORTED", True, 0.001, False),  # stalled nearly shut: nothing worth holding
    ],
)
def test_the_pr2_gripper_holds_by_its_gap(
    state: str, stalled: bool, gap: float, holding: bool
) -> None:
    gripper = _config("pr2").grippers["right"]
    outcome = GoalOutcome(GoalState[state], "", {"position": gap, "stalled": stalled})
    assert gripper.holds(outcome) is holding
    hsr = _config("hsrb").grippers["arm"]  # succeeds on holding: the stall flag decides
    assert not hsr.holds(GoalOutcome(GoalState.SUCCEEDED, "", {"position": 0.5}))


def test_a_gripper_fact_with_an_unknown_unit_names_the_fix() -> None:
    facts = "ros_gripper_command(pr2, right, inches, 0.0, 3.5).\n" + default_facts("pr2")
    with pytest.raises(RosConfigError, match=r"unit 'inches'.*use a unit of \('gap', 'joint'\)"):
        _config("pr2", facts)


def test_native_pr2_action_types_are_accepted_by_name() -> None:
    facts = (
        "ros_action(pr2, torso, '/torso_controller/position_joint_action', "
        "'pr2_controllers_msgs/SingleJointPosition').\n" + default_facts("pr2")
    )
    config = _config("pr2", facts)
    kinds = {i.action_type for i in config.actions.values()}
    assert "pr2_controllers_msgs/SingleJointPosition" in kinds
