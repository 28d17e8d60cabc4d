"""The failure taxonomy: names, hierarchy, data fields and messages."""

from __future__ import annotations

import pickle
import typing

import pytest

from robocram.execution import failures as F
from robocram.execution.failures import PlanFailure, failure_class

CRAM_NAMES = [
    "actionlib-action-timed-out",
    "manipulation-goal-not-reached",
    "manipulation-pose-unreachable",
    "gripper-closed-completely",
    "gripper-goal-not-reached",
    "torso-goal-unreachable",
    "torso-goal-not-reached",
    "navigation-pose-unreachable",
    "navigation-goal-not-reached",
    "perception-object-not-found",
    "ptu-goal-unreachable",
    "ptu-goal-not-reached",
    "navigation-goal-in-collision",
    "looking-high-level-failure",
    "object-unreachable",
    "manipulation-goal-in-collision",
    "object-unfetchable",
    "object-undeliverable",
    "object-nowhere-to-be-found",
    "environment-unreachable",
    "environment-manipulation-impossible",
    "designator-reference-failure",
    "designator-goal-parsing-failure",
]


@pytest.mark.parametrize("name", CRAM_NAMES)
def test_every_cram_failure_exists_by_both_names(name: str) -> None:
    cls = failure_class(name)
    assert issubclass(cls, PlanFailure)
    assert cls.cram_name == name
    assert getattr(F, cls.__name__) is cls


def test_area_hierarchy() -> None:
    assert issubclass(F.ManipulationGoalNotReached, F.ManipulationLowLevelFailure)
    assert issubclass(F.ManipulationLowLevelFailure, F.LowLevelFailure)
    assert issubclass(F.TorsoGoalNotReached, F.TorsoLowLevelFailure)
    assert issubclass(F.GripperClosedCompletely, F.GripperLowLevelFailure)
    assert issubclass(F.PtuGoalUnreachable, F.PtuLowLevelFailure)
    assert issubclass(F.ObjectUnfetchable, F.HighLevelFailure)
    assert issubclass(F.FlyingGoalInCollision, F.HighLevelFailure)
    assert issubclass(F.DesignatorReferenceFailure, F.DesignatorFailure)
    assert not issubclass(F.NotInTopLevel, PlanFailure)


def test_fields_are_keywords_attributes_and_in_the_message() -> None:
    failure = F.TorsoGoalNotReached(goal=0.5, limits=(0.0, 0.33), reached=0.33)
    assert (failure.goal, failure.limits, failure.reached) == (0.5, (0.0, 0.33), 0.33)
    assert str(failure) == (
        "the torso did not reach its goal (goal=0.5, limits=(0.0, 0.33), reached=0.33); "
        "check the goal against the joint limits or retry"
    )


def test_fields_are_inherited_and_missing_ones_are_none() -> None:
    failure = F.ManipulationPoseUnreachable(arm="right", target=(0.5, 0.0, 0.9))
    assert failure.arm == "right"
    assert failure.target == (0.5, 0.0, 0.9)
    failure = F.NavigationPoseUnreachable(target=(1, 2, 0))
    assert failure.colliding is None
    assert "colliding" not in str(failure)


def test_unknown_field_is_a_type_error_with_a_suggestion() -> None:
    with pytest.raises(TypeError, match="did you mean 'reached'"):
        F.TorsoGoalNotReached(goal=0.5, reachd=0.3)


def test_context_is_added_on_the_way_up() -> None:
    failure = F.TorsoGoalNotReached(goal=0.5).add_context(process_module="torso", command="move")
    assert failure.context == {"process_module": "torso", "command": "move"}
    assert "[process_module='torso', command='move']" in str(failure)


def test_custom_message_and_pickling_keep_data() -> None:
    failure = F.PerceptionObjectNotFound("no cup on the table", object_designator="cup")
    copy = pickle.loads(pickle.dumps(failure.add_context(module="perception")))
    assert type(copy) is F.PerceptionObjectNotFound
    assert (copy.object_designator, copy.message, copy.context) == (
        "cup",
        "no cup on the table",
        {"module": "perception"},
    )
    assert str(copy).startswith("no cup on the table (object_designator='cup')")


def test_unknown_failure_name_suggests_the_close_one() -> None:
    with pytest.raises(KeyError, match="torso-goal-not-reached"):
        failure_class("torso-goal-not-reachd")


def test_missing_attribute_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no attribute 'goall'"):
        _ = F.TorsoGoalNotReached(goal=1.0).goall


def test_fields_are_typed_attributes_mypy_can_see() -> None:
    hints = typing.get_type_hints(F.TorsoGoalNotReached)
    assert F.TorsoGoalNotReached.fields == ("goal", "limits", "reached")
    assert hints["goal"] == float | None
    assert hints["limits"] == tuple[float, float] | None
    assert typing.get_type_hints(F.ManipulationPoseUnreachable)["arm"] == str | None
    assert F.ManipulationPoseUnreachable.fields == (
        "arm",
        "target",
        "colliding_pairs",
        "beyond_reach",
    )
    assert "fields" not in F.ManipulationPoseUnreachable.__dict__.get("__annotations__", {})
