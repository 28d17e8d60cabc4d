"""A pick whose every try failed leaves no hand gripping the thing (session 25, household
seed 6: Boxy's right hand gripped spoon-2 in an east drawer, its lift was blocked, no
later try opened the hand, and Boxy parked and drove off with the spoon), judged by raw
PyBullet (the spoon still in its drawer after the arms park)."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pybullet
import pytest

from robocram.designators import an
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.basic_actions import navigate, park_arms
from robocram.plans.bringing import Visit, find, usual_place
from robocram.plans.grasp_failures import PickUpFailed
from robocram.plans.known_robot import current_robot
from robocram.plans.pick_object import grasp_object, pick_up_object
from robocram.plans.stands import front_stands, yaw_of
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import transform_pose
from robocram.world import World

sys.path.insert(0, str(Path(__file__).parents[2] / "benchmarks"))
from activity_bench import variant  # noqa: E402 - the bench's households

SEED = 6  # the spoons in east_drawers_3_drawer_3
REACH = 0.75  # [m] the right shoulder this far in front of the spoon: its hand reaches the
# spoon there, but no lift of it out of the drawer (each try fails before the hand moves)


def _position(world: World, name: str) -> tuple[float, ...]:
    """An object's position by PyBullet."""
    cid = world.physics.client()
    uid = world.object(name).body_id
    return tuple(pybullet.getBasePositionAndOrientation(uid, physicsClientId=cid)[0])


def test_a_pick_that_failed_leaves_no_hand_gripping_the_spoon() -> None:
    kept, places = variant(SEED)
    scene = breakfast_scene("boxy", places=places, kept=kept)
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            wanted = an.object(type="spoon", name="spoon-2")
            seen, opened = find(wanted, Visit(usual_place("spoon")), AttemptLog())
            assert opened is not None
            where = transform_pose(seen.get("pose"), "map")
            out = yaw_of(opened.stand.pose) + math.pi
            stand = next(front_stands(current_robot(), ["right"], where.pose, out, (REACH,)))
            park_arms()
            navigate(stand.pose)
            spoon = an.object(type="spoon", name="spoon-2", pose=where)  # in map
            grasp_object(spoon, arm="right")  # gripped where it lies, as a blocked lift leaves it
            before = _position(world, "spoon-2")
            drawer = (opened.container.environment, opened.container.link)
            with pytest.raises(PickUpFailed):
                pick_up_object(spoon, arm="right", out_of=drawer)
            assert current_robot().held_objects(["right"]) == {}
            park_arms()  # a hand still holding it would carry it off
        after = _position(world, "spoon-2")
        assert math.dist(before, after) < 0.01  # still where it lay in the drawer
    finally:
        world.close()
