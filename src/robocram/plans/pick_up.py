"""Pick up an object with any robot: one plan, unchanged, on the PR2, the HSR and Boxy.

The tabletop plan: look at where the object should be, raise the torso, detect it and
pick it up with :func:`~robocram.plans.pick_object.pick_up_object`, whose grasps come from
the grasp model through the knowledge base (docs/grasping.md). Everything
robot-specific (arms, tool frames, torso limits, parking joints, the hand's size) comes
from the KB, so the same PERFORM calls run on every robot and in every environment.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.designators import ObjectDesignator, a, an
from robocram.plans.basic_actions import look_from_above, look_lowering, park_arms
from robocram.plans.detect_past_hand import detect_past_hand
from robocram.plans.pick_object import Held, pick_up_object
from robocram.tf import PoseStamped


@dataclass(frozen=True)
class PickResult:
    """What the plan did: the arm, the object and the tool targets it reached (``map``)."""

    arm: str
    tool_frame: str
    object_name: str
    grasp: PoseStamped
    lifted: PoseStamped
    detected: ObjectDesignator
    held: Held


def pick_up(look_target: PoseStamped, object_type: str = "mug") -> PickResult:
    """Look, raise the torso, detect an ``object_type`` and pick it up."""
    park_arms()
    look_lowering(a.location(pose=look_target))
    look_from_above(a.location(pose=look_target), looked=True)
    seen = _detected(object_type)
    held = pick_up_object(seen)
    return PickResult(
        held.arm, held.tool_frame, held.object_name, held.grasp_pose, held.lifted, seen, held
    )


def _detected(object_type: str) -> ObjectDesignator:
    """Detect an ``object_type``, past the robot's own hand (:func:`detect_past_hand`)."""
    return detect_past_hand(an.object(type=object_type))
