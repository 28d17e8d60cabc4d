"""MCAP export that Foxglove shows as a robot: the URDF's TF tree, /tf_static,
/robot_description and the objects' shapes, all read back with the mcap reader and the
ROS 2 decoder."""

from __future__ import annotations

import json
import shutil
import sqlite3
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory

from robocram.execution import top_level
from robocram.robots import RobotModel
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.traces import (
    MissingRobotDescription,
    TraceDatabase,
    build_scene,
    export_mcap,
    replay_frames,
    require_run,
    trace_to,
)
from robocram.world import RobotObject, World

TOL = 1e-6  # [m] and [rad]
ODOM = "odom_combined"  # the PR2 description's odom frame


def _read(path: Path) -> dict[str, list[tuple[str, int, Any]]]:
    """Per topic: (schema name, log time [ns], decoded message), in log order."""
    by_topic: dict[str, list[tuple[str, int, Any]]] = {}
    with path.open("rb") as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        for schema, channel, message, decoded in reader.iter_decoded_messages():
            by_topic.setdefault(channel.topic, []).append((schema.name, message.log_time, decoded))
    return by_topic


def _pose(transform: Any) -> Pose:
    t, q = transform.translation, transform.rotation
    return Pose((t.x, t.y, t.z), (q.x, q.y, q.z, q.w))


def _in_map(frame: str, edges: dict[str, tuple[str, Pose]]) -> Pose:
    """map_T_frame by walking the tree's parents up to map."""
    pose = Pose()
    while frame != "map":
        parent, parent_T_frame = edges[frame]
        pose = parent_T_frame * pose
        frame = parent
    return pose


def _frame_of(world: World, obj: Any, link: str) -> str:
    """The TF frame of ``link``: a robot's links by name, another body's root by its object."""
    if isinstance(obj, RobotObject) or link != world.link_names(obj)[0]:
        return link
    return str(obj.name)


def _links(world: World) -> list[tuple[Any, str]]:
    return [(obj, link) for obj in world.objects() for link in world.link_names(obj) or [obj.name]]


def _link_pose(world: World, obj: Any, link: str) -> Pose:
    return world.link_pose(obj, link) if world.link_names(obj) else world.pose(obj)


@dataclass
class KitchenTrace:
    """A run that only starts, in the kitchen with a door and a drawer open."""

    db_path: Path
    run: int


@pytest.fixture(scope="module")
def kitchen_trace(tmp_path_factory: pytest.TempPathFactory) -> KitchenTrace:
    scene = kitchen_scene("pr2")
    opened = {"cupboard_door_joint": 0.8, "drawer_unit_drawer_1_joint": 0.2}  # [rad], [m]
    scene.world.set_joint_states("kitchen", opened)
    db_path = tmp_path_factory.mktemp("kitchen") / "runs.db"
    try:
        with trace_to(db_path, world=scene.world) as tracer, top_level(name="look"):
            pass
    finally:
        scene.world.close()
    return KitchenTrace(db_path, tracer.runs[0])


