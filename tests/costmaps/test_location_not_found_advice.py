"""``LocationNotFound`` names what removed the candidates and gives only advice that applies.

Issue 26, item 8: the message ended "widen the search area, loosen the keys or clear the
obstacles" whatever happened, also for an object out of reach, where none of that helps.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations, LocationNotFound
from robocram.costmaps.cost_layer import LocationQuery
from robocram.costmaps.cost_registry import BUILTIN_COST_FUNCTIONS, BUILTIN_VALIDATORS
from robocram.costmaps.location_advice import (
    GENERIC_ADVICE,
    LAYER_ADVICE,
    VALIDATOR_ADVICE,
)
from robocram.designators import a
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import Pose

WIDEN = "widen the search area"


@pytest.fixture(scope="module")
def scene() -> Iterator[TabletopScene]:
    scene = tabletop_scene("pr2")
    yield scene
    scene.world.close()


def _not_found(locations: CostmapLocations, designator: object) -> LocationNotFound:
    with pytest.raises(LocationNotFound) as caught:
        list(locations.poses(designator))
    return caught.value


def test_every_builtin_layer_and_validator_has_its_own_advice() -> None:
    assert set(LAYER_ADVICE) == set(BUILTIN_COST_FUNCTIONS)
    assert set(VALIDATOR_ADVICE) == set(BUILTIN_VALIDATORS)


def test_an_object_out_of_reach_blames_the_reachability_layer(scene: TabletopScene) -> None:
    world = scene.world
    x, y, _ = world.pose("mug-1").position
    with world.snapshots.stored_state():
        world.set_pose("mug-1", Pose((x, y, 3.0)))  # 3 m up: no arm gets there
        error = _not_found(CostmapLocations(world), a.location(reachable_for="pr2", object="mug-1"))
    message = str(error)
    assert error.emptied_by == ("reachability",)
    assert error.rejections == {} and error.accepted == 0
    assert "no candidates at all" in message  # the first part is unchanged
    assert "the reachability layer left no cell" in message
    assert LAYER_ADVICE["reachability"] in message
    assert WIDEN not in message and "clear the obstacles" not in message


def test_a_walled_in_stand_area_blames_the_occupancy_layer(scene: TabletopScene) -> None:
    world = scene.world
    x, y, _ = world.pose("mug-1").position
    with world.snapshots.stored_state():
        world.add_box("slab", (3.0, 3.0, 0.05), Pose((x, y, 0.025)))  # no base fits anywhere
        error = _not_found(CostmapLocations(world), a.location(reachable_for="pr2", object="mug-1"))
    message = str(error)
    assert error.emptied_by == ("occupancy",)
    assert "the occupancy layer left no cell: every cell within reach is blocked" in message
    assert "reachability" not in message and WIDEN not in message


def test_a_hidden_target_blames_the_visibility_layer(scene: TabletopScene) -> None:
    world = scene.world
    x, y, z = world.pose("mug-1").position
    with world.snapshots.stored_state():
        _shut_in(scene, (x, y, z))
        locations = CostmapLocations(world, size=2.0, resolution=0.1)
        error = _not_found(locations, a.location(visible_for="pr2", target=(x, y, z + 0.05)))
    message = str(error)
    assert error.emptied_by == ("visibility",)
    assert error.rejections == {}
    assert "the visibility layer left no cell: no cell within the camera's range" in message
    assert "occupancy" not in message and WIDEN not in message


def _shut_in(scene: TabletopScene, point: tuple[float, float, float]) -> None:
    """A hollow crate (a lid on four walls, 0.3 m wide) on the table round ``point``: a ray
    cast from inside a solid box would not hit it, so the walls must be separate."""
    x, y, z = point
    side, thick, high = 0.3, 0.02, 0.3
    scene.world.add_box("lid", (side, side, thick), Pose((x, y, z + high)))
    for i, (dx, dy) in enumerate(((1, 0), (-1, 0), (0, 1), (0, -1))):
        size = (thick, side, high) if dx else (side, thick, high)
        scene.world.add_box(
            f"wall-{i}", size, Pose((x + dx * side / 2, y + dy * side / 2, z + high / 2))
        )


def test_refused_candidates_name_the_validators_and_their_advice(scene: TabletopScene) -> None:
    locations = CostmapLocations(scene.world)
    locations.add_validator("reachable", lambda query, pose: False)  # no grasp works anywhere
    error = _not_found(locations, a.location(reachable_for="pr2", object="mug-1"))
    message = str(error)
    assert error.rejections["reachable"] > 0 and error.accepted == 0
    assert f"reachable ({error.rejections['reachable']}): {VALIDATOR_ADVICE['reachable']}" in (
        message
    )
    assert "layer left no cell" not in message and WIDEN not in message
    assert "ran dry" not in message


def test_a_users_validator_is_named_with_generic_advice(scene: TabletopScene) -> None:
    world = scene.world
    world.kb.consult("location_validator(near, never).", group="test_never_advice")
    locations = CostmapLocations(world, max_rejections=7)
    locations.add_validator("never", lambda query, pose: False)
    error = _not_found(locations, a.location(near="mug-1"))
    world.kb.consult("", group="test_never_advice")
    message = str(error)
    assert error.rejections == {"never": 7}
    assert message.endswith("never (7): validator 'never' refused them: check what it tests")
    assert GENERIC_ADVICE not in message


def test_a_stream_that_runs_dry_says_how_many_it_accepted(scene: TabletopScene) -> None:
    world = scene.world
    world.kb.consult("location_validator(near, first_two).", group="test_first_two")
    calls: list[Pose] = []

    def first_two(query: LocationQuery, pose: Pose) -> bool:
        calls.append(pose)
        return len(calls) <= 2

    locations = CostmapLocations(world, max_rejections=5)
    locations.add_validator("first_two", first_two)
    error = _not_found(locations, a.location(near="mug-1"))
    world.kb.consult("", group="test_first_two")
    message = str(error)
    assert error.accepted == 2 and error.rejections == {"first_two": 5}
    assert "(first_two rejected 5; 2 accepted before)" in message
    assert "the stream ran dry after 2 accepted (5 refused in a row): first_two (5)" in message
    assert WIDEN not in message


def test_a_wide_search_area_is_not_told_to_widen(scene: TabletopScene) -> None:
    """Issue 37: "widen `size`" was advised when a 6 m square did not help."""
    world = scene.world
    x, y, _ = world.pose("mug-1").position
    with world.snapshots.stored_state():
        world.add_box("slab", (3.0, 3.0, 0.05), Pose((x, y, 0.025)))  # no base fits anywhere
        wide = CostmapLocations(world, size=6.0, resolution=0.1)
        error = _not_found(wide, a.location(reachable_for="pr2", object="mug-1"))
    message = str(error)
    assert error.emptied_by == ("occupancy",) and error.area == pytest.approx(6.0, abs=0.1)
    assert "widen `size`" not in message and "widening the search area cannot help" in message
    assert "clear the obstacles there" in message
