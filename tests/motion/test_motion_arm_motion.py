"""Arm motions that move no joint: free without a checker, and timed like any other.

An arm parked again (the plans park before every drive) starts where its goal is; the
motion must come back at once, as the straight path with no checks, even when the arm
rests against something (contacts a motion starts with are allowed).
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.motion import plan_arm_motion
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.world import RobotHandle

PARKING = ("r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_elbow_flex_joint")


@pytest.fixture(scope="module")
def scene() -> Iterator[KitchenScene]:
    made = kitchen_scene("pr2")
    yield made
    made.world.close()


def test_a_motion_to_where_the_arm_is_needs_no_check(scene: KitchenScene) -> None:
    world = scene.world
    now = world.joint_states("pr2")
    motion = plan_arm_motion(RobotHandle.of(world, "pr2"), {j: now[j] for j in PARKING})
    assert motion.path.planner == "straight" and motion.path.checks == 0
    assert motion.path.waypoints == (tuple(now[j] for j in PARKING),) * 2
    assert motion.trajectory.joint_names == PARKING
    for point in (motion.trajectory.points[0], motion.trajectory.points[-1]):
        assert point.positions == pytest.approx([now[j] for j in PARKING], abs=1e-12)
    assert world.joint_states("pr2") == now


def test_a_motion_that_moves_is_checked(scene: KitchenScene) -> None:
    world = scene.world
    now = world.joint_states("pr2")
    goal = {j: now[j] for j in PARKING}
    goal["r_elbow_flex_joint"] -= 0.1
    motion = plan_arm_motion(RobotHandle.of(world, "pr2"), goal)
    assert motion.path.planner == "straight" and motion.path.checks > 0
