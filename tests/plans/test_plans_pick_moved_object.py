"""A pick's try is refused where the object no longer lies where its grasps were aimed.

In household 11 of the activity bench the HSR's first rim grasp of a bowl in a drawer
pushed it 5.4 cm; the next grasp, aimed at where it had been, still caught the rim off its
middle, and the bowl, carried as if held at its middle, was put down 5.5 cm off its seat.
"""

from __future__ import annotations

from collections.abc import Iterator

import pybullet
import pytest

from robocram.designators import ObjectDesignator, an
from robocram.plans import PickUpFailed, install_actions, pick_up_object
from robocram.plans.basic_actions import park_arms
from robocram.plans.grasp_failures import ObjectMovedSinceSeen
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import PoseStamped
from robocram.world import World

MOVED = 0.03  # [m] how far the mug lies from where the designator says it was seen


@pytest.fixture()
def scene() -> Iterator[TabletopScene]:
    made = tabletop_scene("pr2")
    install_actions(made.world.kb)
    yield made
    made.world.close()


def _joints(world: World, body: str) -> list[float]:
    """Every joint position of ``body``, read from PyBullet itself."""
    bid = world.object(body).body_id
    client = world.physics.client()
    count = pybullet.getNumJoints(bid, physicsClientId=client)
    return [pybullet.getJointState(bid, i, physicsClientId=client)[0] for i in range(count)]


def _seen_at(world: World, dx: float) -> ObjectDesignator:
    x, y, z = world.pose("mug-1").position
    return an.object(type="mug", name="mug-1", pose=PoseStamped("map", (x + dx, y, z)))


def test_a_mug_moved_since_it_was_seen_is_not_grasped_beside_it(scene: TabletopScene) -> None:
    world = scene.world
    with simulated_robot(world, scene.robot):
        park_arms()
        before = _joints(world, scene.robot)
        with pytest.raises(PickUpFailed) as failed:
            pick_up_object(_seen_at(world, MOVED))
        assert _joints(world, scene.robot) == pytest.approx(before, abs=1e-9)  # no try moved
        causes = failed.value.causes or []
        assert causes and all(isinstance(c, ObjectMovedSinceSeen) for c in causes)
        assert causes[0].moved == pytest.approx(MOVED, abs=1e-3)
        assert "perceive it again" in str(causes[0])
        held = pick_up_object(_seen_at(world, 0.0))  # seen where it lies: taken
    assert world.bodies.attached_to("mug-1") is not None
    assert held.object_name == "mug-1"
