"""Issue 37: an arm whose hand has no moving finger (a bare UR5) is drafted with a suction
gripper; its check touches a mug's top for real, and the tabletop pick-up lifts the mug."""

from __future__ import annotations

import warnings
from dataclasses import replace
from pathlib import Path

import pybullet
import pytest

from robocram.kinematics import forward_kinematics
from robocram.plans.basic_actions import park_arms
from robocram.plans.pick_object import pick_up_object
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import (
    DescriptionError,
    GripperDescription,
    GripperJoint,
    RobotDescription,
    example_robot_data_folder,
    load_description,
)
from robocram.robots.description_json import description_from_json, description_to_json
from robocram.scenes import UnfitRobotError, kitchen_scene, tabletop_scene
from robocram.tf import Pose
from robocram.traces import TraceDatabase, audit_runs, trace_to
from tests.drafts import drafted_module

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


@pytest.fixture(scope="module")
def module(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bare UR5 of example-robot-data (no gripper), drafted to a module file."""
    urdf = example_robot_data_folder() / "ur_description" / "urdf" / "ur5_robot.urdf"
    path = tmp_path_factory.mktemp("ur5") / "ur5_robot.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        drafted_module(urdf, path)
    return path


@pytest.fixture(scope="module")
def described(module: Path) -> RobotDescription:
    return description_from(str(module))


def test_a_hand_without_fingers_is_drafted_as_a_suction_gripper_with_a_doubt(
    module: Path, described: RobotDescription
) -> None:
    (arm,) = described.arms.values()
    assert arm.gripper == GripperDescription.suction()
    assert arm.end_effector_link == "wrist_3_link" and not arm.gripper_joints
    text = module.read_text(encoding="utf-8")
    assert "gripper=GripperDescription.suction()" in text
    doubt = next(line for line in text.splitlines() if "TODO doubt: no finger joint" in line)
    assert "suction" in doubt
    assert described.drive == "fixed"  # its root is 'world': the arm does not drive
    loaded = load_description(described)
    hand = loaded.arms[arm.name]
    assert hand.gripper is not None and hand.gripper.max_opening is None
    assert set(hand.gripper_links) == set(hand.hand_links) >= {"wrist_3_link", "ee_link"}


def test_the_tool_frame_is_on_the_tip_of_the_hand(described: RobotDescription) -> None:
    """Raw PyBullet: with the tool frame 1 cm over a plate, the hand is 1 cm over it too."""
    loaded = load_description(described)
    (arm,) = loaded.arms.values()
    tool = forward_kinematics(loaded, {}, arm.tool_frame)
    wrist = forward_kinematics(loaded, {}, arm.end_effector_link)
    client = pybullet.connect(pybullet.DIRECT)
    try:
        body = pybullet.loadURDF(str(loaded.urdf), physicsClientId=client)
        names = {
            pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i
            for i in range(pybullet.getNumJoints(body, physicsClientId=client))
        }
        plate_at = tool * Pose((0.01 + 0.0005, 0.0, 0.0))  # 1 cm out along the approach
        half = 0.0005
        shape = pybullet.createCollisionShape(
            pybullet.GEOM_BOX, halfExtents=(half, 0.2, 0.2), physicsClientId=client
        )
        plate = pybullet.createMultiBody(
            0, shape, basePosition=plate_at.position, baseOrientation=plate_at.orientation,
            physicsClientId=client,
        )  # fmt: skip
        hand = [names["wrist_3_link"], names["ee_link"]]
        near = [
            p[8]
            for link in hand
            for p in pybullet.getClosestPoints(body, plate, 0.05, link, physicsClientId=client)
        ]
    finally:
        pybullet.disconnect(client)
    assert min(near) == pytest.approx(0.01, abs=0.0025)  # PyBullet's margins
    assert tool.distance_to(wrist) > 0.05


def test_the_drafted_arm_passes_every_check(described: RobotDescription) -> None:
    card = check_robot(described)
    grip = next(r for r in card.results if r.name == "arm arm: grip")
    assert grip.passed and "holds it" in grip.detail, card.render()
    assert card.passed, card.render()


def test_a_tool_frame_inside_the_hand_fails_the_check_in_one_line(
    described: RobotDescription,
) -> None:
    """The tool frame 4 cm back into the hand: touching the mug's top there puts the hand
    into the mug, which the grip check names."""
    frames = tuple(
        replace(f, pose=f.pose * Pose((-0.04, 0.0, 0.0))) if f.name.endswith("tool_frame") else f
        for f in described.extra_frames
    )
    card = check_robot(replace(described, extra_frames=frames))
    grip = next(r for r in card.results if r.name == "arm arm: grip")
    assert not grip.passed
    assert "into the mug" in grip.detail and "\n" not in grip.detail
    assert "tool frame on the tip of the hand" in grip.fix


def test_the_tabletop_pick_up_lifts_the_mug_touching_its_top(module: Path, tmp_path: Path) -> None:
    """Checked with raw PyBullet: the mug rose by the lift, and the hand touches it, no
    more than the hand's 5 mm bound in; the trajectory audit finds nothing. (Looking needs
    a neck, which a bare arm lacks: the pick-up starts at the grasp.)"""
    scene = tabletop_scene(str(module))
    world = scene.world
    try:
        client = world.physics.client()
        mug = world.object("mug-1").body_id
        robot = world.object(scene.robot).body_id
        before = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        with trace_to(tmp_path / "pick.db", world=world), simulated_robot(world, scene.robot):
            park_arms()
            held = pick_up_object("mug-1")
        after = pybullet.getBasePositionAndOrientation(mug, physicsClientId=client)[0][2]
        gaps = [p[8] for p in pybullet.getClosestPoints(robot, mug, 0.01, physicsClientId=client)]
    finally:
        world.close()
    assert held.grasp == "top"
    assert after - before == pytest.approx(0.10, abs=0.005)
    assert gaps and -0.005 <= min(gaps) <= 0.005
    with TraceDatabase(tmp_path / "pick.db") as db:
        report = audit_runs(db)
    assert not report.findings, report.summary_lines()


def test_the_kitchen_refuses_a_fixed_base_in_one_line(described: RobotDescription) -> None:
    with pytest.raises(UnfitRobotError, match=r"base is fixed .*mobile base") as caught:
        kitchen_scene(described)
    assert "\n" not in str(caught.value)


def test_a_suction_gripper_with_joints_is_refused(described: RobotDescription) -> None:
    (arm,) = described.arms.values()
    bad = GripperDescription((GripperJoint("wrist_3_joint", 0.0, 1.0),), kind="suction")
    with pytest.raises(DescriptionError, match="suction gripper has no joints"):
        load_description(replace(described, arms={arm.name: replace(arm, gripper=bad)}))
    with pytest.raises(DescriptionError, match="none of"):
        GripperDescription(kind="sticky")  # type: ignore[arg-type]


def test_a_trace_keeps_the_suction_gripper_as_data(described: RobotDescription) -> None:
    loaded = load_description(described)
    back = description_from_json(description_to_json(loaded), loaded.model)
    (arm,) = back.arms.values()
    gripper = arm.gripper
    assert gripper is not None and gripper.is_suction and gripper.joints == ()
