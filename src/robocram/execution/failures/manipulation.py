"""Manipulation failures: arms and grippers, low level and high level."""

from __future__ import annotations

from robocram.designators import ObjectDesignator
from robocram.execution.failures.high_level import HighLevelFailure
from robocram.execution.failures.low_level import LowLevelFailure


class ManipulationLowLevelFailure(LowLevelFailure):
    """An arm motion failed."""

    arm: str | None = None
    summary = "the arm motion failed"


class ManipulationGoalNotReached(ManipulationLowLevelFailure):
    """The arm moved but stopped away from its goal."""

    target: object | None = None
    reached: object | None = None
    error: tuple[float, float] | None = None
    summary = "the arm did not reach its goal"
    hint = "retry, or loosen the tolerance if the remaining error is small"


class ManipulationPoseUnreachable(ManipulationLowLevelFailure):
    """No arm configuration reaches the target (IK found no solution)."""

    target: object | None = None
    colliding_pairs: tuple[tuple[str, str], ...] | None = None  # (robot link, object)
    beyond_reach: float | None = None  # [m] the target's distance beyond the arm's reach
    summary = "the target pose is out of the arm's reach"
    hint = ""  # the advice depends on the robot and the cause: the raiser's message has it


class ManipulationPathBlocked(ManipulationPoseUnreachable):
    """The goal is reachable, but no collision-free path of the arm leads there."""

    path_fraction: float | None = None  # [0..1] how far along the path the first collision is
    summary = "the arm's path to its goal is blocked"
    hint = "try another grasp, arm or stand, or allow planning around the obstacle"


class ToolPathUnreachable(ManipulationPoseUnreachable):
    """A tool path the arm can follow only part of the way from where the robot stands;
    refused before the path is followed (the arm has only moved to the path's start)."""

    fraction: float | None = None  # [0..1] of the path the plan reached
    needed: float | None = None  # [0..1] of the path the motion asked for
    stopped_by: str | None = None  # why the planned path ended early
    summary = "the tool path is out of the arm's reach from here"
    hint = "stand elsewhere (a reachable_for location of the work) and try again"


class GripperLowLevelFailure(LowLevelFailure):
    """A gripper motion failed."""

    gripper: str | None = None
    summary = "the gripper motion failed"


class GripperClosedCompletely(GripperLowLevelFailure):
    """The gripper closed all the way: nothing is between the fingers."""

    position: float | None = None
    summary = "the gripper closed completely, so it holds nothing"
    hint = "perceive the object again and regrasp"


class GripperMetOneSide(GripperClosedCompletely):
    """One finger sank into the object before the other side came near: no grip.

    ``shift`` [m, map] moves the open hand so that the fingers meet the object together (a
    plan recovers by moving the tool by it and gripping again, as a robot centres its hand
    on what it sees between the fingers).
    """

    shift: tuple[float, float, float] | None = None
    met: str | None = None  # the object the one finger met
    summary = "the gripper met the object on one side only, so it holds nothing"
    hint = "grasp the object centred between the fingers, or take another grasp"


class GripperGoalNotReached(GripperLowLevelFailure):
    """The gripper stopped away from the commanded opening."""

    goal: float | None = None
    reached: object | None = None
    summary = "the gripper did not reach its goal"
    hint = "check for an obstacle between the fingers and retry"


class GripperPathBlocked(GripperLowLevelFailure):
    """The fingers' way to the commanded opening runs into something (not what they
    grip); the gripper did not move."""

    goal: float | None = None
    colliding_pairs: tuple[tuple[str, str], ...] | None = None  # (robot link, object)
    path_fraction: float | None = None  # [0..1] where along the way it collides (1: the goal)
    summary = "the gripper's way to its goal is blocked"
    hint = "move the hand away from what the message names, then retry"


class ManipulationGoalInCollision(HighLevelFailure):
    """The planned arm motion would collide with the environment."""

    arm: str | None = None
    target: object | None = None
    colliding: list[str] | None = None
    summary = "the manipulation goal is in collision"
    hint = "choose another grasp or approach pose"


class ObjectUnreachable(HighLevelFailure):
    """No base pose and arm combination reaches the object."""

    object_designator: ObjectDesignator | None = None
    summary = "the object is unreachable"
    hint = "try other base locations or clear the way"


class ObjectUnfetchable(HighLevelFailure):
    """Fetching the object failed after all retries."""

    object_designator: ObjectDesignator | None = None
    summary = "the object could not be fetched"
    hint = "search for another instance of the object"


class ObjectUndeliverable(HighLevelFailure):
    """Delivering the object to its target failed after all retries."""

    object_designator: ObjectDesignator | None = None
    target: object | None = None
    summary = "the object could not be delivered"
    hint = "pick another target location"
