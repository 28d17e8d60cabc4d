"""A grasp in a drawer that a finger was caught at is tried last with the hand opened a
third: the drafted Stretch takes the spoon lying beside the knife.

Household 6 (``benchmarks/activity_bench.py``) keeps the cutlery in ``east_drawers_3_drawer_3``;
the knife lies 8.2 cm beside spoon-1. Fully open (21 cm between the fingertips), the
Stretch's right fingertip came down on the knife and the closing met it on one side only;
half open (the usual retry) the fingertip still lay 1.2 cm over the knife's edge at the
grasp. The situation is rebuilt from the state saved at the household's first pick of
spoon-1 (tests/data/stretch_spoon_knife.json). Judged on raw PyBullet: the spoon leaves
the drawer's bottom in the hand, no finger was more than the hand's 5 mm bound in the knife
when the fingers closed on it, and the knife did not move.
"""

from __future__ import annotations

from pathlib import Path

import pybullet
import pytest

from robocram.plans import pick_object
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from tests.plans.household_state import rebuilt

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
DRAWER = ("kitchen", "east_drawers_3_drawer_3")
BOUND = 0.005  # [m] the hand may touch what it does not grip this deep at most


def test_the_stretch_takes_the_spoon_lying_beside_the_knife(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    household = rebuilt(STRETCH, "stretch_spoon_knife.json")
    world = household.world
    cid = world.physics.client()
    robot = world.robot(household.robot).body_id
    spoon, knife = world.object("spoon-1").body_id, world.object("knife-1").body_id
    knife_before = pybullet.getBasePositionAndOrientation(knife, physicsClientId=cid)
    bottom_before = pybullet.getAABB(spoon, -1, physicsClientId=cid)[0][2]
    in_knife: list[float] = []  # [m] the deepest robot point in the knife at each closing
    gripped = pick_object._gripped

    def measured(arm: str, name: str, choice: pick_object.ObjectGrasp) -> pick_object.ObjectGrasp:
        try:
            return gripped(arm, name, choice)
        finally:
            pybullet.performCollisionDetection(cid)
            points = pybullet.getClosestPoints(robot, knife, 0.0, physicsClientId=cid)
            in_knife.append(max((-p[8] for p in points), default=0.0))

    monkeypatch.setattr(pick_object, "_gripped", measured)
    try:
        with simulated_robot(world, household.robot):
            held = pick_up_object("spoon-1", out_of=DRAWER)
        assert held.object_name == "spoon-1"
        assert world.bodies.attachments(household.robot) == {"spoon-1": "link_wrist_roll"}
        bottom = pybullet.getAABB(spoon, -1, physicsClientId=cid)[0][2]
        assert bottom > bottom_before + 0.05  # lifted out of the drawer's bottom
        assert in_knife and in_knife[-1] <= BOUND  # the grip that held it
        knife_after = pybullet.getBasePositionAndOrientation(knife, physicsClientId=cid)
        assert knife_after[0] == pytest.approx(knife_before[0], abs=1e-6)
    finally:
        world.close()
