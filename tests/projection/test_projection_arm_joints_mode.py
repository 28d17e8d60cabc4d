"""``moving-arm-joints`` in a collision mode, as ``moving-tcp`` is (issue 38, Boxy's seed 33:
a hand that let go low in a drawer goes back through the joints it came in by, its
fingers brushing the counter's top as they did on the way in).

A PR2 swings its right arm forward and down to a joint goal; a box is planted where its
palm ends, 3 mm deep at the goal as PyBullet's raw closest points measure it. Under
``avoid_all`` the motion is refused and the arm stays; under ``allow_hand`` touching the
box it gets there, and every executed point keeps the hand within the 5 mm bound (raw
PyBullet again, not the planner's checker); touching another object it is refused. An
unknown mode is a typed error naming it (the process module's input error, the caller's
mistake), before anything moves.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import ManipulationPathBlocked, ProcessModuleInputError
from robocram.motion import JointTrajectory, MotionSettings
from robocram.motion.collision_modes import hand_links
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.motion.trajectory_log import trajectory_listener
from robocram.projection import simulated_robot
from robocram.projection.errors import ProjectionError
from robocram.tf import Pose
from robocram.world import RawDistances, World

PALM = "r_gripper_palm_link"
DEPTH = 0.003  # [m] how deep the palm ends in the box: within the hand's bound
TOLERANCE = 2e-4  # [m] how near the planted depth comes to DEPTH
STRAIGHT = MotionSettings(plan=False)  # the straight segment only: a blocked one fails
AWAY = {"box": Pose((2.0, 0.0, 0.02)), "other": Pose((2.0, 1.0, 0.02))}


@pytest.fixture(scope="module")
def world() -> Iterator[World]:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    for arm in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    for name, pose in AWAY.items():
        world.add_box(name, (0.02, 0.02, 0.02), pose)
    yield world
    world.close()


@pytest.fixture()
def parked(world: World) -> Iterator[dict[str, float]]:
    """The robot parked and the boxes away before and after each test; the start joints."""
    start = world.joint_states("pr2")
    yield start
    world.set_joint_states("pr2", start)
    for name, pose in AWAY.items():
        world.set_pose(name, pose)


def _goal(world: World) -> dict[str, float]:
    """The right arm parked, its shoulder lowered: the palm swings forward and down."""
    parked = dict(world.robot("pr2").description.arms["right"].parking)
    return {**parked, "r_shoulder_lift_joint": parked["r_shoulder_lift_joint"] + 0.4}


def _palm(world: World) -> np.ndarray:
    low, high = world.contacts.link_aabb("pr2", PALM)
    return (np.asarray(low) + np.asarray(high)) / 2


def _plant(world: World, box: str) -> float:
    """Put ``box`` ahead of the palm at the goal, along its last move, :data:`DEPTH` into
    it as raw PyBullet measures; return the depth measured (the arm is put back)."""
    raw, start, goal = RawDistances(world), world.joint_states("pr2"), _goal(world)
    world.set_joint_states(
        "pr2", {**goal, "r_shoulder_lift_joint": goal["r_shoulder_lift_joint"] - 0.02}
    )
    before = _palm(world)
    world.set_joint_states("pr2", goal)
    end = _palm(world)
    way = (end - before) / np.linalg.norm(end - before)
    ahead, depth = 0.08, 0.0  # [m] the box's centre ahead of the palm's
    for _ in range(60):  # moved by the measured depth's error until it is DEPTH
        world.set_pose(box, Pose(tuple((end + way * ahead).tolist())))
        gap = raw.closest("pr2", PALM, box, box, reach=0.1)
        depth = -gap.distance if gap is not None else -0.1
        if abs(depth - DEPTH) < TOLERANCE / 4:
            break
        ahead += depth - DEPTH
    world.set_joint_states("pr2", start)
    return depth


def _deepest(world: World, trajectories: list[JointTrajectory], box: str) -> float:
    """[m] the deepest any hand link went into ``box`` at the executed points (raw PyBullet)."""
    raw, now = RawDistances(world), world.joint_states("pr2")
    links = hand_links(world.robot("pr2").description.arms["right"])
    links &= set(raw.collision_links("pr2"))
    deepest = 0.0
    for trajectory in trajectories:
        for point in trajectory.points:
            world.set_joint_states(
                "pr2", dict(zip(trajectory.joint_names, point.positions, strict=True))
            )
            for link in links:
                gap = raw.closest("pr2", link, box, box, reach=0.05)
                if gap is not None:
                    deepest = max(deepest, -gap.distance)
    world.set_joint_states("pr2", now)
    return deepest


def _move(world: World, **mode: str) -> list[JointTrajectory]:
    heard: list[JointTrajectory] = []
    with trajectory_listener(heard.append), simulated_robot(world, "pr2", motion=STRAIGHT):
        perform(a.motion(type="moving-arm-joints", arm="right", configuration=_goal(world), **mode))
    return heard


def test_avoid_all_refuses_the_goal_and_the_arm_stays(
    world: World, parked: dict[str, float]
) -> None:
    assert _plant(world, "box") == pytest.approx(DEPTH, abs=TOLERANCE)
    with pytest.raises(ManipulationPathBlocked) as info:
        _move(world)
    assert (PALM, "box") in info.value.colliding_pairs
    assert world.joint_states("pr2") == parked


def test_allow_hand_reaches_it_with_the_hand_within_its_bound(
    world: World, parked: dict[str, float]
) -> None:
    assert _plant(world, "box") == pytest.approx(DEPTH, abs=TOLERANCE)
    heard = _move(world, collision_mode="allow_hand", touching="box")
    now = world.joint_states("pr2")
    goal = _goal(world)
    assert [now[j] for j in goal] == pytest.approx(list(goal.values()), abs=1e-9)
    deepest = _deepest(world, heard, "box")
    assert DEPTH - TOLERANCE <= deepest <= HAND_CONTACT_DEPTH  # it touched, not deeper


def test_allow_hand_touching_another_object_is_refused(
    world: World, parked: dict[str, float]
) -> None:
    assert _plant(world, "box") == pytest.approx(DEPTH, abs=TOLERANCE)
    with pytest.raises(ManipulationPathBlocked) as info:
        _move(world, collision_mode="allow_hand", touching="other")
    assert (PALM, "box") in info.value.colliding_pairs
    assert world.joint_states("pr2") == parked


def test_an_unknown_mode_is_named_before_anything_moves(
    world: World, parked: dict[str, float]
) -> None:
    with pytest.raises(
        ProcessModuleInputError, match="unknown collision mode 'allow_elbow'"
    ) as info:
        _move(world, collision_mode="allow_elbow")
    assert isinstance(info.value.error, ProjectionError)  # the caller's mistake, typed
    assert world.joint_states("pr2") == parked
