"""``on`` / ``in_`` locations, bad input and reproducibility, in a real PyBullet world."""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import pytest

from robocram.costmaps import CostmapError, CostmapInputError, CostmapLocations, LocationKeyError
from robocram.costmaps.surface_costs import RESTING_GAP, SURFACE_MARGIN
from robocram.designators import a, using_location_resolver
from robocram.tf import Pose
from robocram.world import World

TABLE = (1.5, 0.0, 0.7)  # [m] centre x, y and height of the table top
TABLE_SIZE = (0.6, 1.0)


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("pr2")
        w.add_box("table", (*TABLE_SIZE, TABLE[2]), pose=Pose((TABLE[0], TABLE[1], TABLE[2] / 2)))
        w.add_item("mug", "mug", pose=(0.0, 2.0, 0.0))
        w.add_item("bottle", "bottle", pose=(TABLE[0], 0.3, TABLE[2] + 0.125))
        w.add_box("drawer-bottom", (0.4, 0.4, 0.02), pose=(0.0, -2.0, 0.4))
        yield w


def test_on_table_poses_lie_on_the_top_within_the_margin(world: World) -> None:
    locs = CostmapLocations(world, resolution=0.02)
    poses = list(itertools.islice(locs.poses(a.location(on="table", for_="mug")), 10))
    mug_low, mug_high = world.aabb("mug")
    radius = max(mug_high[0] - mug_low[0], mug_high[1] - mug_low[1]) / 2
    bottle = world.pose("bottle").position
    for pose in poses:
        x, y, z = pose.position
        assert abs(x - TABLE[0]) <= TABLE_SIZE[0] / 2 - SURFACE_MARGIN - radius + 0.02
        assert abs(y - TABLE[1]) <= TABLE_SIZE[1] / 2 - SURFACE_MARGIN - radius + 0.02
        assert TABLE[2] <= z <= TABLE[2] + 0.01  # the mug's frame is at its bottom
        assert (x - bottle[0]) ** 2 + (y - bottle[1]) ** 2 > (0.035 + radius) ** 2


def test_a_mug_put_on_the_table_stays_there(world: World) -> None:
    locs = CostmapLocations(world, resolution=0.02, seed=3)
    with using_location_resolver(locs.resolver()):
        pose = a.location(on="table", for_="mug").reference()
    with world.snapshots.stored_state():
        world.set_pose("mug", pose)
        world.physics.simulate(1.0)
        assert world.physics.supported_by("mug", "table")
        assert world.pose("mug").distance_to(pose) < 0.01
        assert world.physics.stable("mug")


def test_same_seed_same_poses(world: World) -> None:
    def first(seed: int) -> list[tuple[float, float, float]]:
        locs = CostmapLocations(world, seed=seed)
        return [p.position for p in itertools.islice(locs.poses(a.location(on="table")), 5)]

    assert first(4) == first(4)
    assert first(4) != first(5)


@pytest.mark.parametrize(
    ("designator", "error", "culprit"),
    [
        (a.location(on="table", colour="red"), LocationKeyError, "colour"),
        (a.location(on="table", in_="drawer-bottom"), LocationKeyError, "in_"),
        (a.location(on="sofa"), CostmapInputError, "sofa"),
        (a.location(visible_for="pr3", object="mug"), CostmapInputError, "pr3"),
        (a.location(on="table", resolution=0.0), CostmapInputError, 0.0),
        (a.location(on="table", resolution=-1), CostmapInputError, -1),
    ],
)
def test_bad_input_gets_a_typed_error(
    world: World, designator: object, error: type[CostmapError], culprit: object
) -> None:
    locs = CostmapLocations(world)
    with pytest.raises(error) as caught:
        next(locs.poses(designator))
    assert caught.value.culprit == culprit
    assert str(culprit) in str(caught.value)


def test_visible_for_a_robot_without_a_camera() -> None:
    with World() as w:
        w.bodies.add_floor()
        w.add_robot("quadrotor")
        w.add_item("mug", "mug", pose=(1.0, 0.0, 0.0))
        with pytest.raises(CostmapInputError, match="no camera") as caught:
            next(CostmapLocations(w).poses(a.location(visible_for="quadrotor", object="mug")))
        assert caught.value.culprit == "quadrotor"


def test_a_pose_on_the_table_lies_the_resting_gap_above_the_mugs_true_bottom(
    world: World,
) -> None:
    """The mug's frame is 1 mm above its bottom (its Bullet bounds say 3 mm): the pose
    puts the bottom RESTING_GAP over the top, so a mug let go there drops 2 mm."""
    locs = CostmapLocations(world, resolution=0.02)
    pose = next(iter(locs.poses(a.location(on="table", for_="mug"))))
    frame_over_bottom = 0.001
    assert pose.position[2] == pytest.approx(TABLE[2] + frame_over_bottom + RESTING_GAP, abs=2e-4)
    assert world.pose("mug").position[2] - world.aabb("mug")[0][2] > frame_over_bottom + 0.001
