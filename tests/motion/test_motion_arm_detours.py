"""Detours before planning: over a box in the arm's way, never through it.

The PR2 stands at the counter, torso up, arms parked; a box stands on the counter between
its parked right hand and the mug, so the straight joint-space move to the mug's
pre-grasp sweeps the fingers through it. Lifted 0.3 m at both ends, the hand crosses over
the box: the detour must be found, start and end where the motion does, lift the tool,
and every configuration 1 cm of travel apart along it must be free as PyBullet judges it.
A box too tall to cross is left to OMPL; a goal inside the box gets no detour. A lift one
joint leaves short (a torso near its top) is carried on by the next steepest joint.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

import numpy as np
import pytest

from robocram.kinematics import solve_ik
from robocram.motion import MotionSettings, joint_limits, plan_arm_motion
from robocram.motion.arm_detours import DETOUR_LIFTS, MIN_LIFT, ToolHeight, detour_path
from robocram.motion.bullet_scene import BulletScene
from robocram.motion.coal_clearance import CoalClearance
from robocram.motion.segment_check import CheckCounter, first_collision
from robocram.motion.travel_bound import TravelBound
from robocram.plans.basic_actions import move_torso, navigate, park_arms
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.collision_mode import collision_check
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import PoseStamped
from robocram.tf import quaternion as quat
from robocram.world import RobotHandle

NORTH = quat.from_euler(0.0, 0.0, math.pi / 2)
LOW_BOX = ((0.12, 0.12, 0.36), (-0.97, 2.02, 1.04))  # [m] size, centre: the hand lifts over
TALL_BOX = ((0.08, 0.08, 0.8), (-0.95, 2.02, 1.26))  # [m] ... and a post it cannot
JOINTS = (
    "r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
    "r_elbow_flex_joint", "r_forearm_roll_joint", "r_wrist_flex_joint", "r_wrist_roll_joint",
)  # fmt: skip


@pytest.fixture(scope="module")
def stand() -> Iterator[tuple[KitchenScene, PoseStamped]]:
    """The PR2 before the mug, and the mug's pre-grasp for the right hand."""
    scene = kitchen_scene("pr2")
    world = scene.world
    x = world.pose("mug-1").position[0]
    with simulated_robot(world, "pr2"):
        park_arms()
        move_torso("upper")
        navigate(PoseStamped("map", (x, 1.43, 0.0), NORTH))
        grasp = world.kb.first("object_grasp(O, R, A, N, G, P, L)", O="mug-1", R="pr2", A="right")
    assert grasp is not None
    yield scene, grasp["P"]
    world.close()


@pytest.fixture()
def motion(
    request: pytest.FixtureRequest, stand: tuple[KitchenScene, PoseStamped]
) -> Iterator[tuple[KitchenScene, list[float], list[float]]]:
    """With a box on the counter (``request.param``: size, centre): the right arm's joints
    now and at the pre-grasp (IK avoiding the box). The box is removed after the test."""
    scene, pre_grasp = stand
    world = scene.world
    size, centre = request.param
    world.add_box("box", size, centre)
    robot = ProjectedRobot.of(world, "pr2")
    current = world.joint_states("pr2")
    check = collision_check(robot, "right", "avoid_all")
    goal = solve_ik(robot.description, "right", robot.in_base(pre_grasp), seed=current,
                    collision_check=check)  # fmt: skip
    assert goal.success
    yield scene, [current[j] for j in JOINTS], [goal.joint_positions[j] for j in JOINTS]
    world.remove("box")


def _detour_setup(scene: KitchenScene) -> tuple:
    world = scene.world
    limits = joint_limits(world.robot("pr2").description, JOINTS)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    bound = TravelBound.of(RobotHandle.of(world, "pr2"), JOINTS)
    height = ToolHeight.of(RobotHandle.of(world, "pr2"), JOINTS)
    assert height is not None
    return CoalClearance(BulletScene(RobotHandle.of(world, "pr2"), JOINTS)), bound, box, height


def _tool_height(scene: KitchenScene, q: tuple[float, ...]) -> float:
    """The tool's height [m] in the world (PyBullet), the arm put at ``q`` and back."""
    world = scene.world
    before = world.joint_states("pr2")
    world.set_joint_states("pr2", dict(zip(JOINTS, q, strict=True)))
    tool = world.robot("pr2").description.arms["right"].tool_frame
    z = world.link_pose("pr2", tool).position[2]
    world.set_joint_states("pr2", before)
    return z


@pytest.mark.parametrize("motion", [LOW_BOX], indirect=True)
def test_the_hand_is_lifted_over_the_box_and_never_touches_it(motion: tuple) -> None:
    scene, start, end = motion
    checker, bound, limits, height = _detour_setup(scene)
    judge = BulletScene(RobotHandle.of(scene.world, "pr2"), JOINTS)
    blocked = first_collision(judge, np.array(start), np.array(end), bound, CheckCounter())
    assert blocked is not None and any(other == "box" for _, other in blocked[1])
    path = detour_path(checker, start, end, bound, limits, height)
    assert path is not None and path.planner == "detour"
    assert path.joints == JOINTS and len(path.waypoints) == 4
    assert np.allclose(path.waypoints[0], start, atol=1e-12)
    assert np.allclose(path.waypoints[-1], end, atol=1e-12)
    lift = DETOUR_LIFTS[0]
    for end_point, lifted in ((path.waypoints[0], path.waypoints[1]),
                              (path.waypoints[3], path.waypoints[2])):  # fmt: skip
        raised = _tool_height(scene, lifted) - _tool_height(scene, end_point)
        assert MIN_LIFT <= raised <= lift + 0.01  # the lift, or as far as a joint limit lets
    points = [np.array(w) for w in path.waypoints]
    for qa, qb in zip(points, points[1:], strict=False):
        assert first_collision(judge, qa, qb, bound, CheckCounter()) is None


