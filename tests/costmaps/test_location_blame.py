"""``LocationNotFound`` names the object in the way (issue 35, item 6).

A judge's cluttered counters ended in "no location found" without a word about the box
that hid the mug or blocked every stand. Refused candidates now blame the objects their
rays met first or the robot would touch, and the failure names the most frequent.
"""

from __future__ import annotations

import pickle
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations, LocationNotFound
from robocram.costmaps.location_blame import LocationBlame
from robocram.costmaps.validators import robot_collision_free, visible
from robocram.designators import a
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

MUG = (-1.25, 2.11, 0.85)  # [m] where the kitchen scene puts mug-1 (its base, on the counter)


@pytest.fixture(scope="module")
def kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def _not_found(kitchen: KitchenScene, designator: object) -> LocationNotFound:
    with pytest.raises(LocationNotFound) as caught:
        list(CostmapLocations(kitchen.world).poses(designator))
    return caught.value


def add_screen(kitchen: KitchenScene) -> None:
    """A 2.4 m wide, 1 m tall board on the counter's front edge, before the mug."""
    x, y, z = MUG
    kitchen.world.add_box("box-3", (2.4, 0.04, 1.0), Pose((x, y - 0.15, z + 0.5)))


def add_pen(kitchen: KitchenScene) -> None:
    """Three boards 0.3 m tall round the mug, 1 cm from it: front, left and right."""
    x, y, z = MUG
    world, h, off = kitchen.world, 0.3, 0.074  # [m] height, from the mug's axis to a board's
    world.add_box("box-1", (0.6, 0.04, h), Pose((x, y - off, z + h / 2)))
    world.add_box("box-2", (0.04, 0.5, h), Pose((x - off, y + 0.1, z + h / 2)))
    world.add_box("box-4", (0.04, 0.5, h), Pose((x + off, y + 0.1, z + h / 2)))


def test_a_board_hiding_the_mug_from_every_stand_is_named(kitchen: KitchenScene) -> None:
    with kitchen.world.snapshots.stored_state():
        add_screen(kitchen)
        error = _not_found(kitchen, a.location(visible_for="pr2", object="mug-1"))
    message = str(error)
    assert error.occluded_by == ("box-3",) and error.blocked_by == ()
    assert "mug-1 is hidden from every stand by box-3 (in the way at " in message
    assert "move box-3 or look from elsewhere" in message
    assert error.emptied_by == ("visibility",)  # the advice before is still there
    copy = pickle.loads(pickle.dumps(error))
    assert copy.occluded_by == ("box-3",) and str(copy) == message


def test_a_board_hiding_a_target_point_is_named(kitchen: KitchenScene) -> None:
    """A point over the mug (as the search looks at a place): one ray per stand."""
    x, y, z = MUG
    with kitchen.world.snapshots.stored_state():
        add_screen(kitchen)
        error = _not_found(kitchen, a.location(visible_for="pr2", target=(x, y, z + 0.2)))
    assert error.occluded_by == ("box-3",)
    assert "the target (-1.25, 2.11, 1.05) is hidden from every stand by box-3" in str(error)


def test_boards_blocking_every_reaching_stand_are_named(kitchen: KitchenScene) -> None:
    with kitchen.world.snapshots.stored_state():
        add_pen(kitchen)
        error = _not_found(kitchen, a.location(reachable_for="pr2", object="mug-1"))
    message = str(error)
    assert set(error.blocked_by) == {"box-1", "box-2", "box-4"} and error.occluded_by == ()
    assert error.rejections["reachable"] > 0
    listed = " and ".join([", ".join(error.blocked_by[:-1]), error.blocked_by[-1]])
    assert f"every stand for mug-1 is blocked by {listed} (in the way at " in message
    assert f"move {listed} or stand elsewhere" in message
    assert "kitchen" not in error.blocked_by  # touched too, but it is the counter: not movable
    assert pickle.loads(pickle.dumps(error)).blocked_by == error.blocked_by


def test_a_crate_taking_every_stand_on_the_floor_is_named(kitchen: KitchenScene) -> None:
    x, _, _ = MUG
    with kitchen.world.snapshots.stored_state():
        kitchen.world.add_box("crate-1", (2.0, 0.7, 0.5), Pose((x, 1.45, 0.25)))
        error = _not_found(kitchen, a.location(reachable_for="pr2", object="mug-1"))
    assert error.blocked_by == ("crate-1",)
    assert "every stand for mug-1 is blocked by crate-1" in str(error)
    assert "move crate-1 or stand elsewhere" in str(error)


def test_the_visible_validator_blames_what_hides_the_target(kitchen: KitchenScene) -> None:
    world = kitchen.world
    x, y, _ = MUG
    stand = Pose((x, y - 1.0, 0.0), quat.from_euler(0.0, 0.0, 1.5708))  # [m] facing the mug
    with world.snapshots.stored_state():
        query = CostmapLocations(world).query(a.location(visible_for="pr2", object="mug-1"))
        assert visible(query, stand) and query.blame == LocationBlame()  # seen: no blame
        add_screen(kitchen)
        assert not visible(query, stand)
    assert query.blame.occluders == {"box-3": 1} and query.blame.occluded == 1


def test_the_collision_validator_blames_what_the_base_touches(kitchen: KitchenScene) -> None:
    world = kitchen.world
    stand = Pose((-1.0, 0.8, 0.0))  # [m] open floor
    with world.snapshots.stored_state():
        query = CostmapLocations(world).query(a.location(reachable_for="pr2", object="mug-1"))
        assert robot_collision_free(query, stand) and query.blame == LocationBlame()
        world.add_box("crate-2", (0.3, 0.3, 0.3), Pose((-1.0, 0.8, 0.15)))
        assert not robot_collision_free(query, stand)
    assert query.blame.blockers == {"crate-2": 1} and query.blame.blocked == 1


def test_a_failure_with_nobody_to_blame_names_nobody(kitchen: KitchenScene) -> None:
    locations = CostmapLocations(kitchen.world)
    locations.add_validator("reachable", lambda query, pose: False)  # refuses, blames nobody
    with pytest.raises(LocationNotFound) as caught:
        list(locations.poses(a.location(reachable_for="pr2", object="mug-1")))
    assert caught.value.blocked_by == () and caught.value.occluded_by == ()
    assert "blocked by" not in str(caught.value) and "hidden" not in str(caught.value)
