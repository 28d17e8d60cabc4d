"""The TF tree of a world, as a robot's state publisher would send it.

Each articulated body gives one edge per URDF joint: parent frame = the joint's parent
link, child frame = its child link, transform = the joint's origin and then its motion at
the joint's value. A robot's root link hangs below its odom frame, which sits at ``map``
(projection knows where the robot is, so localisation is exact); every other body's root
frame is named after the object and hangs below ``map``. Fixed joints and the odom frames
never move: they go on ``/tf_static`` once, the rest on ``/tf`` at every moment.

Frame names must be unique in one tree: a link name that another body already uses (two
robots of one kind) is prefixed with its object's name, ``pr2_2/base_link``.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from robocram.robots import Joint, RobotModel, joint_transform
from robocram.tf import Pose
from robocram.world import RobotObject, UrdfSpec, World, WorldObject

MAP_FRAME = "map"

Transform = tuple[str, str, Pose]  # parent frame, child frame, parent_T_child


@dataclass(frozen=True)
class FrameEdge:
    """One edge of the tree: ``child`` below ``parent``, placed by ``joint`` or by the body.

    ``joint`` is ``None`` for a body's root (its pose in map, or in odom for a robot) and
    for an odom frame (``body`` ``None``: identity in map).
    """

    parent: str
    child: str
    body: str | None
    joint: Joint | None = None
    scale: float = 1.0  # a URDF object's global scale: joint origins scale with it

    @property
    def is_static(self) -> bool:
        """Whether the transform never changes: a fixed joint, or an odom frame."""
        if self.joint is not None:
            return not self.joint.movable
        return self.body is None


@dataclass(frozen=True)
class BodyFrames:
    """The frames of one body: the frame of each of its links, and its edges in the tree."""

    body: str
    model: RobotModel | None  # None: a single shape or mesh
    frames: dict[str, str]  # link -> frame; a shape's only "link" is its object name
    edges: list[FrameEdge] = field(default_factory=list)

    @property
    def root_frame(self) -> str:
        """The frame of the body's root link (its object pose)."""
        return next(iter(self.frames.values()))


def world_frames(world: World) -> list[BodyFrames]:
    """The frames and edges of every body of ``world``, in insertion order."""
    taken = {MAP_FRAME}
    bodies: list[BodyFrames] = []
    for obj in world.objects():
        model = body_model(obj)
        if model is None:
            bodies.append(_shape_frames(obj, taken))
        else:
            bodies.append(_model_frames(obj, model, taken))
    return bodies


def body_model(obj: WorldObject) -> RobotModel | None:
    """The URDF model of a robot or a URDF object; ``None`` for a shape or a mesh."""
    if isinstance(obj, RobotObject):
        return obj.description.model
    if isinstance(obj.spec, UrdfSpec):
        return RobotModel.from_file(obj.spec.path)
    return None


def _unique(name: str, obj: WorldObject, taken: set[str]) -> str:
    frame = name if name not in taken else f"{obj.name}/{name}"
    taken.add(frame)
    return frame


def _shape_frames(obj: WorldObject, taken: set[str]) -> BodyFrames:
    frame = _unique(obj.name, obj, taken)
    return BodyFrames(obj.name, None, {obj.name: frame}, [FrameEdge(MAP_FRAME, frame, obj.name)])


def _model_frames(obj: WorldObject, model: RobotModel, taken: set[str]) -> BodyFrames:
    root = model.root_link
    edges: list[FrameEdge] = []
    if isinstance(obj, RobotObject):
        frames = {root: _unique(root, obj, taken)}
        odom = _unique(obj.description.odom_frame, obj, taken)
        edges.append(FrameEdge(MAP_FRAME, odom, None))
        edges.append(FrameEdge(odom, frames[root], obj.name))
    else:
        frames = {root: _unique(obj.name, obj, taken)}
        edges.append(FrameEdge(MAP_FRAME, frames[root], obj.name))
    scale = obj.spec.scale if isinstance(obj.spec, UrdfSpec) else 1.0
    for joint in _top_down(model):
        frames[joint.child] = _unique(joint.child, obj, taken)
        edges.append(FrameEdge(frames[joint.parent], frames[joint.child], obj.name, joint, scale))
    return BodyFrames(obj.name, model, frames, edges)


def _top_down(model: RobotModel) -> list[Joint]:
    """The model's joints, each after the joint of its parent link."""
    below: dict[str, list[Joint]] = {}
    for joint in model.joints.values():
        below.setdefault(joint.parent, []).append(joint)
    ordered: list[Joint] = []
    queue = [model.root_link]
    while queue:
        for joint in below.get(queue.pop(0), []):
            ordered.append(joint)
            queue.append(joint.child)
    return ordered


def static_transforms(bodies: Iterable[BodyFrames]) -> list[Transform]:
    """The transforms that never change: fixed joints, odom frames at map."""
    return [
        (e.parent, e.child, _edge_transform(e, 0.0)) for b in bodies for e in b.edges if e.is_static
    ]


def moving_transforms(world: World, bodies: Iterable[BodyFrames]) -> list[Transform]:
    """The transforms of ``world``'s current state: body roots and movable joints."""
    found: list[Transform] = []
    for body in bodies:
        values = world.joint_states(body.body) if body.model is not None else {}
        for edge in body.edges:
            if edge.is_static:
                continue
            if edge.joint is None:
                found.append((edge.parent, edge.child, world.pose(body.body)))
            else:
                value = values[edge.joint.name]
                found.append((edge.parent, edge.child, _edge_transform(edge, value)))
    return found


def _edge_transform(edge: FrameEdge, value: float) -> Pose:
    if edge.joint is None:
        return Pose()
    pose = joint_transform(edge.joint, value)
    if edge.scale == 1.0:
        return pose
    x, y, z = pose.position
    s = edge.scale
    return Pose((x * s, y * s, z * s), pose.orientation)
