"""The ROS planner bounds the hand as projection does (issue 35: it let the hand touch
anything under ``allow_hand``). Planned without ROS (``MotionPlanner`` takes a world),
so it runs outside the ROS group.

The judge is raw PyBullet: the deepest contact between the hand and the mug at the goal
(``getClosestPoints``), against the 5 mm the bound allows.
"""

from __future__ import annotations

from collections.abc import Iterator

import pybullet
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.kinematics import IKOptions, solve_ik
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.ros.motion_planner import MotionPlanner
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.tf import Pose

ARM = "right"


@pytest.fixture(scope="module")
def scene() -> Iterator[TabletopScene]:
    made = tabletop_scene("pr2")
    yield made
    made.world.close()


def _goal(scene: TabletopScene, above_mug: float) -> dict[str, float]:
    """IK's arm joints putting the tool ``above_mug`` [m] over the mug's origin."""
    world, desc = scene.world, scene.world.robot("pr2").description
    mug = world.pose("mug-1").position
    target = Pose((mug[0], mug[1], mug[2] + above_mug))
    result = solve_ik(
        desc, ARM, world.pose("pr2").inverse() * target, seed=world.joint_states("pr2"),
        options=IKOptions(use_torso=False, random_seed=1),
    )  # fmt: skip
    assert result.success
    return {j: result.joint_positions[j] for j in desc.arms[ARM].joints}


def _depth_in_mug(scene: TabletopScene, goal: dict[str, float]) -> float:
    """[m] how deep the robot is in the mug with its arm at ``goal`` (raw PyBullet)."""
    world = scene.world
    start = world.joint_states("pr2")
    cid = world.physics.client()
    try:
        world.set_joint_states("pr2", goal)
        points = pybullet.getClosestPoints(
            world.object("pr2").body_id, world.object("mug-1").body_id, 0.01, physicsClientId=cid
        )
    finally:
        world.set_joint_states("pr2", start)
    return max((-p[8] for p in points), default=0.0)


def test_a_goal_that_puts_the_fingers_into_the_mug_is_refused(scene: TabletopScene) -> None:
    goal = _goal(scene, 0.05)
    assert _depth_in_mug(scene, goal) > 2 * HAND_CONTACT_DEPTH  # deep: the bound must refuse
    planner = MotionPlanner(scene.world.robot("pr2").description, scene.world)
    with pytest.raises(ManipulationPathBlocked, match="mug-1"):
        planner.joint_motion(
            goal, scene.world.joint_states("pr2"), arm=ARM, mode="allow_hand", touching="mug-1"
        )


def test_a_goal_touching_the_mug_within_the_bound_is_planned_to_it(scene: TabletopScene) -> None:
    goal = _goal(scene, 0.12)
    assert 0.0 < _depth_in_mug(scene, goal) <= HAND_CONTACT_DEPTH  # the fingers graze the rim
    planner = MotionPlanner(scene.world.robot("pr2").description, scene.world)
    trajectory = planner.joint_motion(
        goal, scene.world.joint_states("pr2"), arm=ARM, mode="allow_hand", touching="mug-1"
    )
    end = dict(zip(trajectory.joint_names, trajectory.points[-1].positions, strict=True))
    assert all(abs(end[j] - v) < 1e-6 for j, v in goal.items())
