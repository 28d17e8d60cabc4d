"""Failures of the tool actions (pouring, wiping, cutting, mixing), each naming its culprit."""

from __future__ import annotations

from robocram.execution.failures import HighLevelFailure


class ToolActionFailure(HighLevelFailure):
    """A tool action could not do what it was asked."""

    action: str | None = None  # pouring, wiping, cutting or mixing
    summary = "a tool action failed"


class ToolNotHeld(ToolActionFailure):
    """The tool (or the source to pour from) is in no hand of the robot."""

    tool: str | None = None
    robot: str | None = None
    summary = "the tool is not in the robot's hand"
    hint = "pick the tool up first (a 'picking-up' action), then perform the tool action"


class TargetCovered(ToolActionFailure):
    """Something lies on the target's opening: nothing can be poured into it."""

    target: str | None = None
    cover: str | None = None  # what lies on the opening
    summary = "the target's opening is covered"
    hint = "take the cover off the target first (a 'transporting' action), then pour"


class ToolPathIncomplete(ToolActionFailure):
    """The tool path could not be followed far enough for the action to count as done."""

    fraction: float | None = None  # of the path reached (0..1)
    needed: float | None = None  # the fraction the action needs
    stopped_by: str | None = None  # why the path ended early
    summary = "the tool path was not followed far enough"
    hint = "move the robot or the objects so that the whole path is in the arm's reach"


class UnknownToolObject(ToolActionFailure):
    """An object the action names is not known to the knowledge base (no pose or box)."""

    object: str | None = None
    summary = "the action names an object the knowledge base does not know"
    hint = "name an object of the world (object_pose/3 and object_extent/3 must answer it)"
