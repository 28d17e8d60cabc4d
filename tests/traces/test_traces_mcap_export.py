"""MCAP export: a run's TF, joint states and object poses as ROS 2 messages, read back."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

from robocram.cli import EXIT_OK, main
from robocram.traces import TraceDatabase, world_state_times
from robocram.traces.ros2_messages import message_definition

TOL = 1e-9


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
    with out.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        messages = list(reader.iter_decoded_messages())
    by_topic: dict[str, list[Any]] = {}
    for schema, channel, message, decoded in messages:
        by_topic.setdefault(channel.topic, []).append((schema.name, message.log_time, decoded))
    assert len(by_topic["/tf"]) == len(states)
    assert [t for _, t, _ in by_topic["/tf"]] == [round(t * 1e9) for _, t, _ in states]
    assert {schema.name for schema, *_ in messages} == {
        "tf2_msgs/TFMessage",
        "sensor_msgs/JointState",
        "geometry_msgs/PoseStamped",
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
    assert "r_gripper_tool_frame" in frames and frames["mug-1"].header.frame_id == "map"
    assert frames["mug-1"].transform.translation.z == pytest.approx(mug.z, abs=TOL)


def test_message_definitions_list_their_dependencies() -> None:
    text = message_definition("tf2_msgs/TFMessage")
    assert text.startswith("geometry_msgs/TransformStamped[] transforms\n")
    for dep in ("geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time"):
        assert f"MSG: {dep}\n" in text
    with pytest.raises(KeyError, match="known"):
        message_definition("nav_msgs/Odometry")
