"""The grasp model as predicates, the door plans use to it (docs/grasping.md).

``object`` is an object's name, or ``object(Name, Type, Pose)`` with its type and a
``PoseStamped`` in ``map`` where no world knows it (recording, a real robot).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.knowledge.argument import Vector, unit
from robocram.knowledge.predicate import Predicate, Source
from robocram.knowledge.robot_predicates import Arm
from robocram.tf import PoseStamped


@dataclass(frozen=True)
class ObjectExtent:
    """An object's box in its own frame (a resting object's bottom is ``-low[2]`` down)."""

    object: object
    low: Vector = unit("m")
    high: Vector = unit("m")


@dataclass(frozen=True)
class ObjectGrasp:
    """One grasp of an object by an arm: the tool's targets in ``map``."""

    object: object
    robot: str
    arm: str
    grasp: str
    grasp_pose: PoseStamped = unit("m, map")
    pre_grasp: PoseStamped = unit("m, map")
    lift: PoseStamped = unit("m, map")


@dataclass(frozen=True)
class Ungraspable:
    """An object no grasp of which fits an arm's hand."""

    object: object
    robot: str
    arm: str
    hand_width: float = unit("m")
    needed_width: float = unit("m")


_G = Source.GRASPING
GRASPING_ARM = Predicate("grasping_arm", Arm, _G, "an arm with a gripper (a neck is none)")
OBJECT_EXTENT = Predicate("object_extent", ObjectExtent, _G, "an object's box in its frame")
OBJECT_GRASP = Predicate("object_grasp", ObjectGrasp, _G, "the grasps of an object, best first")
OBJECT_UNGRASPABLE = Predicate(
    "object_ungraspable", Ungraspable, _G, "no grasp of the object fits the hand"
)

GRASP_PREDICATES: tuple[Predicate[Any], ...] = (
    GRASPING_ARM,
    OBJECT_EXTENT,
    OBJECT_GRASP,
    OBJECT_UNGRASPABLE,
)
