"""An arm that reaches along a telescope takes a thing out of a shelf from a stand on the
approach line: the drafted Stretch brings the fridge's milk out.

The Stretch stands beside the opened fridge (household seed 0's second stand for the milk,
``benchmarks/activity_bench.py``). Every usual try fails: the lift 10 cm over the grasp is
4.3 cm over the lift's top, and the hand, its base turned, backs out only by a drive that
turns its fingers into the fridge (``test_plans_pick_drive_out.py``). The pick then stands
where the telescope's axis lies on the front grasp's approach line, 32 cm of telescope out
at the grasp (``costmaps/line_stand.py``), lifts the milk 5 cm (half the usual rise, within
the lift's reach) and draws it back along the line 30 cm, out of the fridge. Judged on raw
PyBullet: the milk is held over its shelf, wholly in front of the fridge, and neither the
robot nor the milk touches the kitchen.
"""

from __future__ import annotations

import math

import pybullet
import pytest

from robocram.costmaps.line_stand import LINE_MARGIN, line_stand
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from tests.plans.stretch_at_the_milk import stretch_at_the_milk

RISE = 0.05  # [m] the milk lifted over where it stood (half the usual 10 cm)
FRONT = ((0.6, 1.9579, 1.162), (0.6, 2.0579, 1.162))  # the front grasp's pre-grasp, grasp
LEVEL_HAND = (0.707107, 0.707107, 0.0, 0.0)  # its orientation (map)


def test_the_line_stand_lays_the_telescope_on_the_approach() -> None:
    scene = stretch_at_the_milk()
    world = scene.world
    try:
        out, grasp = (Pose(p, LEVEL_HAND) for p in FRONT)
        stand = line_stand(world, scene.robot, "arm", out, grasp)
        assert stand is not None
        # the arm works to the base's right (-y): on the approach (+y in map), the base
        # heads -x, its side square to the fridge's front
        assert (
            abs(math.remainder(quat.to_euler(stand.orientation)[2] - math.pi, 2 * math.pi)) < 1e-6
        )
        # back from the grasp by the approach, the margin and the arm's drawn-in length
        assert stand.position[1] < grasp.position[1] - (0.10 + LINE_MARGIN)
    finally:
        world.close()


def test_the_stretch_takes_the_milk_out_of_the_fridge_from_a_line_stand() -> None:
    scene = stretch_at_the_milk()
    world = scene.world
    cid = world.physics.client()
    try:
        kitchen, milk = world.object("kitchen"), world.object("milk-1")
        fridge = kitchen.link_index["fridge_body"]
        low_before = pybullet.getAABB(milk.body_id, -1, physicsClientId=cid)[0][2]
        with simulated_robot(world, scene.robot):
            held = pick_up_object("milk-1")
        assert held.object_name == "milk-1" and held.grasp == "right"
        (lo, hi) = pybullet.getAABB(milk.body_id, -1, physicsClientId=cid)
        assert lo[2] == pytest.approx(low_before + RISE, abs=0.01)  # held over its shelf
        front = pybullet.getAABB(kitchen.body_id, fridge, physicsClientId=cid)[0][1]
        assert hi[1] < front  # wholly in front of the fridge
        robot = world.robot(scene.robot)
        pybullet.performCollisionDetection(cid)
        for body in (robot.body_id, milk.body_id):
            touching = pybullet.getClosestPoints(body, kitchen.body_id, 0.0, physicsClientId=cid)
            assert not touching
    finally:
        world.close()
