"""Searching: usual places first, bounded retries, PerceptionObjectNotFound naming every place."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations
from robocram.designators import LocationDesignator, using_location_resolver
from robocram.designators.errors import GroundingError
from robocram.execution.failures import PerceptionObjectNotFound
from robocram.plans.errors import SearchExhausted
from robocram.plans.search import SearchLog, search
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene

SURFACES = ["counter_top_north", "counter_top_east", "sink", "stove", "table_top"]


@pytest.fixture(scope="module", params=["pr2", "hsrb", "boxy"])
def kitchen(request: pytest.FixtureRequest) -> Iterator[KitchenScene]:
    scene = kitchen_scene(request.param)
    yield scene
    scene.world.close()


def _search(scene: KitchenScene, object_type: str, log: SearchLog, poses: int = 2) -> object:
    locations = CostmapLocations(scene.world, seed=0)
    with simulated_robot(scene.world, scene.robot), using_location_resolver(locations.resolver()):
        return search(object_type, poses_per_place=poses, log=log)


def test_the_mug_is_found_at_its_usual_place_first(kitchen: KitchenScene) -> None:
    log = SearchLog()
    with kitchen.world.snapshots.stored_state():
        seen = _search(kitchen, "mug", log)
        assert kitchen.world.view.visible(kitchen.robot, "mug-1")
    assert seen.get("name") == "mug-1"  # type: ignore[attr-defined]
    assert [p.link for p in log.searched] == ["counter_top_north"]


@pytest.mark.parametrize("poses", [1, 2])
def test_an_absent_object_is_searched_for_everywhere_then_not_found(
    kitchen: KitchenScene, poses: int
) -> None:
    log = SearchLog()
    with kitchen.world.snapshots.stored_state(), pytest.raises(SearchExhausted) as caught:
        _search(kitchen, "pot", log, poses)
    assert isinstance(caught.value, PerceptionObjectNotFound)
    assert caught.value.searched == tuple(SURFACES)  # every supporting surface, in KB order
    assert 1 <= len(log.failures) <= poses * len(SURFACES)  # retries stay within the bound
    assert "table_top" in str(caught.value)


def test_a_stand_stream_running_dry_ends_that_places_looks_not_the_search(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Boxy's breakfast (seeded household 1) stopped with a bare ``LocationNotFound``: the
    next stand for a look at a counter, after a look that failed, ran the stream dry."""

    def dry(self: LocationDesignator, kb: object = None, *, resolver: object = None) -> None:
        raise GroundingError("no more stands (the stream ran dry)", self)

    monkeypatch.setattr(LocationDesignator, "next_solution", dry)
    scene = kitchen_scene("pr2")
    log = SearchLog()
    try:
        with pytest.raises(SearchExhausted) as caught:
            _search(scene, "pot", log, poses=2)
    finally:
        scene.world.close()
    assert caught.value.searched == tuple(SURFACES)  # every place still looked at
    dried = [f for f in log.failures if isinstance(f, GroundingError)]
    assert len(dried) == len(SURFACES)  # one dry stream per place, each recorded
