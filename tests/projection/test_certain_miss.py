"""A torso-held IK try stops at its first refused solution when a hand link is deeper in
something than any solution can take it out of; ``move_tcp`` then fails exactly as it did
with the whole search (the torso-free query's failure is the one it reports).

The PR2's right fingertips are put in a cube at a reach; the arm parks, then moves its
tool back to that reach. Raw PyBullet depths at every solution IK finds say that the
premise holds there: the fingertip is in the cube at each, within the bound of the first.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import pybullet
import pytest

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.kinematics import IKOptions, arm_joints, solve_ik
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH, HandContact
from robocram.projection import ProjectedRobot, arm
from robocram.projection.certain_miss import (
    MISS_MARGIN,
    CertainMiss,
    CertainMissJudge,
    rigid_links,
)
from robocram.projection.collision_mode import _Check
from robocram.tf import Pose
from robocram.world import World

TIP, TOOL = "r_gripper_l_finger_tip_link", "r_gripper_tool_frame"
LIFT, ELBOW = "r_shoulder_lift_joint", "r_elbow_flex_joint"
CUBE = 0.06  # [m] edge: the fingertip ~2 cm deep whatever the solution


@pytest.fixture()
def world() -> Iterator[World]:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    for spec in world.robot("pr2").description.arms.values():
        world.set_joint_states("pr2", dict(spec.parking))
    world.add_box("cube", (CUBE, CUBE, CUBE), Pose((3.0, 0.0, 0.5)))
    yield world
    world.close()


def _reach(world: World) -> dict[str, float]:
    """The right arm reaching forward (from parking: shoulder down, elbow opened)."""
    parked = dict(world.robot("pr2").description.arms["right"].parking)
    return {**parked, LIFT: parked[LIFT] + 0.5, ELBOW: parked[ELBOW] + 0.8}


def _tip_in_cube(world: World, shift: float = 0.0) -> Pose:
    """Put the cube round the fingertip at the reach (``shift`` [m] along x from its
    centre); park the arm again; return the tool's pose at the reach (map)."""
    parked = world.joint_states("pr2")
    world.set_joint_states("pr2", _reach(world))
    low, high = world.contacts.link_aabb("pr2", TIP)
    centre = [(a + b) / 2 for a, b in zip(low, high, strict=True)]
    world.set_pose("cube", Pose((centre[0] + shift, centre[1], centre[2])))
    tool = world.link_pose("pr2", TOOL)
    world.set_joint_states("pr2", parked)
    return tool


def _shallow(world: World) -> float:
    """Move the cube out along x until the fingertip is 0.5-4 mm in it (raw depth [m]);
    the robot stands at the reach."""
    for mm in range(0, 60):
        _tip_in_cube(world, shift=CUBE / 2 + mm / 1000)
        world.set_joint_states("pr2", _reach(world))
        depth = _raw_depth(world, TIP)
        if 0.0005 < depth < 0.004:
            return depth
    raise AssertionError("no shift leaves the fingertip a few mm in the cube")


def _raw_depth(world: World, link: str) -> float:
    """[m] how deep ``link`` is in the cube, by PyBullet itself (0 when apart)."""
    robot, cube = world.object("pr2"), world.object("cube")
    points = pybullet.getClosestPoints(
        robot.body_id, cube.body_id, 0.0, linkIndexA=robot.link_index[link],
        physicsClientId=world.physics.client(),
    )  # fmt: skip
    return max((-p[8] for p in points), default=0.0)


def test_the_hand_below_the_last_arm_joint_is_rigid_with_the_tool(world: World) -> None:
    desc = world.robot("pr2").description
    for torso in (False, True):
        rigid = rigid_links(desc.model, TOOL, arm_joints(desc, "right", torso))
        assert {"r_wrist_roll_link", "r_gripper_palm_link", TIP, TOOL} <= rigid
        assert not rigid & {"r_wrist_flex_link", "r_forearm_link", "torso_lift_link"}
        assert not any(link.startswith("l_") for link in rigid)


