"""Inside ``simulated_robot`` location designators resolve through costmaps with no set-up."""

from __future__ import annotations

import itertools

from robocram.costmaps import CostmapLocations
from robocram.costmaps.validators import reach_object
from robocram.designators import a
from robocram.projection import simulated_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose


def test_reachable_for_resolves_in_a_projected_plan() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    designator = a.location(reachable_for="pr2", object="mug-1")
    with simulated_robot(world, "pr2"):
        first, second = itertools.islice(designator.solutions(), 2)
    expected = list(itertools.islice(CostmapLocations(world, seed=0).poses(designator), 2))
    assert [first, second] == expected  # the default resolver is seed-0 costmaps
    reach = reach_object(world, world.robot("pr2"), world.object("mug-1"), first)
    assert reach is not None
    world.close()


def test_pose_designators_still_resolve_to_their_pose() -> None:
    scene = tabletop_scene("pr2")
    with simulated_robot(scene.world, "pr2"):
        pose = a.location(pose=Pose((1.0, 2.0, 0.0))).reference()
    assert pose == Pose((1.0, 2.0, 0.0))  # no costmap key: the pose itself
    scene.world.close()
