"""Plans' failures name the object in the way (issue 35, item 6).

A transport in a cluttered kitchen ended with ``SearchExhausted`` or ``FetchExhausted``
and never said which box hid the mug or took the stands; now the failure's fields
(``occluded_by``, ``blocked_by``) and the head of its message name it.
"""

from __future__ import annotations

import pickle
from collections.abc import Iterator

import numpy as np
import pytest

from robocram.costmaps import LocationNotFound
from robocram.designators import a, an
from robocram.execution import perform
from robocram.execution.failures import PerceptionObjectNotFound
from robocram.plans.errors import FetchExhausted, SearchExhausted
from robocram.plans.fetch import fetch
from robocram.plans.search import search
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose, PoseStamped

MUG = (-1.25, 2.11, 0.85)  # [m] where the kitchen scene puts mug-1 (its base, on the counter)
TABLE = ("kitchen", "table_top")


@pytest.fixture()
def kitchen() -> Iterator[KitchenScene]:
    scene = kitchen_scene("pr2")
    yield scene
    scene.world.close()


def test_a_transport_names_the_board_that_hides_the_mug(kitchen: KitchenScene) -> None:
    x, y, z = MUG
    kitchen.world.add_box("box-3", (2.4, 0.04, 1.0), Pose((x, y - 0.15, z + 0.5)))
    with simulated_robot(kitchen.world, kitchen.robot), pytest.raises(SearchExhausted) as caught:
        transport("mug", a.location(on=TABLE, for_="mug-1"))
    error = caught.value
    assert error.occluded_by == ("box-3",)
    assert str(error).startswith(
        "no mug seen from any place searched, hidden by box-3 (move it or look from elsewhere): "
    )
    bare = SearchExhausted(error.message, occluded_by=error.occluded_by)  # a live designator
    assert pickle.loads(pickle.dumps(bare)).occluded_by == ("box-3",)  # holds a lock: not sent


def test_a_transport_names_the_crate_that_takes_every_stand(kitchen: KitchenScene) -> None:
    x, _, _ = MUG
    kitchen.world.add_box("crate-1", (2.0, 0.7, 0.5), Pose((x, 1.45, 0.25)))  # on the floor
    with simulated_robot(kitchen.world, kitchen.robot), pytest.raises(FetchExhausted) as caught:
        transport("mug", a.location(on=TABLE, for_="mug-1"))
    error = caught.value
    assert error.blocked_by == ("crate-1",) and error.attempts == 0
    # no reachable stand left by the costmap, then every stand facing the mug collides
    assert str(error).startswith(
        "could not fetch mug-1, blocked by crate-1 (move it or stand elsewhere): "
        "the robot would collide at each of "
    )
    assert error.causes is not None and isinstance(error.causes[0], LocationNotFound)
    assert error.causes[0].blocked_by == ("crate-1",)


def test_fetching_names_the_boards_round_the_mug(kitchen: KitchenScene) -> None:
    x, y, z = MUG
    world, h, off = kitchen.world, 0.3, 0.074  # [m] boards' height, from the mug's axis
    world.add_box("box-1", (0.6, 0.04, h), Pose((x, y - off, z + h / 2)))
    world.add_box("box-2", (0.04, 0.5, h), Pose((x - off, y + 0.1, z + h / 2)))
    world.add_box("box-4", (0.04, 0.5, h), Pose((x + off, y + 0.1, z + h / 2)))
    where = PoseStamped.from_pose("map", world.pose("mug-1"))  # as if perceived before
    with simulated_robot(world, kitchen.robot), pytest.raises(FetchExhausted) as caught:
        fetch(an.object(type="mug", name="mug-1", pose=where))
    error = caught.value
    assert error.blocked_by is not None
    assert set(error.blocked_by) == {"box-1", "box-2", "box-4"}
    named = f"{', '.join(error.blocked_by[:2])} and {error.blocked_by[2]}"
    # the costmap's stands are blocked; from the stands facing it, the boards hide the mug
    assert str(error).startswith(
        "could not fetch mug-1 in 3 tries, hidden by box-1 and box-4 (move them or look from "
        f"elsewhere), blocked by {named} (move them or stand elsewhere)"
    )
    assert error.causes is not None
    cause = pickle.loads(pickle.dumps(error.causes[0]))  # a LocationNotFound did not pickle
    assert isinstance(cause, LocationNotFound) and cause.blocked_by == error.blocked_by
    assert str(cause) == str(error.causes[0])


def test_detecting_names_what_hides_the_mug_in_view(kitchen: KitchenScene) -> None:
    world = kitchen.world
    with simulated_robot(world, kitchen.robot):
        search("mug")  # the robot sees the mug now
        camera = np.asarray(world.view.camera(kitchen.robot).pose.position)
        mug = np.asarray(world.pose("mug-1").position)
        between = camera + 0.5 * (mug - camera)
        world.add_box("screen", (0.3, 0.3, 0.3), Pose(tuple(between.tolist())))
        with pytest.raises(PerceptionObjectNotFound) as caught:
            perform(a.motion(type="detecting", object=an.object(type="mug")))
    assert caught.value.occluded_by == ("screen",)
    assert "mug-1 is hidden by screen; move screen or look from elsewhere" in str(caught.value)
