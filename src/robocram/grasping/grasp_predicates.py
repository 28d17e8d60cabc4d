"""The grasp model as predicates of a knowledge base: the door plans use.

The rows (arguments, types, meanings) are declared in
``robocram.knowledge.grasp_predicates``; the table registers the functions here.

Plans may not import this layer; they ask the KB instead (docs/grasping.md). ``Obj`` is
an object's name, or ``object(Name, Type, Pose)`` with its type and a ``PoseStamped``
(in ``map``) where no world knows it (recording, a real robot: the shape then comes from
the catalogue by type).

- ``object_grasp(Obj, Robot, Arm, Name, Grasp, PreGrasp, Lift)``: the grasps of ``Obj``
  by ``Robot``'s ``Arm`` (unbound: each arm with a gripper), best first; ``Grasp``,
  ``PreGrasp`` and ``Lift`` are the tool's ``PoseStamped`` targets in ``map``. Nothing
  when no grasp fits.
- ``object_ungraspable(Obj, Robot, Arm, HandWidth, NeededWidth)``: holds when no grasp of
  ``Obj`` fits the hand, with the widths [m] to name in the failure.
- ``grasping_arm(Robot, Arm)``: the arms with a gripper (a neck camera arm is none).
- ``object_extent(Obj, Low, High)``: the object's box [m] in its own frame, ``[x, y, z]``
  lists (a resting object's bottom is ``-Low[2]`` below its origin).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

from robocram.grasping.errors import GraspingError, ObjectUngraspable
from robocram.grasping.object_grasps import (
    GraspCandidate,
    candidates_at,
    grasp_names,
    install_grasp_facts,
    type_facts,
)
from robocram.grasping.object_shape import ObjectShape, catalogue_shape, shape_of
from robocram.knowledge import Source, register_predicates
from robocram.knowledge.registration import Implementation
from robocram.logic import KnowledgeBase, Term, Var
from robocram.robots import RobotDescription
from robocram.tf import Pose, PoseStamped, transform_pose
from robocram.world import World

Solutions = Iterator[tuple[Any, ...] | None]


@dataclass(frozen=True)
class _Object:
    name: str
    kind: str
    pose: Pose  # in map


class GraspDoor:
    """Answers the grasp predicates from a world, or from poses and the catalogue."""

    def __init__(self, kb: KnowledgeBase, world: World | None, desc: RobotDescription | None):
        self.kb, self.world, self.desc = kb, world, desc

    def description(self, robot: str) -> RobotDescription:
        if self.world is not None and robot in self.world:
            return self.world.robot(robot).description
        if self.desc is not None and self.desc.name == robot:
            return self.desc
        raise GraspingError(f"no robot {robot!r} to grasp with")

    def base_pose(self, robot: str) -> Pose:
        if self.world is not None and robot in self.world:
            return self.world.pose(robot)
        return transform_pose(PoseStamped(self.description(robot).base_frame), "map").pose

    def obj(self, spec: object) -> _Object:
        if isinstance(spec, Term) and spec.name == "object" and spec.arity == 3:
            name, kind, pose = spec.args
            return _Object(str(name), str(kind), transform_pose(pose, "map").pose)
        if self.world is None or str(spec) not in self.world:
            raise GraspingError(
                f"no object {spec!r} in the world; name one, or pass object(Name, Type, Pose)"
            )
        body = self.world.object(str(spec))
        return _Object(body.name, body.type, self.world.pose(body))

    def shape(self, obj: _Object) -> ObjectShape:
        facts = type_facts(self.kb, obj.kind)
        if self.world is not None and obj.name in self.world:
            return shape_of(self.world, self.world.object(obj.name), *facts)
        return catalogue_shape(obj.kind, obj.name, *facts)

    def arms(self, robot: str, arm: object) -> list[str]:
        desc = self.description(robot)
        found = [a for a, s in desc.arms.items() if s.gripper is not None and a != desc.neck_arm]
        return found if isinstance(arm, Var) else [a for a in found if a == arm]

    def candidates(
        self, obj: _Object, robot: str, arm: str, names: tuple[str, ...] | None = None
    ) -> list[GraspCandidate]:
        allowed = grasp_names(self.kb, obj.kind) if names is None else names
        return candidates_at(
            self.shape(obj), obj.pose, self.description(robot), arm, self.base_pose(robot), allowed
        )

    def robots(self, robot: object) -> list[str]:
        names = [r.name for r in self.world.robots()] if self.world is not None else []
        if self.desc is not None and self.desc.name not in names:
            names.append(self.desc.name)
        return names if isinstance(robot, Var) else [r for r in names if r == robot]


def install_grasp_predicates(
    kb: KnowledgeBase, world: World | None = None, description: RobotDescription | None = None
) -> KnowledgeBase:
    """Add the grasp predicates (module docstring) to ``kb``, on ``world`` if there is one.

    Without a world, ``description`` is the robot, its base pose comes from the current
    transform tree and objects are named with their type and pose.
    """
    install_grasp_facts(kb)
    door = GraspDoor(kb, world, description)

    def object_grasp(
        spec: object, robot: object, arm: object, name: object, *_: object
    ) -> Solutions:
        obj = door.obj(spec)
        names = None if isinstance(name, Var) else (str(name),)
        for choice in door.arms(str(robot), arm):
            try:
                found = door.candidates(obj, str(robot), choice, names)
            except ObjectUngraspable:
                continue
            for c in found:
                poses = (PoseStamped.from_pose("map", p) for p in (c.tool, c.pre_grasp, c.lifted))
                yield (spec, robot, choice, c.grasp.name, *poses)

    def object_ungraspable(spec: object, robot: object, arm: object, *_: object) -> Solutions:
        obj = door.obj(spec)
        for choice in door.arms(str(robot), arm):
            try:
                door.candidates(obj, str(robot), choice)
            except ObjectUngraspable as err:
                yield (spec, robot, choice, err.hand_width, err.needed_width)

    def grasping_arm(robot: object, arm: object) -> Solutions:
        for name in door.robots(robot):
            for choice in door.arms(name, arm):
                yield (name, choice)

    def object_extent(spec: object, *_: object) -> Solutions:
        shape = door.shape(door.obj(spec))
        yield (spec, list(shape.low), list(shape.high))

    implementations: dict[str, Implementation] = {
        "grasping_arm/2": grasping_arm,
        "object_extent/3": object_extent,
        "object_grasp/7": object_grasp,
        "object_ungraspable/5": object_ungraspable,
    }
    register_predicates(kb, Source.GRASPING, implementations)
    return kb
