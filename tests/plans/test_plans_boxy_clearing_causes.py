"""What stopped Boxy's clearing in session 24, on its smallest case, judged by raw PyBullet
(the milk's bounds against the fridge's, what holds it, the door's joint).
"""

from __future__ import annotations

from robocram.plans.clearing_table import clear_table
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from tests.milk_checks import assert_milk_back_in_the_fridge, milk_on_its_spot


def test_boxy_puts_the_milk_from_its_table_spot_back_under_the_fridge_shelf() -> None:
    """Taken from above on the table, no hand put the carton under the shelf; it is put
    down again and taken from the side."""
    scene = breakfast_scene("boxy")
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            milk_on_its_spot(world)
            done = clear_table(objects=["milk-1"])
        assert set(done.returned) == {"milk-1"}
        assert_milk_back_in_the_fridge(world, scene.robot)
    finally:
        world.close()
