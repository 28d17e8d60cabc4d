"""Export a stored run to MCAP as ROS 2 messages, for Foxglove, Rerun or ``ros2 bag``.

For each stored world state (the run's start and every motion's end) it writes ``/tf``
(map -> every link of every robot and every object, flat), ``/joint_states`` (one
``sensor_msgs/JointState`` per articulated body, ``header.frame_id`` naming the body) and
``/object_poses/<name>`` (``geometry_msgs/PoseStamped`` in map). Link poses come from the
run's scene rebuilt in a fresh physics world and put into each stored state.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from robocram.tf import Pose
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.queries import require_run, world_state_times
from robocram.traces.ros2_messages import message_definition
from robocram.traces.world_record import StoredWorldState, build_scene, load_world_state
from robocram.world import World

MAP_FRAME = "map"


def export_mcap(db: TraceDatabase, run: int, out: str | Path) -> int:
    """Write run ``run`` of ``db`` to the MCAP file ``out``; return the messages written."""
    try:
        from mcap_ros2.writer import Writer
    except ImportError as err:
        raise TraceError(
            "MCAP export needs the mcap and mcap-ros2-support packages: "
            "pip install 'robocram[mcap]'"
        ) from err
    scene = require_run(db, run).scene
    if scene is None:
        raise TraceError(f"run {run} stored no scene; trace with trace_to(db, world=world)")
    with db.read() as session:
        states = [load_world_state(session, i) for i, _, _ in world_state_times(db, run)]
    written = 0
    with build_scene(scene) as world, open(out, "wb") as stream:
        writer = Writer(stream)
        schemas = {
            name: writer.register_msgdef(name, message_definition(name))
            for name in (
                "tf2_msgs/TFMessage",
                "sensor_msgs/JointState",
                "geometry_msgs/PoseStamped",
            )
        }
        for state in states:
            state.apply(world)
            for topic, schema, message in _messages(world, state):
                stamp = int(round(state.time * 1e9))  # [ns] since the epoch
                writer.write_message(topic, schemas[schema], message, log_time=stamp)
                written += 1
        writer.finish()
    return written


def _messages(world: World, state: StoredWorldState) -> list[tuple[str, str, dict[str, Any]]]:
    header = _header(state.time, MAP_FRAME)
    transforms = [
        {"header": header, "child_frame_id": frame, "transform": _transform(pose)}
        for frame, pose in _frames(world).items()
    ]
    out: list[tuple[str, str, dict[str, Any]]] = [
        ("/tf", "tf2_msgs/TFMessage", {"transforms": transforms})
    ]
    for body, joints in state.joints.items():
        names = list(joints)
        message = {
            "header": _header(state.time, body),
            "name": names,
            "position": [joints[n] for n in names],
            "velocity": [],
            "effort": [],
        }
        out.append(("/joint_states", "sensor_msgs/JointState", message))
    for name, pose in state.poses.items():
        message = {"header": header, "pose": _pose(pose)}
        out.append((f"/object_poses/{name}", "geometry_msgs/PoseStamped", message))
    return out


def _frames(world: World) -> dict[str, Pose]:
    """map_T_frame of every object root and every link of an articulated body."""
    frames: dict[str, Pose] = {}
    for obj in world.objects():
        frames[obj.name] = world.pose(obj)
        for link in world.link_names(obj)[1:]:
            frames.setdefault(link, world.link_pose(obj, link))
    return frames


def _header(time: float, frame: str) -> dict[str, Any]:
    sec = int(time // 1)
    nanosec = min(int(round((time - sec) * 1e9)), 999_999_999)
    return {"stamp": {"sec": sec, "nanosec": nanosec}, "frame_id": frame}


def _transform(pose: Pose) -> dict[str, Any]:
    (x, y, z), (qx, qy, qz, qw) = pose.position, pose.orientation
    return {
        "translation": {"x": x, "y": y, "z": z},
        "rotation": {"x": qx, "y": qy, "z": qz, "w": qw},
    }


def _pose(pose: Pose) -> dict[str, Any]:
    (x, y, z), (qx, qy, qz, qw) = pose.position, pose.orientation
    return {
        "position": {"x": x, "y": y, "z": z},
        "orientation": {"x": qx, "y": qy, "z": qz, "w": qw},
    }
