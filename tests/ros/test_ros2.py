"""ROS 2: the same plans through rclpy, ros2_control's and Nav2's interfaces, against the
projection driver serving them in another process: one at a time, on a ROS 2 domain of
its own, shared by the tests that ask for the same robot and scene (``driver_pool.py``)."""

from __future__ import annotations

import multiprocessing
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform, pursue, sleep
from robocram.execution.failures import NavigationGoalNotReached
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.ros import RosCancelIgnored, RosConnectionLost, RosExtraMissing, ros_robot
from robocram.ros.ros2_environment import child_argv, ros2_prefix
from robocram.ros.ros_config import default_facts
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped, pose_to_ros, transform_pose
from tests.ros.driver_pool import DriverPool
from tests.ros.received_goals import assert_same_goal, seconds
from tests.ros.served_state import assert_same_state, served_state

AGREE = 0.01  # [m] ROS 2 and direct projection agree this closely
MOVED = 0.05  # [m] the base has started moving
LEASE = 4.0  # [s] a dead process is gone from the ROS graph after it (fastdds_profile.xml)
LOST_AFTER = 0.5  # [s] a server gone from the graph this long has lost its goals (here)
SAME = 1e-9  # [rad | s] what crosses ROS unchanged (float64; times to the nanosecond)
TRAJECTORY_SERVERS = {
    "torso": "/torso_controller/follow_joint_trajectory",
    "head": "/head_controller/follow_joint_trajectory",
    "left": "/l_arm_controller/follow_joint_trajectory",
    "right": "/r_arm_controller/follow_joint_trajectory",
}


def _server_of(trajectory: JointTrajectory) -> str:
    joint = trajectory.joint_names[0]
    side = {"l": "left", "r": "right"}.get(joint.split("_")[0], "")
    return TRAJECTORY_SERVERS[side or joint.split("_")[0]]


def test_pick_up_through_ros2_agrees_with_projection_goal_by_goal_with_the_clock_ahead(
    drivers2: DriverPool, tmp_path: Path
) -> None:
    scene = tabletop_scene("pr2")
    with simulated_robot(scene.world, "pr2"):
        direct = pick_up(scene.look_target)
    tool, mug = scene.world.link_pose("pr2", direct.tool_frame), scene.world.pose("mug-1")
    world = tabletop_scene("pr2").world  # the mirror: motions planned and checked in it
    threads = set(threading.enumerate())
    sent: list[JointTrajectory] = []
    with (
        drivers2("pr2", goal_log=tmp_path / "g", clock_offset=10.0) as driver,
        ros_robot("pr2", ros=2, world=world) as run,
        trajectory_listener(sent.append),
    ):
        result = pick_up(scene.look_target)
        ros_tool = transform_pose(PoseStamped(result.tool_frame), "map").pose
        ros_mug = run.transforms.lookup("map", "mug-1")
        in_world = run.transforms.lookup("world", "mug-1")  # map's parent: /tf_static
        grippers = driver.received_goals("/l_gripper_controller/gripper_cmd")
        grippers += driver.received_goals("/r_gripper_controller/gripper_cmd")
        by_server = {s: driver.received_goals(s) for s in TRAJECTORY_SERVERS.values()}
        skew = run.environment.client.clock_skew
    assert run.tree.root.status.name == "SUCCEEDED"
    assert skew == pytest.approx(10.0, abs=0.5)  # the robot's clock ahead: no matter
    assert result.arm == direct.arm
    assert ros_tool.distance_to(tool) < AGREE
    assert ros_mug.distance_to(mug) < AGREE
    assert in_world.distance_to(ros_mug) < 1e-9
    assert ros_mug.position[2] > 0.09 + scene.look_target.position[2]  # lifted
    assert len(sent) == sum(len(goals) for goals in by_server.values()) >= 4
    for trajectory in sent:  # every trajectory goal, in order per controller, as planned
        assert_same_goal(by_server[_server_of(trajectory)].pop(0), trajectory)
    assert [g["command"]["position"] for g in grippers] == pytest.approx([0.085, 0.0])
    assert set(threading.enumerate()) == threads
    assert multiprocessing.active_children() == []


