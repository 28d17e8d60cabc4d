"""Export a stored run to MCAP as ROS 2 messages, for Foxglove, rviz2 or ``ros2 bag``.

What a real robot would send, so that Foxglove shows the robot and its world:

- ``/tf_static`` once, at the run's start: fixed joints and each robot's odom frame at
  ``map`` (:mod:`~robocram.traces.tf_frames`);
- ``/robot_description`` once (``std_msgs/msg/String``): the URDF the trace stored for
  the run's robot; a trace of an older robocram has none, and the export warns;
- ``/scene_markers`` once (``visualization_msgs/msg/MarkerArray``): the objects' shapes
  (:mod:`~robocram.traces.scene_markers`), meshes embedded as triangles;
- ``/robot_meshes`` once (``MarkerArray``): every robot link's visuals, embedded, in the
  link's TF frame, so the robot shows on a machine without its mesh files;
- at each stored world state (the run's start and every motion's end): ``/tf`` (each
  body's root and movable joints), ``/joint_states`` (one per articulated body,
  ``header.frame_id`` naming the body) and ``/object_poses/<name>`` in map;
- between them, along each executed trajectory sampled every ``period``: ``/tf`` and the
  moving robot's ``/joint_states``, so a player shows the motion.

Link poses come from the run's scene rebuilt in a fresh physics world
(:func:`~robocram.traces.run_replay.replay_frames`). Messages are stamped on the run's
replay clock (``traces/replay_clock.py``): wall time, stretched where projection executed
a trajectory faster than its duration.
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from robocram.traces.database import TraceDatabase
from robocram.traces.errors import MissingRobotDescription, TraceError
from robocram.traces.queries import require_run
from robocram.traces.robot_model_record import stored_urdf
from robocram.traces.ros2_messages import message_definition
from robocram.traces.ros2_values import Value, header, pose_value, transform
from robocram.traces.run_replay import SAMPLE_PERIOD, ReplayFrame, replay_frames, robot_in
from robocram.traces.scene_markers import robot_markers, scene_markers
from robocram.traces.tf_frames import (
    MAP_FRAME,
    BodyFrames,
    Transform,
    moving_transforms,
    static_transforms,
    world_frames,
)
from robocram.traces.trajectory_record import run_trajectories
from robocram.traces.world_record import build_scene
from robocram.world import World

if TYPE_CHECKING:  # mcap-ros2 is imported where an export needs it
    from mcap_ros2.writer import Writer as McapWriter

TF = "tf2_msgs/msg/TFMessage"
JOINT_STATE = "sensor_msgs/msg/JointState"
POSE_STAMPED = "geometry_msgs/msg/PoseStamped"
STRING = "std_msgs/msg/String"
MARKER_ARRAY = "visualization_msgs/msg/MarkerArray"
SCHEMAS = (TF, JOINT_STATE, POSE_STAMPED, STRING, MARKER_ARRAY)

Message = tuple[str, str, Value]  # topic, schema name, message


def export_mcap(
    db: TraceDatabase,
    run: int,
    out: str | Path,
    period: float = SAMPLE_PERIOD,
    robots: Mapping[str, str] | None = None,
) -> int:
    """Write run ``run`` of ``db`` to the MCAP file ``out``; return the messages written.

    Trajectories are sampled every ``period`` [s] of motion time. ``robots``: description
    files by robot name, for robots whose file moved since the run (see
    :func:`~robocram.traces.world_record.build_scene`).

    The file appears only once it is whole: written beside ``out`` first, then renamed.

    Raises:
        DamagedTrajectory: a stored trajectory of the run is damaged (nothing is written).

    Warns:
        MissingRobotDescription: the trace stored no URDF of the run's robot (written by
            an older robocram); the rest is exported without ``/robot_description``.
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
    urdf = _robot_description(db, run, row.scene)
    run_trajectories(db, run)  # a damaged row is refused before any file is made
    target = Path(out)
    part = target.with_name(f".{target.name}.part")
    try:
        written = _write(db, run, row.scene, urdf, part, period, Writer, robots)
        part.replace(target)
    finally:
        part.unlink(missing_ok=True)  # no stub is left where the export failed
    return written


