"""The grasps of an object in a world for one arm of a robot there, best first, in the map.

The object's type chooses the grasps through the knowledge base: ``object_grasps(Type,
Names)`` restricts and orders them (default: :data:`GRASP_NAMES`), ``object_wall(Type,
Thickness)`` makes a type hollow (rim grasps), ``object_handle(Type, Width)`` gives it a
handle bar. The side grasps (front, left, right) share the place of the first of them in
that order, the one coming in most directly from the robot first. Among the turns of one
grasp, the one whose fingers spread along the robot's base y axis comes first: the hand as
the arm holds it reaching ahead.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from robocram.grasping.grasp import Grasp
from robocram.grasping.grasp_model import GRASP_NAMES, grasps
from robocram.grasping.hand import hand_of
from robocram.grasping.object_shape import ObjectShape, shape_of
from robocram.logic import KnowledgeBase
from robocram.robots import RobotDescription
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import RobotObject, World, WorldObject

DEFAULT_FACTS = """
:- dynamic(object_grasps/2).
object_wall(bowl, 0.006).
object_handle(mug, 0.012).
"""
FACTS_GROUP = "object_grasp_facts"
SIDE_GRASPS = ("front", "left", "right")  # tried in the order they face the robot
EXTENDABLE = ["object_grasps/2", "object_wall/2", "object_handle/2"]


@dataclass(frozen=True)
class GraspCandidate:
    """A grasp and its grasp, pre-grasp and lifted tool poses in the map."""

    grasp: Grasp
    tool: Pose
    pre_grasp: Pose
    lifted: Pose


def install_grasp_facts(kb: KnowledgeBase) -> None:
    """Add the default per-type grasp facts (hollow bowl, mug handle) to ``kb``, once."""
    if not kb.known("object_wall", 2):  # asked once per world: no error built to catch
        kb.consult(DEFAULT_FACTS, group=FACTS_GROUP, extendable=EXTENDABLE)


def _first_number(kb: KnowledgeBase, predicate: str, kind: str) -> float | None:
    answer = kb.first(f"{predicate}(T, V)", T=kind)
    return None if answer is None else float(answer["V"])


def grasp_names(kb: KnowledgeBase, kind: str) -> tuple[str, ...]:
    """The grasps type ``kind`` allows, in order (``object_grasps/2``, else all)."""
    install_grasp_facts(kb)
    answer = kb.first("object_grasps(T, N)", T=kind)
    return GRASP_NAMES if answer is None else tuple(str(n) for n in answer["N"])


def type_facts(kb: KnowledgeBase, kind: str) -> tuple[float | None, float | None]:
    """The wall thickness and handle width [m] of type ``kind`` (None: not said)."""
    install_grasp_facts(kb)
    return _first_number(kb, "object_wall", kind), _first_number(kb, "object_handle", kind)


def object_shape(world: World, obj: WorldObject) -> ObjectShape:
    """The shape of ``obj`` with its wall and handle as the world's KB says."""
    return shape_of(world, obj, *type_facts(world.kb, obj.type))


def _preference(robot_in_map: Pose, object_in_map: Pose, grasp: Grasp) -> tuple[float, float]:
    """Smaller first: a side grasp coming in from the robot, then fingers along base y."""
    towards = np.subtract(object_in_map.position, robot_in_map.position)[:2]
    norm = float(np.linalg.norm(towards))
    approach = np.asarray(quat.rotate(object_in_map.orientation, grasp.approach))[:2]
    facing = float(approach @ towards) / norm if norm > 1e-9 else 0.0
    base_y = np.asarray(quat.rotate(robot_in_map.orientation, (0.0, 1.0, 0.0)))
    across = np.asarray(quat.rotate(object_in_map.orientation, grasp.across))
    return -facing, -abs(float(base_y @ across))


def _rank(names: Sequence[str]) -> dict[str, int]:
    """Each grasp's place in ``names``; the side grasps share the place of the first one."""
    order = {name: k for k, name in enumerate(names)}
    sides = [order[n] for n in SIDE_GRASPS if n in order]
    for name in SIDE_GRASPS:
        if name in order:
            order[name] = min(sides)
    return order


def candidates_at(
    shape: ObjectShape,
    object_in_map: Pose,
    desc: RobotDescription,
    arm: str,
    base_in_map: Pose,
    names: Sequence[str],
) -> list[GraspCandidate]:
    """The grasps of ``shape`` at ``object_in_map`` that ``arm``'s hand fits, best first
    (a tilted rim grasp right after the flat ones of its side; a raised one after all).

    Raises:
        ObjectUngraspable: no grasp fits the hand.
        GraspingError: the arm has no gripper.
    """
    found = grasps(shape, hand_of(desc, arm), names)
    order = _rank(names)
    found.sort(
        key=lambda g: (
            g.raised > 0.0,
            order[g.name],
            g.deeper > 0.0,
            _preference(base_in_map, object_in_map, g),
            g.tilt,
        )
    )
    return [GraspCandidate(g, *g.in_map(object_in_map)) for g in found]


def grasp_candidates(
    world: World,
    obj: WorldObject,
    robot: RobotObject,
    arm: str,
    names: Sequence[str] | None = None,
) -> list[GraspCandidate]:
    """Every grasp of ``obj`` the hand of ``robot``'s ``arm`` fits, best first, in the map.

    ``names`` restricts the grasps (default: the type's ``object_grasps/2``, else all).

    Raises:
        ObjectUngraspable: no grasp fits the hand.
        GraspingError: the arm has no gripper.
    """
    allowed = grasp_names(world.kb, obj.type) if names is None else tuple(names)
    shape = object_shape(world, obj)
    return candidates_at(shape, world.pose(obj), robot.description, arm, world.pose(robot), allowed)
