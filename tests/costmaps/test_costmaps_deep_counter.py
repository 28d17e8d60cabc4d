"""A mug deep on the counter is reachable from a stand the base's corner circle ruled out.

Batch variants with the mug 26 cm in from the counter's front edge failed every time:
occupancy kept the PR2 0.47 m (the circle round its base's corners) from the counter,
where its arm falls short. The base facing the counter needs only half its width.
"""

from __future__ import annotations

from robocram.costmaps import CostmapLocations
from robocram.designators import a, an
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

DEEP_MUG = Pose((-1.1724, 2.1478, 0.855), quat.from_euler(0.0, 0.0, -2.499 + 3.1416))


def test_a_stand_is_found_for_a_mug_deep_on_the_counter() -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    world.set_pose("mug-1", DEEP_MUG)
    front = world.contacts.link_aabb("kitchen", "counter_top_north")[0][1]  # [m] its front edge's y
    locations = CostmapLocations(world, seed=0)
    designator = a.location(reachable_for="pr2", object=an.object(name="mug-1"))
    stand = next(locations.poses(designator))  # raised LocationNotFound before
    # nearer the counter than the corner circle allowed, no nearer than half the base
    assert front - 0.472 < stand.position[1] <= front - 0.334 + 0.05
    world.close()
