"""Transport's failures: each with its type, its causes and its retries within bounds."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.designators import DesignatorPropertyError, a, an
from robocram.execution import TaskListener, listening, perform
from robocram.execution.failures import (
    ManipulationLowLevelFailure,
    NavigationPoseUnreachable,
    ObjectUndeliverable,
    ObjectUnfetchable,
    PerceptionObjectNotFound,
)
from robocram.plans import install_actions
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.deliver import deliver
from robocram.plans.errors import DeliveryExhausted, FetchExhausted, SearchExhausted
from robocram.plans.fetch import fetch
from robocram.plans.grasp_failures import PickUpFailed, PlacingFailed
from robocram.plans.search import search
from robocram.plans.stands import STAND_TURNS
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene


class MotionCounter(TaskListener):
    """Counts the PERFORMs of one motion type."""

    def __init__(self, motion_type: str) -> None:
        self.motion_type = motion_type
        self.count = 0

    def performing(self, task: object, designator: object) -> None:
        if getattr(designator, "get", lambda _: None)("type") == self.motion_type:
            self.count += 1


SURFACES = ("counter_top_north", "counter_top_east", "sink", "stove", "table_top")
FRIDGE_TOP = ("kitchen", "fridge_body")  # 1.8 m up: no arm of the PR2 gets there


@pytest.fixture()
def pr2_kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def test_an_unreachable_target_surface_makes_the_mug_undeliverable(
    pr2_kitchen: KitchenScene,
) -> None:
    log = AttemptLog()
    target = a.location(on=FRIDGE_TOP, for_="mug-1")
    with simulated_robot(pr2_kitchen.world, pr2_kitchen.robot):
        held = fetch("mug", log=log)
        with pytest.raises(DeliveryExhausted) as caught:
            deliver(held, target, stand_retries=2, place_retries=2, log=log)
    failure = caught.value
    assert isinstance(failure, ObjectUndeliverable)
    assert failure.causes
    # a stand beside the fridge puts the held mug (at counter height) into the fridge's
    # body, so driving there fails; where it does not, the arm cannot put it up there
    placing = [c for c in failure.causes if not isinstance(c, NavigationPoseUnreachable)]
    assert all(isinstance(c, ManipulationLowLevelFailure | PlacingFailed) for c in placing)
    assert any("kitchen" in str(c) for c in failure.causes)
    tries = log.of("deliver")
    assert failure.attempts == len(tries)
    assert len(tries) <= 2 * STAND_TURNS  # two spots, at most every turn about each
    assert len(placing) <= 2 * 2  # at most stand_retries placings per spot
    assert pr2_kitchen.world.bodies.attached_to("mug-1") is not None  # still in the hand


def test_an_absent_object_is_not_found_after_every_place_was_visited(
    pr2_kitchen: KitchenScene,
) -> None:
    log = AttemptLog()
    drives = MotionCounter("going")
    target = a.location(on=("kitchen", "table_top"), for_="mug-1")
    with (
        simulated_robot(pr2_kitchen.world, pr2_kitchen.robot),
        listening(drives),
        pytest.raises(SearchExhausted) as caught,
    ):
        transport("pot", target, poses_per_place=1, log=log)
    assert isinstance(caught.value, PerceptionObjectNotFound)
    assert caught.value.searched == SURFACES  # every candidate place, in the KB's order
    assert 1 <= drives.count <= len(SURFACES)  # at most one stand per place (poses_per_place)
    assert log.of("fetch") == [] and log.of("deliver") == []  # it never got further


def test_fetching_stops_after_its_bound_with_every_cause(pr2_kitchen: KitchenScene) -> None:
    """A grasp the mug does not offer (a rim: it is no bowl) fails at every stand: exactly
    ``stand_retries`` tries, each with its own cause."""
    log = AttemptLog()
    with simulated_robot(pr2_kitchen.world, pr2_kitchen.robot):
        seen = search("mug")
        with pytest.raises(FetchExhausted) as caught:
            fetch(seen, grasp="rim", stand_retries=2, log=log)
    assert isinstance(caught.value, ObjectUnfetchable)
    assert len(log.of("fetch")) == 2
    assert caught.value.attempts == 2
    assert [type(c) for c in caught.value.causes or ()] == [PickUpFailed, PickUpFailed]
    assert all(not attempt.succeeded for attempt in log.of("fetch"))
    stands = [attempt.stand for attempt in log.of("fetch")]
    assert stands[0] != stands[1]  # the second try took the next solution


@pytest.mark.parametrize(
    ("properties", "culprit"),
    [
        ({"type": "transporting", "object": "mug", "targett": (0.0, 0.0, 0.8)}, "targett"),
        ({"type": "transporting", "object": "mug"}, "target"),
        ({"type": "fetching", "object": "mug", "stand_retires": 2}, "stand_retires"),
        ({"type": "delivering", "target": (0.0, 0.0, 0.8)}, "object"),
    ],
)
def test_transport_actions_check_their_keys(
    pr2_kitchen: KitchenScene, properties: dict[str, object], culprit: str
) -> None:
    install_actions(pr2_kitchen.world.kb)
    with (
        simulated_robot(pr2_kitchen.world, pr2_kitchen.robot),
        pytest.raises(DesignatorPropertyError, match="valid keys") as caught,
    ):
        perform(an.action(**properties))
    assert caught.value.key == culprit
    assert "stand_retries" in str(caught.value)
