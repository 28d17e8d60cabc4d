"""Parking beside a wall: the base steps sideways when backing away cannot help.

A PR2 parks its arms wide of its shoulders. Standing with a wall 0.72 m to its right, the
parked right arm would be inside the wall; backing up moves along the wall and changes
nothing (a batch variant failed so). The base steps left, then the arm parks.
"""

from __future__ import annotations

import pytest

from robocram.plans.basic_actions import park_arms
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose

RIGHT_ARM = ("r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
             "r_elbow_flex_joint")  # fmt: skip


def test_the_base_steps_away_from_a_wall_beside_it_to_park() -> None:
    world = kitchen_scene("pr2").world
    wall_y = world.contacts.link_aabb("kitchen", "wall_south")[1][1]  # [m] its face into the room
    world.set_pose("pr2", Pose((2.0, wall_y + 0.72, 0.0)))  # facing +x: the wall on its right
    world.set_joint_states("pr2", dict.fromkeys(RIGHT_ARM, 0.0))
    with simulated_robot(world, "pr2"):
        park_arms()
    x, y, _ = world.pose("pr2").position
    assert x == pytest.approx(2.0, abs=0.02)  # back where it stood along the wall
    assert y == pytest.approx(wall_y + 0.92, abs=0.02)  # 0.2 m further from it
    parking = world.robot("pr2").description.arms["right"].parking
    states = world.joint_states("pr2")
    assert all(states[j] == pytest.approx(v, abs=1e-3) for j, v in parking.items())
    world.close()
