"""Export a stored run to MCAP as ROS 2 messages, for Foxglove, Rerun or ``ros2 bag``.

For each stored world state (the run's start and every motion's end) it writes ``/tf``
(map -> every link of every robot and every object, flat), ``/joint_states`` (one
``sensor_msgs/JointState`` per articulated body, ``header.frame_id`` naming the body) and
``/object_poses/<name>`` (``geometry_msgs/PoseStamped`` in map). Between them, along each
executed trajectory sampled every ``period``, it writes ``/tf`` and the moving robot's
``/joint_states``, so a player shows the motion; a base trajectory moves the robot's root
frame (map -> robot). Link poses come from the run's scene rebuilt in a fresh physics world
(:func:`~robocram.traces.run_replay.replay_frames`). Messages are stamped on the run's
replay clock (``traces/replay_clock.py``): wall time, stretched where projection executed a
trajectory faster than its duration.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from robocram.tf import Pose
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.queries import require_run
from robocram.traces.ros2_messages import message_definition
from robocram.traces.run_replay import SAMPLE_PERIOD, ReplayFrame, replay_frames, robot_in
from robocram.traces.world_record import StoredWorldState, build_scene
from robocram.world import World

MAP_FRAME = "map"


def export_mcap(db: TraceDatabase, run: int, out: str | Path, period: float = SAMPLE_PERIOD) -> int:
    """Write run ``run`` of ``db`` to the MCAP file ``out``; return the messages written.

    Trajectories are sampled every ``period`` [s] of motion time.
    """
    try:
        from mcap_ros2.writer import Writer
    except ImportError as err:
        raise TraceError(
            "MCAP export needs the mcap and mcap-ros2-support packages: "
            "pip install 'robocram[mcap]'"
        ) from err
    row = require_run(db, run)
    if row.scene is None:
        raise TraceError(f"run {run} stored no scene; trace with trace_to(db, world=world)")
    written = 0
    with build_scene(row.scene) as world, open(out, "wb") as stream:
        writer = Writer(stream)
        schemas = {
            name: writer.register_msgdef(name, message_definition(name))
            for name in (
                "tf2_msgs/TFMessage",
                "sensor_msgs/JointState",
                "geometry_msgs/PoseStamped",
            )
        }
        for frame in replay_frames(db, run, world, period):
            stamp = int(round(frame.time * 1e9))  # [ns] since the epoch, replay clock
            for topic, schema, message in _frame_messages(world, frame, frame.time):
                writer.write_message(topic, schemas[schema], message, log_time=stamp)
                written += 1
        writer.finish()
    return written


Message = tuple[str, str, dict[str, Any]]  # topic, schema name, message


def _frame_messages(world: World, frame: ReplayFrame, time: float) -> list[Message]:
    """A stored state: TF, every body's joints, object poses; a sample: TF, the robot's joints."""
    if frame.state is not None:
        return _messages(world, frame.state, time)
    assert frame.trajectory is not None  # a frame is a state or a sample
    robot = robot_in(world, frame.trajectory.robot)
    return [_tf(world, time), _joint_state(robot, world.joint_states(robot), time)]


def _tf(world: World, time: float) -> Message:
    header = _header(time, MAP_FRAME)
    transforms = [
        {"header": header, "child_frame_id": frame, "transform": _transform(pose)}
        for frame, pose in _frames(world).items()
    ]
    return ("/tf", "tf2_msgs/TFMessage", {"transforms": transforms})


def _joint_state(body: str, joints: dict[str, float], time: float) -> Message:
    names = list(joints)
    message = {
        "header": _header(time, body),
        "name": names,
        "position": [joints[n] for n in names],
        "velocity": [],
        "effort": [],
    }
    return ("/joint_states", "sensor_msgs/JointState", message)


def _messages(world: World, state: StoredWorldState, time: float) -> list[Message]:
    header = _header(time, MAP_FRAME)
    out = [_tf(world, time)]
    out += [_joint_state(body, joints, time) for body, joints in state.joints.items()]
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
