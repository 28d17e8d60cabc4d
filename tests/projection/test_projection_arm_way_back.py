"""An arm goes back along the way it came when the way planned afresh is blocked (issue 38,
Boxy's seed 33: the hand came into a drawer on a path clearing the counter's top by half
a millimetre, and the straight way back dips 18 mm into it).

A PR2's right arm swings its palm down through a box on the straight joint segment; the
kept way bends round it (the elbow opened half way: 31 mm clear, the straight way 39 mm
into the box). Planned straight only, the
goal is refused; under ``allow_hand`` the arm goes back along the kept way, every executed
point clear of the box by PyBullet's raw closest points. Under ``avoid_all`` nothing kept
is used, and a way taken with the base elsewhere is not the arm's way back.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.execution.failures import ManipulationPathBlocked
from robocram.motion import JointTrajectory, MotionSettings
from robocram.motion.joint_path import JointPath
from robocram.motion.trajectory_log import trajectory_listener
from robocram.projection import ProjectedRobot
from robocram.projection.arm import move_joints
from robocram.tf import Pose
from robocram.world import World

STRAIGHT = MotionSettings(plan=False)  # the fresh way is the straight segment only
LIFT, ELBOW = "r_shoulder_lift_joint", "r_elbow_flex_joint"


@pytest.fixture()
def world() -> Iterator[World]:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    world.add_box("box", (0.02, 0.02, 0.02), Pose((2.0, 0.0, 0.02)))
    yield world
    world.close()


def _ends(world: World) -> tuple[dict[str, float], dict[str, float], dict[str, float]]:
    """The parked right arm, its shoulder lowered by 1 rad, and half way with the elbow
    opened (the palm round the box)."""
    parked = dict(world.robot("pr2").description.arms["right"].parking)
    low = {**parked, LIFT: parked[LIFT] + 1.0}
    aside = {**parked, LIFT: parked[LIFT] + 0.5, ELBOW: parked[ELBOW] + 0.8}
    return parked, low, aside


def _box_in_the_straight_way(world: World, parked: dict[str, float]) -> None:
    """The box where the palm is half way down the straight segment."""
    world.set_joint_states("pr2", {**parked, LIFT: parked[LIFT] + 0.5})
    low, high = world.contacts.link_aabb("pr2", "r_gripper_palm_link")
    world.set_pose("box", Pose(tuple(((np.asarray(low) + np.asarray(high)) / 2).tolist())))


def _nearest(world: World, trajectories: list[JointTrajectory]) -> float:
    """[m] the robot's least raw PyBullet distance to the box at the executed points."""
    import pybullet

    cid, now = world.physics.client(), world.joint_states("pr2")
    robot, box = world.object("pr2").body_id, world.object("box").body_id
    least = 1.0
    for trajectory in trajectories:
        for point in trajectory.points:
            world.set_joint_states(
                "pr2", dict(zip(trajectory.joint_names, point.positions, strict=True))
            )
            points = pybullet.getClosestPoints(robot, box, 0.5, physicsClientId=cid)
            least = min([least, *(p[8] for p in points)])
    world.set_joint_states("pr2", now)
    return least


def _came_low(world: World, robot: ProjectedRobot) -> dict[str, float]:
    """The arm low, having come there round the box: the kept way; the parked goal."""
    parked, low, aside = _ends(world)
    _box_in_the_straight_way(world, parked)
    world.set_joint_states("pr2", low)
    joints = tuple(robot.arm("right").joints)
    way = tuple(tuple(c[j] for j in joints) for c in (parked, aside, low))
    robot.arm_ways.remember("right", robot.base_pose(), JointPath(joints, way, "rrt_connect", 0))
    return {j: parked[j] for j in joints}


def test_allow_hand_goes_back_along_the_way_it_came(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2", STRAIGHT)
    goal = _came_low(world, robot)
    with pytest.raises(ManipulationPathBlocked):  # the straight way, on its own
        move_joints(robot, "right", goal, "avoid_all")
    heard: list[JointTrajectory] = []
    with trajectory_listener(heard.append):
        move_joints(robot, "right", goal, "allow_hand")
    now = world.joint_states("pr2")
    assert [now[j] for j in goal] == pytest.approx(list(goal.values()), abs=1e-6)
    assert len(heard) == 2  # aside, then parked
    assert _nearest(world, heard) > 0.0


def test_a_way_taken_with_the_base_elsewhere_is_not_the_way_back(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2", STRAIGHT)
    goal = _came_low(world, robot)
    start = world.joint_states("pr2")
    world.set_pose("pr2", Pose((0.0, 0.01, 0.0)))
    with pytest.raises(ManipulationPathBlocked):
        move_joints(robot, "right", goal, "allow_hand")
    assert world.joint_states("pr2") == start