def test_every_solution_has_the_tip_in_the_cube_within_the_bound(world: World) -> None:
    target = world.pose("pr2").inverse() * _tip_in_cube(world)
    desc = world.robot("pr2").description
    start = world.joint_states("pr2")
    depths: list[float] = []

    def refuse(values: dict[str, float]) -> bool:  # every solution: its raw depth
        world.set_joint_states("pr2", values)
        depths.append(_raw_depth(world, TIP))
        world.set_joint_states("pr2", start)
        return True

    options = IKOptions()  # torso held
    result = solve_ik(desc, "right", target, seed=start, options=options, collision_check=refuse)
    assert not result.success and len(depths) == result.rejected_in_collision > 50
    world.set_joint_states("pr2", {**start, **_reach(world)})
    tool, tip = world.link_pose("pr2", TOOL).position, world.link_pose("pr2", TIP).position
    reach = math.dist(tool, tip) + world.contacts.link_radii("pr2")[TIP]
    bound = 2 * (1e-3 + 1e-2 * reach)  # IKOptions' tolerances: 1 mm, 0.01 rad
    assert min(depths) > 0.01  # in the cube at every solution
    assert max(depths) - min(depths) < bound  # the premise: within the bound of each other


def _fail(
    world: World, target: Pose, explain: bool = True
) -> tuple[ManipulationPoseUnreachable, int]:
    """move_tcp's failure to ``target`` and how many candidates its checks were asked."""
    robot = ProjectedRobot.of(world, "pr2")
    before = world.joint_states("pr2")
    asked = 0
    check = _Check.__call__

    def counted(self: _Check, candidate: dict[str, float]) -> list[tuple[str, str]]:
        nonlocal asked
        asked += 1
        return check(self, candidate)

    _Check.__call__ = counted  # type: ignore[method-assign]
    try:
        with pytest.raises(ManipulationPoseUnreachable) as failed:
            arm.move_tcp(robot, "right", target, explain=explain)
    finally:
        _Check.__call__ = check  # type: ignore[method-assign]
    assert world.joint_states("pr2") == before  # every candidate put back
    return failed.value, asked


def test_move_tcp_fails_as_with_the_whole_search(
    world: World, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = _tip_in_cube(world)
    judged, judged_asked = _fail(world, target)
    monkeypatch.setattr(arm, "_judge", lambda *_: None)  # no query stops early
    whole, whole_asked = _fail(world, target)
    assert type(judged) is type(whole) is ManipulationPoseUnreachable
    assert str(judged) == str(whole)
    assert judged.colliding_pairs == whole.colliding_pairs
    assert (TIP, "cube") in (whole.colliding_pairs or ())
    assert whole_asked - judged_asked > 50  # the torso-held try: one check, not ~100


def test_a_move_whose_failure_is_not_read_stops_at_once(world: World) -> None:
    target = _tip_in_cube(world)
    whole, _ = _fail(world, target)
    stopped, asked = _fail(world, target, explain=False)
    assert isinstance(stopped, CertainMiss) and asked == 2  # one per query, torso held, free
    assert stopped.colliding_pairs is not None and len(stopped.colliding_pairs) == 1
    assert set(stopped.colliding_pairs) <= set(whole.colliding_pairs or ())


def test_the_judge_stops_only_a_deep_contact(world: World) -> None:
    robot = ProjectedRobot.of(world, "pr2")
    hand = HandContact.of(robot.arm("right").hand_links, "cube")
    rigid = rigid_links(robot.description.model, TOOL, arm_joints(robot.description, "right"))
    judge = CertainMissJudge(robot, TOOL, rigid, None, 1e-3, 1e-2)
    touching = CertainMissJudge(robot, TOOL, rigid, hand, 1e-3, 1e-2)
    _tip_in_cube(world)
    world.set_joint_states("pr2", _reach(world))
    deep = _raw_depth(world, TIP)
    with pytest.raises(CertainMiss) as stopped:
        judge([(TIP, "cube")])
    assert stopped.value.colliding_pairs == ((TIP, "cube"),)
    assert stopped.value.depth == pytest.approx(deep, abs=1e-6)
    assert stopped.value.bound is not None and MISS_MARGIN < stopped.value.bound < deep
    with pytest.raises(CertainMiss):  # deep beyond the hand's bound too
        touching([(TIP, "cube")])
    judge([("r_forearm_link", "cube"), ("r_gripper_palm_link", "r_forearm_link")])  # not rigid
    shallow = _shallow(world)  # the cube's face a few mm into the tip
    assert 0.0 < shallow < HAND_CONTACT_DEPTH
    judge([(TIP, "cube")])  # in, but a solution may have it out
    touching([(TIP, "cube")])
