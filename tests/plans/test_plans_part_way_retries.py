"""A grasp a finger was caught at is tried again, after every other, with the hand opened
part way: a third for a rim grasp, half for a grasp round the whole object.

The drafted Stretch's fingers, fully open, span 12-13 cm. In household seed 0 of
``benchmarks/activity_bench.py``:
- the bowls lie 1 cm nearer the front of their opened drawer than in the default kitchen:
  every rim grasp of bowl-2 put the outer finger into bowl-1 or the drawer's front (IK
  solutions refused for a fingertip, a grip met bowl-1 on one side). Opened a third, the
  hand takes bowl-2 from where it first stood;
- cup-2 stands 4 cm from the west wall of its opened drawer, under the counter top's edge:
  the open fingers closing along the drawer met the top over it; closing across it, the
  outer fingertip slid down outside the drawer's side wall and met it when the grip
  closed. Opened half way, the hand takes cup-2 from above.

Judged on raw PyBullet: the thing is lifted clear of the drawer's top, and its neighbour
has not moved.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pybullet
import pytest

from robocram.plans.containers import container
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import BREAKFAST_PLACES, breakfast_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat

STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")
STILL = 0.005  # [m] the neighbour moved no more than this


@pytest.mark.parametrize(
    ("drawer", "seed_0", "stand", "taken", "neighbour", "grasp"),
    [
        pytest.param(
            "drawer_unit_drawer_3",
            {"bowl-1": (-0.2462, 0.12), "bowl-2": (-0.2497, -0.12)},  # [m] in the drawer
            Pose((-1.49, 1.059, 0.0), quat.from_euler(0.0, 0.0, 3.1416)),  # where it peered in
            "bowl-2",
            "bowl-1",
            "rim",
            id="bowl-rim-a-third",
        ),
        pytest.param(
            "cutlery_unit_drawer_4",
            {"cup-1": (-0.2432, 0.18), "cup-2": (-0.2496, -0.18)},
            Pose((-0.267, 1.1963, 0.0), quat.from_euler(0.0, 0.0, -2.9439)),
            "cup-2",
            "cup-1",
            "top",
            id="cup-top-half-way",
        ),
    ],
)
def test_a_caught_grasp_takes_the_thing_with_the_hand_opened_part_way(
    drawer: str,
    seed_0: dict[str, tuple[float, float]],
    stand: Pose,
    taken: str,
    neighbour: str,
    grasp: str,
) -> None:
    places = [replace(p, xy=seed_0[p.name]) if p.name in seed_0 else p for p in BREAKFAST_PLACES]
    scene = breakfast_scene(STRETCH, places=places)
    world = scene.world
    cid = world.physics.client()
    kitchen = world.object("kitchen")
    link = kitchen.link_index[drawer]
    try:
        with simulated_robot(world, scene.robot):
            opened = container(drawer).opened
        before = pybullet.getLinkState(kitchen.body_id, link, physicsClientId=cid)[4]
        world.set_joint_states("kitchen", {f"{drawer}_joint": opened})
        after = pybullet.getLinkState(kitchen.body_id, link, physicsClientId=cid)[4]
        for thing in seed_0:  # carried out with the drawer
            at = world.pose(world.object(thing))
            moved = tuple(p + a - b for p, a, b in zip(at.position, after, before, strict=True))
            world.set_pose(thing, Pose(moved, at.orientation))
        was = pybullet.getBasePositionAndOrientation(world.object(neighbour).body_id, cid)[0]
        world.set_pose(scene.robot, stand)
        with simulated_robot(world, scene.robot):
            held = pick_up_object(taken, out_of=("kitchen", drawer))
        assert held.grasp == grasp
        top = pybullet.getAABB(kitchen.body_id, link, cid)[1][2]
        low = pybullet.getAABB(world.object(taken).body_id, physicsClientId=cid)[0][2]
        assert low > top  # lifted out of the drawer
        now = pybullet.getBasePositionAndOrientation(world.object(neighbour).body_id, cid)[0]
        assert now == pytest.approx(was, abs=STILL)
    finally:
        world.close()
