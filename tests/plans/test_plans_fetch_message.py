"""``FetchExhausted`` counts what happened: "in 0 tries" read like a bug (issue 27, item 3).

A try is a stand where picking up was tried. When the location designator found no stand
at all, the message says so; when every stand found was blocked, it says that.
"""

from __future__ import annotations

from robocram.designators.errors import GroundingError
from robocram.execution.failures import ManipulationGoalNotReached, NavigationPoseUnreachable
from robocram.plans.fetch import exhausted_message

NO_LOCATION = GroundingError("(a location (reachable-for pr2) (object mug-1)): no location found")


def _blocked() -> NavigationPoseUnreachable:
    return NavigationPoseUnreachable(
        "pr2 at (-0.690, -0.955, -1.034) would collide with ['kitchen']", target="x" * 300
    )


def test_no_stand_found_is_said_with_the_designator_error() -> None:
    assert exhausted_message("mug-1", 0, [NO_LOCATION]) == (
        "no stand found for mug-1: GroundingError: (a location (reachable-for pr2) "
        "(object mug-1)): no location found"
    )


def test_only_blocked_stands_are_counted_as_blocked_not_as_tries() -> None:
    assert exhausted_message("mug-1", 0, [_blocked(), _blocked(), NO_LOCATION]) == (
        "could not fetch mug-1: the robot would collide at each of 2 stands; the last: "
        "GroundingError: (a location (reachable-for pr2) (object mug-1)): no location found"
    )


def test_tries_are_counted_and_the_last_cause_is_named_without_its_data() -> None:
    reach = ManipulationGoalNotReached("the tool stopped 3 cm short", target="y" * 300)
    assert exhausted_message("mug-1", 1, [reach]) == (
        "could not fetch mug-1 in 1 try; the last: ManipulationGoalNotReached: "
        "the tool stopped 3 cm short"
    )
    assert exhausted_message("mug-1", 2, [_blocked(), reach, reach]).startswith(
        "could not fetch mug-1 in 2 tries; the last: ManipulationGoalNotReached"
    )
