"""The grasp model as predicates of a world's knowledge base: the door plans use.

Plans may not import this layer; they ask the KB instead (docs/grasping.md):

- ``object_grasp(Obj, Robot, Arm, Name, Grasp, PreGrasp, Lift)``: the grasps of object
  ``Obj`` by ``Robot``'s ``Arm`` (unbound: each arm with a gripper), best first; ``Grasp``,
  ``PreGrasp`` and ``Lift`` are the tool's ``PoseStamped`` targets in ``map``. Nothing
  when no grasp fits.
- ``grasping_arm(Robot, Arm)``: the arms with a gripper (a neck camera arm is none).
- ``object_extent(Obj, Low, High)``: the object's box [m] in its own frame, ``[x, y, z]``
  lists (a placed object's bottom is ``-Low[2]`` below its origin).
- ``object_ungraspable(Obj, Robot, Arm, HandWidth, NeededWidth)``: holds when no grasp of
  ``Obj`` fits the hand, with the widths [m] to name in the failure.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

from robocram.grasping.errors import ObjectUngraspable
from robocram.grasping.object_grasps import grasp_candidates, install_grasp_facts, object_shape
from robocram.logic import KnowledgeBase, Var
from robocram.tf import PoseStamped
from robocram.world import RobotObject, World

Solutions = Iterator[tuple[Any, ...] | None]


def _arms(robot: RobotObject, arm: Any) -> list[str]:
    desc = robot.description
    grippers = [a for a, spec in desc.arms.items() if spec.gripper is not None]
    grippers = [a for a in grippers if a != desc.neck_arm]
    return grippers if isinstance(arm, Var) else [a for a in grippers if a == arm]


def install_grasp_predicates(world: World) -> KnowledgeBase:
    """Add the grasp predicates on ``world`` (module docstring) to its KB."""
    kb = world.kb
    install_grasp_facts(kb)

    def object_grasp(obj: Any, robot: Any, arm: Any, name: Any, *_: Any) -> Solutions:
        target, body = world.object(obj), world.robot(robot)
        names = None if isinstance(name, Var) else [str(name)]
        for choice in _arms(body, arm):
            try:
                found = grasp_candidates(world, target, body, choice, names)
            except ObjectUngraspable:
                continue
            for c in found:
                poses = (PoseStamped.from_pose("map", p) for p in (c.tool, c.pre_grasp, c.lifted))
                yield (obj, robot, choice, c.grasp.name, *poses)

    def object_ungraspable(obj: Any, robot: Any, arm: Any, *_: Any) -> Solutions:
        target, body = world.object(obj), world.robot(robot)
        for choice in _arms(body, arm):
            try:
                grasp_candidates(world, target, body, choice)
            except ObjectUngraspable as err:
                yield (obj, robot, choice, err.hand_width, err.needed_width)

    def grasping_arm(robot: Any, arm: Any) -> Solutions:
        for body in world.robots():
            if isinstance(robot, Var) or body.name == robot:
                for choice in _arms(body, arm):
                    yield (body.name, choice)

    def object_extent(obj: Any, low: Any, high: Any) -> Solutions:
        shape = object_shape(world, world.object(obj))
        yield (obj, list(shape.low), list(shape.high))

    kb.add_predicate("grasping_arm", 2, grasping_arm)
    kb.add_predicate("object_extent", 3, object_extent)
    kb.add_predicate("object_grasp", 7, object_grasp)
    kb.add_predicate("object_ungraspable", 5, object_ungraspable)
    return kb