def _write(
    db: TraceDatabase,
    run: int,
    scene: str,
    urdf: str | None,
    out: Path,
    period: float,
    writer_class: type[McapWriter],
    robots: Mapping[str, str] | None,
) -> int:
    """Write the run's messages to ``out``; return how many."""
    written = 0
    with build_scene(scene, robots=robots, db=db) as world, open(out, "wb") as stream:
        writer = writer_class(stream)
        schemas = {name: writer.register_msgdef(name, message_definition(name)) for name in SCHEMAS}
        bodies = world_frames(world)
        for index, frame in enumerate(replay_frames(db, run, world, period)):
            messages = _frame_messages(world, bodies, frame)
            if index == 0:
                messages = _once(world, bodies, frame.time, urdf) + messages
            stamp = int(round(frame.time * 1e9))  # [ns] since the epoch, replay clock
            for topic, schema, message in messages:
                writer.write_message(topic, schemas[schema], message, log_time=stamp)
                written += 1
        writer.finish()
    return written


def _robot_description(db: TraceDatabase, run: int, scene: str) -> str | None:
    """The stored URDF of the scene's (first) robot; ``None``, with a warning, if absent."""
    robots = [recipe for recipe in json.loads(scene) if "robot" in recipe]
    if not robots:
        return None
    digest = robots[0].get("urdf_digest")
    urdf = None if digest is None else stored_urdf(db, digest)
    if urdf is None:
        warnings.warn(MissingRobotDescription(run, robots[0]["robot"]), stacklevel=3)
    return urdf


def _once(world: World, bodies: list[BodyFrames], time: float, urdf: str | None) -> list[Message]:
    """The latched messages: fixed transforms, the robot's URDF, the objects' shapes."""
    once = [("/tf_static", TF, _tf_message(static_transforms(bodies), time))]
    if urdf is not None:
        once.append(("/robot_description", STRING, {"data": urdf}))
    once.append(("/scene_markers", MARKER_ARRAY, scene_markers(world, bodies, time)))
    once.append(("/robot_meshes", MARKER_ARRAY, robot_markers(world, bodies, time)))
    return once


def _frame_messages(world: World, bodies: list[BodyFrames], frame: ReplayFrame) -> list[Message]:
    """A stored state: TF, every body's joints, object poses; a sample: TF, the robot's joints."""
    tf = ("/tf", TF, _tf_message(moving_transforms(world, bodies), frame.time))
    if frame.state is None:
        assert frame.trajectory is not None  # a frame is a state or a sample
        robot = robot_in(world, frame.trajectory.robot)
        return [tf, _joint_state(robot, world.joint_states(robot), frame.time)]
    out = [tf]
    out += [_joint_state(body, joints, frame.time) for body, joints in frame.state.joints.items()]
    stamp = header(frame.time, MAP_FRAME)
    for name, pose in frame.state.poses.items():
        message: Value = {"header": stamp, "pose": pose_value(pose)}
        out.append((f"/object_poses/{name}", POSE_STAMPED, message))
    return out


def _tf_message(transforms: Iterable[Transform], time: float) -> Value:
    return {
        "transforms": [
            {"header": header(time, parent), "child_frame_id": child, "transform": transform(pose)}
            for parent, child, pose in transforms
        ]
    }


def _joint_state(body: str, joints: dict[str, float], time: float) -> Message:
    names = list(joints)
    message: Value = {
        "header": header(time, body),
        "name": names,
        "position": [joints[n] for n in names],
        "velocity": [],
        "effort": [],
    }
    return ("/joint_states", JOINT_STATE, message)
