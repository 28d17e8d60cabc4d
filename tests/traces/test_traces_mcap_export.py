"""MCAP export: a run's TF, joint states and object poses as ROS 2 messages, read back;
executed trajectories sampled between the states."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

from robocram.cli import EXIT_OK, main
from robocram.traces import (
    TraceDatabase,
    export_mcap,
    replay_clock,
    require_run,
    run_trajectories,
    world_state_times,
)
from robocram.traces.ros2_messages import message_definition

TOL = 1e-9
NS = 2_000  # [ns] stamps are float seconds since the epoch: ~0.2 us apart at worst


def test_export_writes_every_state(
    pick_up_trace: Any, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "run.mcap"
    code = main(
        [
            "runs",
            "export",
            str(pick_up_trace.db_path),
            "--run",
            str(pick_up_trace.run),
            "--mcap",
            str(out),
        ]
    )
    assert code == EXIT_OK and "messages of run" in capsys.readouterr().out
    with TraceDatabase(pick_up_trace.db_path, create=False) as db:
        states = world_state_times(db, pick_up_trace.run)
        clock = replay_clock(db, pick_up_trace.run)
        moved = [t for t in run_trajectories(db, pick_up_trace.run) if t.points]
    with out.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        messages = list(reader.iter_decoded_messages())
    by_topic: dict[str, list[Any]] = {}
    for schema, channel, message, decoded in messages:
        by_topic.setdefault(channel.topic, []).append((schema.name, message.log_time, decoded))
    samples = sum(int(np.ceil(t.duration / 0.05)) + 1 for t in moved)  # every 0.05 s, the end
    assert len(by_topic["/tf"]) == len(states) + samples
    state_stamps = [t for _, t, _ in by_topic["/object_poses/mug-1"]]  # written at states only
    assert state_stamps == [round(clock.at(t) * 1e9) for _, t, _ in states]
    assert {schema.name for schema, *_ in messages} >= {
        "tf2_msgs/msg/TFMessage",
        "sensor_msgs/msg/JointState",
        "geometry_msgs/msg/PoseStamped",
    }
    final = pick_up_trace.final
    joint_states = [m for _, _, m in by_topic["/joint_states"] if m.header.frame_id == "pr2"]
    last_joints = joint_states[-1]
    stored = final.joints["pr2"]
    assert sorted(last_joints.name) == sorted(stored)
    assert (
        max(abs(a - stored[n]) for n, a in zip(last_joints.name, last_joints.position, strict=True))
        <= TOL
    )
    mug = by_topic["/object_poses/mug-1"][-1][2].pose.position
    assert (mug.x, mug.y, mug.z) == pytest.approx(final.poses["mug-1"].position, abs=TOL)
    frames = {t.child_frame_id: t for t in by_topic["/tf"][-1][2].transforms}
    static = {t.child_frame_id: t for t in by_topic["/tf_static"][0][2].transforms}
    assert static["r_gripper_tool_frame"].header.frame_id == "r_gripper_palm_link"  # fixed joint
    assert frames["mug-1"].header.frame_id == "map"
    assert frames["mug-1"].transform.translation.z == pytest.approx(mug.z, abs=TOL)


def test_message_definitions_list_their_dependencies() -> None:
    text = message_definition("tf2_msgs/msg/TFMessage")
    assert text.startswith("geometry_msgs/TransformStamped[] transforms\n")
    for dep in ("geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time"):
        assert f"MSG: {dep}\n" in text
    with pytest.raises(KeyError, match="known"):
        message_definition("nav_msgs/Odometry")


def _read(path: Path) -> dict[str, list[tuple[int, Any]]]:
    by_topic: dict[str, list[tuple[int, Any]]] = {}
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for _, channel, message, decoded in reader.iter_decoded_messages():
            by_topic.setdefault(channel.topic, []).append((message.log_time, decoded))
    return by_topic


def _last_per_moment(messages: list[tuple[int, Any]]) -> list[tuple[int, Any]]:
    """The last message of each moment: a trajectory's first sample follows the state it
    starts from at the same time (within float rounding)."""
    kept: list[tuple[int, Any]] = []
    for stamp, message in messages:
        if kept and stamp - kept[-1][0] <= NS:
            kept[-1] = (stamp, message)
        else:
            kept.append((stamp, message))
    return kept


def test_export_plays_the_trajectories(trajectory_run: Any, tmp_path: Path) -> None:
    out = tmp_path / "motion.mcap"
    period = 0.1  # [s]
    with TraceDatabase(trajectory_run.db_path, create=False) as db:
        export_mcap(db, trajectory_run.run, out, period=period)
        stored = run_trajectories(db, trajectory_run.run)
        run_start = require_run(db, trajectory_run.run).start
    by_topic = _read(out)
    joint_states = _last_per_moment(
        [(t, m) for t, m in by_topic["/joint_states"] if m.header.frame_id == "pr2"]
    )
    arm = next(s for s in stored if s.kind == "arm")
    begin = round((run_start + arm.start) * 1e9)
    end = begin + round(arm.duration * 1e9)
    along = [(t, m) for t, m in joint_states if begin - NS <= t <= end + NS]
    samples = int(np.ceil(arm.duration / period)) + 1
    assert len(along) == samples  # every 0.1 s, and the end
    for k, (stamp, message) in enumerate(along):
        t = min(k * period, arm.duration)
        assert stamp == pytest.approx((run_start + arm.start + t) * 1e9, abs=NS)
        assert message.header.stamp.sec + message.header.stamp.nanosec * 1e-9 == pytest.approx(
            stamp * 1e-9, abs=1e-6
        )
        positions = dict(zip(message.name, message.position, strict=True))
        expected = trajectory_run.arm.at(t)
        got = [positions[n] for n in arm.joint_names]
        assert np.allclose(got, expected, atol=1e-6)
    base = next(s for s in stored if s.kind == "base")
    begin = round((run_start + base.start) * 1e9)
    end = begin + round(base.duration * 1e9)
    tf = [(t, m) for t, m in _last_per_moment(by_topic["/tf"]) if begin - NS <= t <= end + NS]
    assert len(tf) == int(np.ceil(base.duration / period)) + 1
    for k, (_, message) in enumerate(tf):
        x, y, yaw = trajectory_run.base.at(min(k * period, base.duration))
        root = next(f for f in message.transforms if f.child_frame_id == "base_footprint")
        assert root.header.frame_id == "odom_combined"  # at map: projection's odometry is exact
        assert (root.transform.translation.x, root.transform.translation.y) == pytest.approx(
            (x, y), abs=1e-6
        )
        q = root.transform.rotation
        assert 2 * np.arctan2(q.z, q.w) == pytest.approx(yaw, abs=1e-6)
    stamps = [t for t, _ in by_topic["/tf"]]
    assert stamps == sorted(stamps)  # states and samples on one clock