@pytest.mark.parametrize("motion", [LOW_BOX], indirect=True)
def test_the_same_motion_gets_the_same_detour(motion: tuple) -> None:
    scene, start, end = motion
    first = detour_path(*_split(scene, start, end))
    second = detour_path(*_split(scene, start, end))
    assert first is not None and second is not None
    assert first.waypoints == second.waypoints


def _split(scene: KitchenScene, start: list[float], end: list[float]) -> tuple:
    checker, bound, limits, height = _detour_setup(scene)
    return checker, start, end, bound, limits, height


@pytest.mark.parametrize("motion", [LOW_BOX], indirect=True)
def test_an_arm_motion_takes_the_detour_before_planning(motion: tuple) -> None:
    scene, start, end = motion
    world = scene.world
    before = world.joint_states("pr2")
    motion = plan_arm_motion(RobotHandle.of(world, "pr2"), dict(zip(JOINTS, end, strict=True)))
    assert motion.path.planner == "detour"
    assert np.allclose(motion.path.waypoints[0], start, atol=1e-12)
    assert world.joint_states("pr2") == before  # nothing moved


@pytest.mark.parametrize("motion", [TALL_BOX], indirect=True)
def test_a_box_too_tall_to_lift_over_is_left_to_the_planner(motion: tuple) -> None:
    scene, start, end = motion
    assert detour_path(*_split(scene, start, end)) is None
    motion = plan_arm_motion(
        RobotHandle.of(scene.world, "pr2"), dict(zip(JOINTS, end, strict=True))
    )
    assert motion.path.planner == "rrt_connect"


@pytest.mark.parametrize("motion", [LOW_BOX], indirect=True)
def test_a_goal_inside_the_box_gets_no_detour(motion: tuple) -> None:
    scene, start, end = motion
    checker, bound, limits, height = _detour_setup(scene)
    judge = BulletScene(RobotHandle.of(scene.world, "pr2"), JOINTS)
    hit = first_collision(judge, np.array(start), np.array(end), bound, CheckCounter())
    assert hit is not None
    inside = np.array(start) + (np.array(end) - np.array(start)) * hit[0]
    assert detour_path(checker, start, inside, bound, limits, height) is None


def test_a_lift_one_joint_leaves_short_is_carried_on_by_the_next(
    stand: tuple[KitchenScene, PoseStamped],
) -> None:
    """The torso 0.1 m below its top: alone it lifts the tool 0.1 m, shared with the
    next steepest joint the whole 0.3 m asked (within the tolerance), both in limits."""
    scene, _ = stand
    world = scene.world
    torso = world.robot("pr2").description.torso_joint
    assert torso is not None
    joints = (torso, *JOINTS)
    limits = joint_limits(world.robot("pr2").description, joints)
    box = ([lim.lower for lim in limits], [lim.upper for lim in limits])
    current = world.joint_states("pr2")
    q = np.array([current[j] for j in joints])
    q[0] = box[1][0] - 0.1
    height = ToolHeight.of(RobotHandle.of(world, "pr2"), joints)
    assert height is not None
    here = height.height(q)
    alone = height.raised(q, 0.3, box)
    shared = height.raised(q, 0.3, box, joints=2)
    assert alone is not None and shared is not None
    assert height.height(alone) - here == pytest.approx(0.1, abs=1e-6)
    assert np.flatnonzero(alone != q).tolist() == [0]
    assert height.height(shared) - here == pytest.approx(0.3, abs=0.01)
    moved = np.flatnonzero(shared != q).tolist()
    assert len(moved) == 2 and moved[0] == 0 and shared[0] == pytest.approx(box[1][0])
    assert all(box[0][i] <= shared[i] <= box[1][i] for i in moved)


@pytest.mark.parametrize("motion", [LOW_BOX, TALL_BOX], indirect=True)
def test_a_detour_and_a_planned_path_keep_the_joint_limits(
    motion: tuple, timing_judge: Any
) -> None:
    """Timed at the usual period and every 2 ms, judged by finite differences
    (``timing_judge.py``): several waypoints, at rest at each corner."""
    scene, _, end = motion
    world = scene.world
    goal = dict(zip(JOINTS, end, strict=True))
    coarse, dense = (
        plan_arm_motion(RobotHandle.of(world, "pr2"), goal, settings=MotionSettings(period=period))
        for period in (0.05, timing_judge.DENSE)
    )
    assert coarse.path.planner in ("detour", "rrt_connect") and len(coarse.path.waypoints) >= 3
    assert dense.path == coarse.path
    limits = joint_limits(world.robot("pr2").description, JOINTS)
    timing_judge.assert_keeps_limits(coarse.trajectory, dense.trajectory, limits)
