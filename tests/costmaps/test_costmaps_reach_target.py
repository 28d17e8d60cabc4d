"""A stand from which the robot reaches a place, not an object: CRAM's (location ?target)."""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapLocations
from robocram.costmaps.validators import reach_point
from robocram.designators import a
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose


@pytest.fixture(scope="module", params=["pr2", "hsrb"])
def kitchen(request: pytest.FixtureRequest) -> Iterator[KitchenScene]:
    scene = kitchen_scene(request.param)
    yield scene
    scene.world.close()


def _spot_on_table(scene: KitchenScene) -> tuple[float, float, float]:
    """8 cm over the table, 15 cm in from its long edge facing the room (its centre is out
    of the PR2's reach from every side: the table is 0.9 m deep)."""
    low, high = scene.world.contacts.link_aabb("kitchen", "table_top")
    return ((low[0] + high[0]) / 2, high[1] - 0.15, high[2] + 0.08)


def test_each_stand_reaches_the_spot_with_ik_and_stays_near(kitchen: KitchenScene) -> None:
    world = kitchen.world
    robot = world.robot(kitchen.robot)
    spot = _spot_on_table(kitchen)
    locations = CostmapLocations(world, seed=0)
    designator = a.location(reachable_for=kitchen.robot, target=spot)
    stands = list(itertools.islice(locations.poses(designator), 3))
    assert len(stands) == 3
    for stand in stands:
        distance = ((stand.position[0] - spot[0]) ** 2 + (stand.position[1] - spot[1]) ** 2) ** 0.5
        assert distance < 1.2  # an arm's length, not across the room
        reach = reach_point(world, robot, spot, stand)
        assert reach is not None
        tool = Pose(stand.position, stand.orientation) * reach.tool_in_base
        if reach.base_motion is None:  # the tool pose is over the spot, from above
            assert tool.position == pytest.approx(spot, abs=1e-6)


def test_a_spot_out_of_every_arms_reach_is_refused(kitchen: KitchenScene) -> None:
    world = kitchen.world
    robot = world.robot(kitchen.robot)
    spot = _spot_on_table(kitchen)
    far = Pose((spot[0] + 3.0, spot[1], 0.0))
    assert reach_point(world, robot, spot, far) is None