@pytest.fixture(scope="module", params=["pick_up_trace", "trajectory_run", "kitchen_trace"])
def every_export(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    """(trace, MCAP file read back) of a pick-up, a run with trajectories, the kitchen."""
    trace = request.getfixturevalue(request.param)
    out = tmp_path_factory.mktemp("mcap") / "run.mcap"
    with TraceDatabase(trace.db_path, create=False) as db:
        export_mcap(db, trace.run, out, period=0.1)
    return trace, _read(out)


@pytest.fixture(scope="module", params=["pick_up_trace", "trajectory_run"])
def exported(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> Any:
    """(trace, MCAP file read back) of a pick-up, and of a run with trajectories."""
    trace = request.getfixturevalue(request.param)
    out = tmp_path_factory.mktemp("mcap") / "run.mcap"
    with TraceDatabase(trace.db_path, create=False) as db:
        export_mcap(db, trace.run, out, period=0.1)
    return trace, _read(out)


def test_the_tf_tree_gives_every_recorded_link_pose(every_export: Any) -> None:
    trace, by_topic = every_export
    ((_, static_stamp, static),) = by_topic["/tf_static"]
    edges = {t.child_frame_id: (t.header.frame_id, _pose(t.transform)) for t in static.transforms}
    tf = by_topic["/tf"]
    assert static_stamp == tf[0][1]  # latched at the run's start
    worst = (0.0, 0.0)
    with TraceDatabase(trace.db_path, create=False) as db:
        scene = require_run(db, trace.run).scene
        with build_scene(scene) as world:
            frames = replay_frames(db, trace.run, world, period=0.1)
            for _, (_, _, message) in zip(frames, tf, strict=True):  # one /tf per frame
                for t in message.transforms:
                    edges[t.child_frame_id] = (t.header.frame_id, _pose(t.transform))
                for obj, link in _links(world):
                    got = _in_map(_frame_of(world, obj, link), edges)
                    want = _link_pose(world, obj, link)
                    error = float(np.linalg.norm(np.subtract(got.position, want.position)))
                    worst = (max(worst[0], error), max(worst[1], got.angle_to(want)))
    assert worst[0] <= TOL and worst[1] <= TOL, worst


def test_the_tree_has_the_urdf_structure(exported: Any) -> None:
    trace, by_topic = exported
    static = {t.child_frame_id: t.header.frame_id for t in by_topic["/tf_static"][0][2].transforms}
    moving = {t.child_frame_id: t.header.frame_id for t in by_topic["/tf"][0][2].transforms}
    assert not set(static) & set(moving)  # each frame on one topic
    parents = static | moving
    model = trace.world.robot("pr2").description.model
    for joint in model.joints.values():
        assert parents[joint.child] == joint.parent, joint.name
        assert (joint.child in static) == (not joint.movable), joint.name
    objects = {obj.name for obj in trace.world.objects() if not isinstance(obj, RobotObject)}
    assert {child for child, parent in parents.items() if parent == "map"} == objects | {ODOM}
    assert [child for child, parent in parents.items() if parent == ODOM] == [model.root_link]
    assert static[ODOM] == "map" and model.root_link in moving
    for _, _, message in by_topic["/tf"]:  # every moment sends every moving frame
        assert {t.child_frame_id for t in message.transforms} == set(moving)


def test_robot_description_is_the_robots_urdf(exported: Any) -> None:
    trace, by_topic = exported
    ((schema, stamp, message),) = by_topic["/robot_description"]
    assert schema == "std_msgs/msg/String" and stamp == by_topic["/tf"][0][1]
    parsed = RobotModel.from_string(message.data)
    model = trace.world.robot("pr2").description.model
    assert set(parsed.links) == set(model.links) and parsed.root_link == model.root_link
    for name, joint in model.joints.items():
        other = parsed.joints[name]
        assert (other.parent, other.child, other.type) == (joint.parent, joint.child, joint.type)
        assert other.origin.position == pytest.approx(joint.origin.position, abs=1e-12)


def test_objects_are_drawn_as_markers_in_their_frames(exported: Any) -> None:
    _, by_topic = exported
    ((schema, _, message),) = by_topic["/scene_markers"]
    assert schema == "visualization_msgs/msg/MarkerArray"
    markers = {m.ns: m for m in message.markers}
    assert set(markers) == {"floor", "table", "mug-1", "bottle-1"}  # not the robot
    table, bottle, mug = markers["table"], markers["bottle-1"], markers["mug-1"]
    assert (table.type, table.header.frame_id) == (1, "table")  # CUBE
    assert (table.scale.x, table.scale.y, table.scale.z) == pytest.approx((0.6, 1.0, 0.615675))
    assert (bottle.type, bottle.header.frame_id) == (3, "bottle-1")  # CYLINDER
    assert (bottle.scale.x, bottle.scale.z) == pytest.approx((0.07, 0.25))
    assert (mug.type, mug.header.frame_id) == (11, "mug-1")  # TRIANGLE_LIST: embedded
    assert mug.mesh_resource == "" and len(mug.points) % 3 == 0 and len(mug.points) > 30
    assert all(m.frame_locked for m in message.markers)


def test_the_robot_is_drawn_from_embedded_meshes_in_its_link_frames(exported: Any) -> None:
    """Another machine, without the mesh files, shows the robot: every link visual of the
    URDF is a marker in the link's frame, a mesh as its triangles (no file named)."""
    trace, by_topic = exported
    ((_, _, message),) = by_topic["/robot_meshes"]
    with TraceDatabase(trace.db_path, create=False) as db:
        world = build_scene(require_run(db, trace.run).scene)
    model = world.robots()[0].description.model
    visuals = sum(len(link.visuals) for link in model.links.values())
    meshes = [m for m in message.markers if m.type == 11]
    assert len(message.markers) == visuals and len(meshes) >= 40  # the PR2: 45 meshes
    assert all(m.mesh_resource == "" and len(m.points) % 3 == 0 for m in meshes)
    assert {m.header.frame_id for m in message.markers} <= set(model.links)
    points = sum(len(m.points) for m in meshes)
    assert 3 * 27_000 < points < 3 * 28_000  # the PR2's visual triangles, every one
    world.close()


def test_every_schema_is_a_ros2_name(exported: Any) -> None:
    _, by_topic = exported
    names = {schema for messages in by_topic.values() for schema, _, _ in messages}
    assert names == {
        "tf2_msgs/msg/TFMessage",
        "sensor_msgs/msg/JointState",
        "geometry_msgs/msg/PoseStamped",
        "std_msgs/msg/String",
        "visualization_msgs/msg/MarkerArray",
    }


def test_an_older_trace_exports_without_robot_description(
    pick_up_trace: Any, tmp_path: Path
) -> None:
    old = tmp_path / "v4.db"
    shutil.copy(pick_up_trace.db_path, old)
    with sqlite3.connect(old) as con:  # what robocram wrote before it stored URDFs
        con.execute("DROP TABLE robot_models")
        con.execute("UPDATE schema_info SET version = 4")
        (scene,) = con.execute(
            "SELECT scene FROM runs WHERE id = ?", (pick_up_trace.run,)
        ).fetchone()
        recipes = [{k: v for k, v in r.items() if k != "urdf_digest"} for r in json.loads(scene)]
        con.execute("UPDATE runs SET scene = ?", (json.dumps(recipes),))
    out = tmp_path / "old.mcap"
    with (
        TraceDatabase(old, create=False) as db,
        pytest.warns(MissingRobotDescription, match="older"),
    ):
        export_mcap(db, pick_up_trace.run, out)
    by_topic = _read(out)
    assert "/robot_description" not in by_topic and len(by_topic["/tf_static"]) == 1
