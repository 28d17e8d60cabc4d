"""A robot whose base is fixed carries things across its workcell with the kitchen's plan.

The Z1 and the Panda (lone arms of ``examples/robots``; the Panda's draft is fixed since
zoo13: one chain ending in its hand's two fingers) run the same ``transport`` action the
mobile robots run in the kitchen: no stand but where it is mounted. PyBullet judges: where the
mug and the bowl end up, and that the robot's base, the pedestal and the table stayed.
"""

from __future__ import annotations

import math
from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans import perform
from robocram.projection import simulated_robot
from robocram.robot_check import description_from
from robocram.scenes import workcell_scene, workcell_spots

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"
PLACED = 0.02  # [m] an item put down lies this near its spot, across the table
SETTLED = 0.01  # [m] and as high as it rested before, within this (it stands, not lies)
STILL = 1e-6  # [m] what is not carried does not move


def _position(world_id: int, body: int) -> tuple[float, float, float]:
    position, _ = pybullet.getBasePositionAndOrientation(body, physicsClientId=world_id)
    return (float(position[0]), float(position[1]), float(position[2]))


@pytest.mark.parametrize("robot", ["z1", "panda"])
def test_a_lone_arm_carries_the_mug_then_the_bowl_across_its_table(robot: str) -> None:
    scene = workcell_scene(description_from(str(EXAMPLES / f"{robot}.py")))
    world = scene.world
    try:
        assert world.robot(scene.robot).description.drive == "fixed"
        client = world.physics.client()
        bodies = {o.name: o.body_id for o in world.objects() if o.type != "floor"}
        spots = workcell_spots(scene)
        before = {name: _position(client, body) for name, body in bodies.items()}
        with simulated_robot(world, scene.robot):
            for kind, item in (("mug", "mug-1"), ("bowl", "bowl-1")):
                perform(an.action(type="transporting", object=kind, target=spots[item]))
        for item in ("mug-1", "bowl-1"):
            x, y, z = _position(client, bodies[item])
            sx, sy, _ = spots[item].position
            assert math.hypot(x - sx, y - sy) < PLACED, item
            assert z == pytest.approx(before[item][2], abs=SETTLED), item
        mug, bowl = before["mug-1"], before["bowl-1"]
        assert abs(mug[1] - bowl[1]) > 0.1  # the spots are apart: each item really moved
        for name in set(bodies) - {"mug-1", "bowl-1"}:  # the robot, its pedestal, the table
            assert _position(client, bodies[name]) == pytest.approx(before[name], abs=STILL)
    finally:
        world.close()
