"""The shapes of a run's bodies as ``visualization_msgs/msg/MarkerArray`` s.

Markers, not ``foxglove.SceneUpdate``: they are ROS 2 messages like every other topic of
the export (one ``ros2msg``/CDR encoding, one writer), and rviz2, ``ros2 bag`` and Foxglove
all show them. Each marker sits in its object's (or link's) TF frame, so it moves with
``/tf`` and is sent once. The shapes are the recipes the trace stored: a shape's box,
cylinder or sphere, a mesh file, a URDF object's or a robot's link visuals.

A mesh is embedded, its triangles in the marker (``TRIANGLE_LIST``), not named by a file
path: a path into the exporting machine's checkout or ``.venv`` showed nothing on another
machine (issue 41). The robot's links go to a topic of their own (:func:`robot_markers`),
beside ``/robot_description`` for tools that read the URDF.
"""

from __future__ import annotations

from pathlib import Path

from robocram.robots import Geometry
from robocram.tf import Pose
from robocram.traces.mesh_triangles import MeshBox, mesh_triangles
from robocram.traces.ros2_values import Value, header, pose_value
from robocram.traces.tf_frames import BodyFrames
from robocram.world import MeshSpec, RobotObject, ShapeSpec, UrdfSpec, World

CUBE, SPHERE, CYLINDER, MESH_RESOURCE, TRIANGLE_LIST = 1, 2, 3, 10, 11  # Marker.type
PLANE_SIZE = 40.0  # [m] side of the slab a floor plane is drawn as (as in the simulator)
PLANE_THICKNESS = 0.001  # [m]
GREY = (0.6, 0.6, 0.6, 1.0)

Rgba = tuple[float, float, float, float]
Point = tuple[float, float, float]
Shape = tuple[int, tuple[float, float, float], tuple[Point, ...]]  # type, scale [m], triangles


def scene_markers(world: World, bodies: list[BodyFrames], time: float) -> Value:
    """The markers of every object of ``world`` that is not a robot, stamped ``time``."""
    markers: list[Value] = []
    for body in bodies:
        obj = world.object(body.body)
        spec = obj.spec
        if isinstance(obj, RobotObject):
            continue
        if isinstance(spec, ShapeSpec):
            markers.append(_marker(body, body.root_frame, _shape(spec), Pose(), spec.color, time))
        elif isinstance(spec, MeshSpec):
            shape = _mesh(str(spec.path), (spec.scale,) * 3)
            markers.append(_marker(body, body.root_frame, shape, Pose(), spec.color, time))
        elif isinstance(spec, UrdfSpec):
            markers += _link_markers(body, spec.scale, time)
    return {"markers": markers}


def robot_markers(world: World, bodies: list[BodyFrames], time: float) -> Value:
    """The markers of every robot's link visuals, meshes embedded, stamped ``time``."""
    markers: list[Value] = []
    for body in bodies:
        if isinstance(world.object(body.body), RobotObject):
            markers += _link_markers(body, 1.0, time)
    return {"markers": markers}


def _link_markers(body: BodyFrames, scale: float, time: float) -> list[Value]:
    """One marker per visual of each of ``body``'s links, in the link's frame."""
    markers: list[Value] = []
    if body.model is None:
        return markers
    for link, frame in body.frames.items():
        for visual in body.model.links[link].visuals:
            shape = _geometry(visual.geometry, scale)
            origin = _scaled(visual.origin, scale)
            color = visual.rgba or GREY
            markers.append(_marker(body, frame, shape, origin, color, time, len(markers)))
    return markers


def _shape(spec: ShapeSpec) -> Shape:
    sx, sy, sz = spec.size
    if spec.shape == "box":
        return CUBE, (sx, sy, sz), ()
    if spec.shape == "cylinder":
        return CYLINDER, (sx, sx, sz), ()
    if spec.shape == "sphere":
        return SPHERE, (sx, sx, sx), ()
    return CUBE, (PLANE_SIZE, PLANE_SIZE, PLANE_THICKNESS), ()


def _geometry(geometry: Geometry, scale: float) -> Shape:
    """A URDF visual's shape, scaled by the object's global scale."""
    if geometry.kind == "box":
        x, y, z = geometry.size
        return CUBE, (x * scale, y * scale, z * scale), ()
    if geometry.kind == "cylinder":
        d = 2 * geometry.radius * scale
        return CYLINDER, (d, d, geometry.length * scale), ()
    if geometry.kind == "sphere":
        d = 2 * geometry.radius * scale
        return SPHERE, (d, d, d), ()
    sx, sy, sz = geometry.scale
    return _mesh(geometry.filename, (sx * scale, sy * scale, sz * scale))


def _mesh(filename: str, scale: tuple[float, float, float]) -> Shape:
    """A mesh's triangles, scaled, for a ``TRIANGLE_LIST``; a mesh too big to embed
    (:data:`~robocram.traces.mesh_triangles.MAX_TRIANGLES`) is drawn as its box."""
    found = mesh_triangles(str(Path(filename).resolve()), scale)
    if isinstance(found, MeshBox):
        return TRIANGLE_LIST, (1.0, 1.0, 1.0), found.triangles()
    return TRIANGLE_LIST, (1.0, 1.0, 1.0), found


def _scaled(pose: Pose, scale: float) -> Pose:
    x, y, z = pose.position
    return Pose((x * scale, y * scale, z * scale), pose.orientation)


def _marker(
    body: BodyFrames,
    frame: str,
    shape: Shape,
    origin: Pose,
    color: Rgba,
    time: float,
    index: int = 0,
) -> Value:
    kind, (sx, sy, sz), triangles = shape
    r, g, b, a = color
    stamp = header(time, frame)
    return {
        "header": stamp,
        "ns": body.body,
        "id": index,
        "type": kind,
        "action": 0,  # ADD
        "pose": pose_value(origin),
        "scale": {"x": sx, "y": sy, "z": sz},
        "color": {"r": r, "g": g, "b": b, "a": a},
        "lifetime": {"sec": 0, "nanosec": 0},  # forever
        "frame_locked": True,  # follows its frame as /tf moves it
        "points": [{"x": x, "y": y, "z": z} for x, y, z in triangles],
        "colors": [],
        "texture_resource": "",
        "texture": {"header": stamp, "format": "", "data": b""},
        "uv_coordinates": [],
        "text": "",
        "mesh_resource": "",
        "mesh_file": {"filename": "", "data": b""},
        "mesh_use_embedded_materials": False,
    }
