"""A grasp whose closed fingers would lie in the surface under the thing is tried again a
little higher (``pick_object.RAISES``): the drafted Stretch's curved fingertips, closing on
a spoon flat on the table, dipped into the table's top at every stand, and both spoons of
household 0 stayed on the table (session 31). The situation is rebuilt from the state the
household's setting left (tests/data/stretch_table_set.json); where the spoon ends is
judged by raw PyBullet."""

from __future__ import annotations

from pathlib import Path

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from tests.plans.household_state import inside, rebuilt

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
DRAWER = "cutlery_unit_drawer_3"  # where the kitchen keeps spoons


def test_the_stretch_takes_the_spoon_from_the_table_to_its_drawer() -> None:
    household = rebuilt(STRETCH, "stretch_table_set.json")
    world, robot = household.world, household.robot
    try:
        assert not inside(world, "spoon-1", DRAWER)
        with simulated_robot(world, robot):
            perform(an.action(type="clearing-table", objects=["spoon-1"]))
        assert inside(world, "spoon-1", DRAWER)
        assert world.bodies.attachments(robot) == {}
    finally:
        world.close()