def test_without_the_set_up_ros2_names_the_command(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("ROBOCRAM_ROS2_PREFIX", str(tmp_path / "no_ros2"))
    with pytest.raises(RosExtraMissing, match=r"rclpy.*make setup.*tools/setup_ros2.sh"):
        ros_robot("pr2", ros=2).__enter__()


def test_an_absent_controller_fails_typed_within_its_server_timeout(drivers2: DriverPool) -> None:
    facts = default_facts("pr2", ros=2).replace(
        "ros_server_timeout(pr2, 5.0)", "ros_server_timeout(pr2, 1.0)"
    )
    facts = facts.replace("/torso_controller/", "/no_torso_controller/")
    with (
        drivers2("pr2"),
        ros_robot("pr2", ros=2, ros_facts=facts),
    ):
        start = time.monotonic()
        with pytest.raises(RosConnectionLost, match="no_torso_controller.*1.0 s") as lost:
            perform(a.motion(type="moving-torso", joint_angle=0.2))
        waited = time.monotonic() - start
    assert lost.value.server == "/no_torso_controller/follow_joint_trajectory"
    assert 1.0 <= waited < 3.0


def test_nav2_failing_gives_the_typed_failure_with_its_error_code_and_feedback_is_read(
    drivers2: DriverPool,
) -> None:
    x, y, _ = tabletop_scene("pr2").world.pose("table").position
    into_the_table = Pose((x, y, 0.0))  # the base inside the table
    back = Pose((-1.0, 0.0, 0.0))  # [m] 1 m behind the robot: 2 s at 0.5 m/s
    serving = drivers2("pr2", base_speed=0.5)
    with serving, ros_robot("pr2", ros=2) as run:
        client = run.environment.client
        before = client.base_pose()
        with pytest.raises(NavigationGoalNotReached, match="ABORTED") as failed:
            perform(a.motion(type="going", target=into_the_table))
        after = client.base_pose()
        goal = {"pose": {"header": {"frame_id": "map"}, "pose": pose_to_ros(back)}}
        handle = client.transport.send_goal("/navigate_to_pose", goal)
        with handle.done:
            assert handle.done.wait_for(lambda: handle.outcome is not None, 10.0)
    assert failed.value.context["error_code"] == 206
    assert "error_code 206 (GOAL_OCCUPIED)" in str(failed.value)
    assert "would collide with ['mug-1', 'table']" in str(failed.value)  # Nav2's error_msg
    assert after.distance_to(before) < 1e-6  # refused: the robot did not move
    assert handle.outcome is not None and handle.outcome.state.name == "SUCCEEDED"
    feedback = handle.outcome.feedback  # the last the server sent while driving
    assert feedback["distance_remaining"] < 0.2
    assert seconds(feedback["navigation_time"]) > 1.5
    assert feedback["current_pose"]["header"]["frame_id"] == "map"


def test_stopping_mid_navigation_cancels_the_nav2_goal_and_the_base_stops(
    drivers2: DriverPool, tmp_path: Path
) -> None:
    far = Pose((-4.0, 3.0, 0.0))  # free floor, far from the robot at the origin
    log = tmp_path / "goals.jsonl"
    with drivers2("pr2", base_speed=0.3, goal_log=log) as driver, ros_robot("pr2", ros=2) as run:
        client = run.environment.client
        start = client.base_pose()
        stops: list[float] = []

        def until_moving() -> None:
            while client.base_pose().distance_to(start) < MOVED:
                sleep(0.02)
            stops.append(time.monotonic())

        pursue(lambda: perform(a.motion(type="going", target=far)), until_moving)
        stopped = client.base_pose()
        for _ in range(3):  # several state messages later the base is still there
            assert client.transport.wait_for_state(None, 5.0)
        later = client.base_pose()
        (cancel,) = driver.cancels_seen("/navigate_to_pose")
    assert stopped.distance_to(start) >= MOVED
    assert stopped.distance_to(far) > 1.0
    assert later.distance_to(stopped) < 1e-6
    assert 0.0 < cancel - stops[0] < 0.05  # [s] the stop reached the driver within 50 ms


def test_a_reset_driver_serves_what_a_fresh_one_does(drivers2: DriverPool) -> None:
    """The module's driver, its robot moved here (torso, gripper, base) and its clock
    shifted, is reset: it serves the robot's joints, every transform, its topics and its
    services as a driver started fresh does."""
    with drivers2("pr2", clock_offset=10.0), ros_robot("pr2", ros=2) as run:
        perform(a.motion(type="moving-torso", joint_angle=0.2))
        perform(a.motion(type="opening", gripper="left"))
        perform(a.motion(type="going", target=a.location(pose=Pose((-0.4, 0.3, 0.0)))))
        moved = run.environment.client.joint_states()["torso_lift_joint"]
    with drivers2("pr2"):
        reset = served_state(["/joint_states"], domain=drivers2.domain_id)
    drivers2.close()  # the next driver of the pool is started fresh (the test after uses it)
    started = drivers2.started
    with drivers2("pr2"):
        fresh = served_state(["/joint_states"], domain=drivers2.domain_id)
    assert drivers2.started == started + 1
    assert moved == pytest.approx(0.2, abs=0.005)
    assert fresh["/joint_states"]["torso_lift_joint"] != pytest.approx([0.2], abs=0.005)
    assert_same_state(reset, fresh, SAME)
    assert "/navigate_to_pose/_action/send_goal" in fresh["serves"]


def test_a_cancel_the_server_refuses_raises_that_the_robot_may_still_move(
    drivers2: DriverPool,
) -> None:
    facts = (
        "ros_action_timeout(pr2, navigation, 1.0).\nros_cancel_timeout(pr2, 0.5).\n"
        + default_facts("pr2", ros=2)
    )
    with (
        drivers2("pr2", fault="ignore_cancel"),
        ros_robot("pr2", ros=2, ros_facts=facts),
    ):
        start = time.monotonic()
        with pytest.raises(RosCancelIgnored) as ignored:
            perform(a.motion(type="going", target=Pose((-1.0, 0.0, 0.0))))
        waited = time.monotonic() - start
    # the action's timeout (1 s), then the cancel's (0.5 s), both waited out; the upper
    # bound only says it did not hang (a loaded machine took 3.8 s with teardown)
    assert 1.5 - 0.05 <= waited < 1.5 + 8.0
    assert ignored.value.server == "/navigate_to_pose"
    assert ignored.value.timeout == 0.5
    assert ignored.value.stopping is False


def test_a_parallel_gripper_takes_a_joint_state_command_and_reports_its_state(
    drivers2: DriverPool, tmp_path: Path
) -> None:
    facts = default_facts("pr2", ros=2).replace(
        "'control_msgs/GripperCommand'", "'control_msgs/ParallelGripperCommand'"
    )
    facts_file = tmp_path / "pr2_parallel.pl"
    facts_file.write_text(facts)
    log = tmp_path / "goals.jsonl"
    serving = drivers2("pr2", ros_facts=facts_file, goal_log=log)
    with serving as driver, ros_robot("pr2", ros=2, ros_facts=facts) as run:
        opened = perform(a.motion(type="opening", gripper="left"))
        closed = perform(a.motion(type="closing", gripper="left"))
        finger = run.environment.client.joint_states()["l_gripper_l_finger_joint"]
        (open_goal, close_goal) = driver.received_goals("/l_gripper_controller/gripper_cmd")
    assert open_goal["command"]["name"] == ["l_gripper_l_finger_joint"]
    assert open_goal["command"]["position"] == pytest.approx([0.085])  # a gap [m], the facts
    assert close_goal["command"]["position"] == pytest.approx([0.0])
    assert opened == pytest.approx(0.548, abs=1e-3)  # 0.085 m is open: the finger's upper limit
    assert closed == pytest.approx(0.0, abs=1e-3) and finger == pytest.approx(0.0, abs=1e-3)


CDR_CHECK = """
from rclpy.serialization import serialize_message
from geometry_msgs.msg import TransformStamped
from tf2_msgs.msg import TFMessage
from rclpy.serialization import deserialize_message
from robocram.ros.tf_cdr import read_stamped_tf_message, read_tf_message, write_tf_message
transforms = []
for i in range(50):  # names of every length mod 4, so each alignment is crossed
    t = TransformStamped(child_frame_id="link" + "x" * i)
    t.header.frame_id, t.header.stamp.sec = ("map", "base_footprint")[i % 2], i
    t.header.stamp.nanosec = 0
    t.transform.translation.x, t.transform.translation.z = 0.1 * i, -2.0 * i
    t.transform.rotation.y, t.transform.rotation.w = 0.6, 0.8
    transforms.append(t)
want = [(t.header.frame_id, t.child_frame_id, (0.1 * i, 0.0, -2.0 * i), (0.0, 0.6, 0.0, 0.8))
        for i, t in enumerate(transforms)]
assert read_tf_message(serialize_message(TFMessage(transforms=transforms))) == want
assert read_tf_message(serialize_message(TFMessage())) == []
stamped = read_stamped_tf_message(serialize_message(TFMessage(transforms=transforms)))
assert [stamp for stamp, _ in stamped] == [float(i) for i in range(50)]
written = deserialize_message(write_tf_message((7, 9), want), TFMessage)
assert [t.header.stamp.sec for t in written.transforms] == [7] * 50
for t in transforms:
    t.header.stamp.sec, t.header.stamp.nanosec = 7, 9
assert written == TFMessage(transforms=transforms)  # every field, as rclpy reads our bytes
# rclpy leaves CDR's alignment padding unset (its bytes vary run to run; ours are zero):
# the same layout, and the same message read back from rclpy's bytes
theirs = serialize_message(written)
assert len(theirs) == len(write_tf_message((7, 9), want))
assert deserialize_message(theirs, TFMessage) == written
assert deserialize_message(write_tf_message((7, 9), []), TFMessage).transforms == []
"""


def test_tf_is_read_from_and_written_to_its_cdr_bytes_as_rclpy_does() -> None:
    environment = ros2_prefix().environment(0)
    subprocess.run(child_argv(CDR_CHECK), env=environment, check=True, timeout=60)


def test_a_point_head_controller_aims_the_camera_at_the_target(
    drivers2: DriverPool, tmp_path: Path
) -> None:
    facts = default_facts("pr2", ros=2).replace(
        "ros_action(pr2, head, '/head_controller/follow_joint_trajectory',\n"
        "           'control_msgs/FollowJointTrajectory').",
        "ros_action(pr2, head, '/head_controller/point_head', 'control_msgs/PointHead').",
    )
    assert "control_msgs/PointHead" in facts
    facts_file = tmp_path / "pr2_point_head.pl"
    facts_file.write_text(facts)
    target = Pose((1.5, 0.5, 0.6))  # [m] in map, ahead and to the left, low
    log = tmp_path / "goals.jsonl"
    serving = drivers2("pr2", ros_facts=facts_file, goal_log=log)
    with serving as driver, ros_robot("pr2", ros=2, ros_facts=facts) as run:
        pan_tilt = perform(a.motion(type="looking", target=a.location(pose=target)))
        camera = run.transforms.lookup("map", "wide_stereo_optical_frame")
        (goal,) = driver.received_goals("/head_controller/point_head")
    assert goal["target"]["point"] == pytest.approx({"x": 1.5, "y": 0.5, "z": 0.6})
    assert goal["pointing_frame"] == "wide_stereo_optical_frame"
    assert pan_tilt["head_pan_joint"] > 0.1 and pan_tilt["head_tilt_joint"] > 0.1  # left, down
    axis = camera.matrix()[:3, 2]  # the optical axis: z
    to_target = np.subtract(target.position, camera.position)
    assert float(axis @ to_target) / float(np.linalg.norm(to_target)) > 0.99  # aimed


def test_a_controller_killed_mid_goal_gives_a_typed_failure_in_bounded_time(
    drivers2: DriverPool,
) -> None:
    # gone from the graph after its lease, then LOST_AFTER more (the packaged facts: 2 s)
    facts = f"ros_connection_timeout(pr2, {LOST_AFTER}).\n" + default_facts("pr2", ros=2)
    with (
        drivers2("pr2", base_speed=0.3) as driver,
        ros_robot("pr2", ros=2, ros_facts=facts) as run,
    ):
        client = run.environment.client
        start = client.base_pose()
        killed: list[float] = []

        def kill_once_moving() -> None:
            while client.base_pose().distance_to(start) < MOVED:
                time.sleep(0.02)
            driver.kill()
            killed.append(time.monotonic())

        killer = threading.Thread(target=kill_once_moving)
        killer.start()
        try:
            with pytest.raises(RosConnectionLost) as lost:
                perform(a.motion(type="going", target=Pose((-2.0, 0.0, 0.0))))
        finally:
            killer.join()
        noticed = time.monotonic() - killed[0]
    assert lost.value.server == "/navigate_to_pose"
    assert "left the ROS graph" in str(lost.value)
    assert noticed < LEASE + LOST_AFTER + 1.5  # the dead process's lease, then LOST_AFTER
    assert multiprocessing.active_children() == []
