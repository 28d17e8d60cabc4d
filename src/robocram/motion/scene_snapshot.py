"""What a collision scene takes from the world: plain values, so it pickles.

A :class:`SceneSnapshot` is the robot's description, joint values and base pose, what it
holds (shapes in their link's frame) and every other object's shapes (in the robot's root
frame), read once through ``World`` methods. A worker process rebuilds the coal scene
from it without a world.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass

from robocram.motion.errors import MotionError
from robocram.motion.hand_contact import HandContact
from robocram.motion.self_collision_matrix import SelfCollisionMatrix
from robocram.robots import LoadedDescription
from robocram.tf import Pose
from robocram.world import CollisionShape, RobotHandle, World


@dataclass(frozen=True)
class PlacedShape:
    """A shape of a world object placed in a robot frame; ``label`` names it in results."""

    shape: CollisionShape
    frame_T_shape: Pose  # noqa: N815  (in the robot's root link, or the carrier link)
    label: str  # "object", or "object/link" for an object of several links
    type: str  # the object's type
    held_by: str | None = None  # the arm holding the object
    carrier: str | None = None  # the robot link it hangs from


@dataclass(frozen=True)
class SceneSnapshot:
    """The world around one robot at one moment, for :class:`CollisionScene`."""

    robot: str
    description: LoadedDescription
    joints: tuple[str, ...]
    joint_values: tuple[tuple[str, float], ...]  # every non-mimic joint [rad | m]
    held: tuple[PlacedShape, ...]
    static: tuple[PlacedShape, ...]
    allowed_links: frozenset[str]
    margin: float  # [m]
    skipped_self: frozenset[frozenset[str]] = frozenset()  # own pairs the matrix skips
    hand: HandContact | None = None  # the hand may touch what it acts on (bounded on the world)

    @classmethod
    def take(
        cls,
        robot: RobotHandle,
        joints: Sequence[str],
        allowed_links: Collection[str] = (),
        margin: float = 0.0,
        hand: HandContact | None = None,
    ) -> SceneSnapshot:
        """Read the world once: the robot's state, what it holds, every other object
        (``hand``'s links are not checked against what it may touch; its bound is the
        world's to judge)."""
        world = robot.world
        if not margin >= 0.0:
            raise MotionError(f"collision margin must be >= 0 [m], got {margin!r}")
        handle = robot.body
        desc = handle.description
        _check_joints(desc, joints)
        model = desc.model
        values = tuple(
            (name, value)
            for name, value in world.joint_states(handle).items()
            if model.joints[name].mimic is None
        )
        held_names = set(world.bodies.attachments(handle))
        return cls(
            handle.name, desc, tuple(joints), values,
            tuple(_held_shapes(robot, desc)),
            tuple(_static_shapes(robot, held_names)),
            frozenset(allowed_links), float(margin),
            frozenset(SelfCollisionMatrix.of(robot).skipped), hand,
        )  # fmt: skip


def _check_joints(desc: LoadedDescription, joints: Sequence[str]) -> None:
    if not joints:
        raise MotionError(f"a collision scene of {desc.name} needs at least one joint to plan")
    if len(set(joints)) != len(joints):
        raise MotionError(f"joints {list(joints)} name a joint twice; give each once")
    model = desc.model
    for name in joints:
        joint = model.joints.get(name)
        if joint is None or not joint.movable:
            movable = [j.name for j in model.movable_joints() if j.mimic is None]
            raise MotionError(
                f"{name!r} is not a movable joint of {desc.name}; use one of {movable}"
            )
        if joint.mimic is not None:
            raise MotionError(
                f"joint {name!r} of {desc.name} mimics {joint.mimic.joint!r}; plan its master"
            )


def _arm_of(desc: LoadedDescription, link: str) -> str | None:
    for name, arm in desc.arms.items():
        members = {*arm.gripper_links, *arm.hand_links, *arm.links, arm.end_effector_link}
        if link in members or link == arm.tool_frame:
            return name
    return None


def _label(world: World, obj: str, link: str) -> str:
    return obj if len(world.link_names(obj)) == 1 else f"{obj}/{link}"


def _held_shapes(robot: RobotHandle, desc: LoadedDescription) -> list[PlacedShape]:
    world = robot.world
    placed = []
    for obj, link in world.bodies.attachments(robot.name).items():
        link_T_map = world.link_pose(robot.name, link).inverse()
        kind = world.object(obj).type
        for shape in world.contacts.collision_shapes(obj):
            placed.append(
                PlacedShape(
                    shape, link_T_map * shape.pose, _label(world, obj, shape.link), kind,
                    _arm_of(desc, link), link,
                )
            )  # fmt: skip
    return placed


def _static_shapes(robot: RobotHandle, held: set[str]) -> list[PlacedShape]:
    world = robot.world
    root_T_map = world.pose(robot.name).inverse()
    placed = []
    for obj in world.objects():
        if obj.name == robot.name or obj.name in held:
            continue
        for shape in world.contacts.collision_shapes(obj):
            label = _label(world, obj.name, shape.link)
            placed.append(PlacedShape(shape, root_T_map * shape.pose, label, obj.type))
    return placed
