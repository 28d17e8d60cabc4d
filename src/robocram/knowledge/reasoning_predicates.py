"""Reach reasoning the location costmaps put into a world's knowledge base, as typed rows.

``pose_reachable/3`` and ``lift_clearance/4`` are what a pick from an opened drawer asks
before the hand moves: how far the object must rise to clear the drawer's top, and
whether the arm reaches that lift from where the robot stands. ``line_stand/5`` is where
a pick whose every try failed stands again when its arm reaches along a telescope. CRAM's untyped
``reachable/2``, ``pose_reachable/2`` and ``blocking/4`` sit beside them
(docs/locations.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from robocram.knowledge.argument import unit
from robocram.knowledge.predicate import Predicate, Source
from robocram.tf import PoseStamped


@dataclass(frozen=True)
class ArmPoseReach:
    """An arm of a robot, standing where it is, brings its tool to a pose."""

    robot: str
    arm: str
    pose: PoseStamped = unit("m, map")


@dataclass(frozen=True)
class LiftClearance:
    """How far an object must rise for its bottom to clear the top of a link."""

    object: str
    body: str
    link: str
    rise: float = unit("m")


@dataclass(frozen=True)
class LineStand:
    """Where a robot stands for an arm to take its tool from a pose back on an approach
    line (``out``) to a grasp and back along that line by its level telescope alone."""

    robot: str
    arm: str
    out: PoseStamped = unit("m, map")
    grasp: PoseStamped = unit("m, map")
    stand: PoseStamped = unit("m, map")


_R = Source.REASONING
ARM_POSE_REACHABLE = Predicate(
    "pose_reachable", ArmPoseReach, _R, "the arm brings its tool to the map pose from here"
)
LIFT_CLEARANCE = Predicate(
    "lift_clearance", LiftClearance, _R, "the rise that lifts an object over a link's top"
)

LINE_STAND = Predicate(
    "line_stand", LineStand, _R, "the stand whose telescope takes the tool along the approach"
)

REASONING_PREDICATES: tuple[Predicate[Any], ...] = (
    ARM_POSE_REACHABLE,
    LIFT_CLEARANCE,
    LINE_STAND,
)
