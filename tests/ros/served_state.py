"""What a driver serves, read by a plain rospy or rclpy node of its own (not our client):
one message of each joint state topic, one of ``/tf`` and the latched ``/tf_static``;
on ROS 2 also the topics and services of the driver's node (``publishes``, ``serves``)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from robocram.ros.ros2_environment import child_argv, ros2_prefix

Served = dict[str, dict[str, list[float]]]  # topic -> joint or "parent>child" -> numbers

ROS1_READER = """
import json, sys, rospy
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
rospy.init_node("robocram_served_state", anonymous=True, disable_signals=True)
out = {}
for topic in json.loads(sys.argv[1]):
    m = rospy.wait_for_message(topic, JointState, 30)
    out[topic] = {n: [p] for n, p in zip(m.name, m.position)}
for topic in ("/tf", "/tf_static"):
    m = rospy.wait_for_message(topic, TFMessage, 30)
    out[topic] = {
        t.header.frame_id + ">" + t.child_frame_id: [
            t.transform.translation.x, t.transform.translation.y, t.transform.translation.z,
            t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
            t.transform.rotation.w,
        ] for t in m.transforms
    }
print("SERVED" + json.dumps(out))
rospy.signal_shutdown("read")
"""

ROS2_READER = """
import json, sys, threading, rclpy
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState
from tf2_msgs.msg import TFMessage
rclpy.init()
node = rclpy.create_node("robocram_served_state")
out, subs = {}, []
topics = json.loads(sys.argv[1])
def joints(topic):
    return lambda m: out.setdefault(topic, {n: [p] for n, p in zip(m.name, m.position)})
def tf(topic):
    return lambda m: out.setdefault(topic, {
        t.header.frame_id + ">" + t.child_frame_id: [
            t.transform.translation.x, t.transform.translation.y, t.transform.translation.z,
            t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
            t.transform.rotation.w,
        ] for t in m.transforms
    })
for topic in topics:
    subs.append(node.create_subscription(JointState, topic, joints(topic), 10))
subs.append(node.create_subscription(TFMessage, "/tf", tf("/tf"), 10))
static = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
subs.append(node.create_subscription(TFMessage, "/tf_static", tf("/tf_static"), static))
want = len(topics) + 2
for _ in range(3000):  # every topic heard and the driver's node discovered
    if len(out) == want and "robocram_driver" in node.get_node_names():
        break
    rclpy.spin_once(node, timeout_sec=0.01)
graph = {"publishes": node.get_publisher_names_and_types_by_node,
         "serves": node.get_service_names_and_types_by_node}
for kind, names in graph.items():
    out[kind] = {name: [] for name, _ in names("robocram_driver", "/")}
print("SERVED" + json.dumps(out))
node.destroy_node()
rclpy.shutdown()
"""


def served_state(
    joint_topics: list[str], master_uri: str = "", domain: int | None = None
) -> Served:
    """The driver's state on ``joint_topics``, ``/tf`` and ``/tf_static``: on the ROS 1
    master at ``master_uri``, or on ROS 2 ``domain``."""
    if domain is None:
        argv = [sys.executable, "-c", ROS1_READER, json.dumps(joint_topics)]
        env = dict(os.environ, ROS_MASTER_URI=master_uri)
    else:
        argv = [*child_argv(ROS2_READER), json.dumps(joint_topics)]
        env = ros2_prefix().environment(domain)
    done = subprocess.run(argv, env=env, capture_output=True, text=True, timeout=90)
    assert done.returncode == 0, done.stderr[-3000:]
    (line,) = [x for x in done.stdout.splitlines() if x.startswith("SERVED")]
    served: Served = json.loads(line.removeprefix("SERVED"))
    graph = set() if domain is None else {"publishes", "serves"}
    assert set(served) == {*joint_topics, "/tf", "/tf_static", *graph}, served.keys()
    return served


def assert_same_state(got: Served, want: Served, within: float) -> None:
    """The same topics, names and numbers, each within ``within``."""
    assert got.keys() == want.keys()
    for topic, values in want.items():
        assert got[topic].keys() == values.keys(), topic
        for name, numbers in values.items():
            assert got[topic][name] == pytest.approx(numbers, abs=within), (topic, name)
