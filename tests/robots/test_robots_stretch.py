"""Hello Robot's Stretch, brought in from its URDF alone: a lift, a telescope, a sideways arm.

Its description, ``tests/data/stretch/stretch.py``, is the draft, unedited. The tests check
the kinematic roles the draft found, the reach over the telescope's range, the arm's
working direction, that ``robot check`` passes, that the four telescope joints move as one
actuator, and that the unchanged pick-up runs in the tabletop scene and the unchanged
transport carries the mug from the kitchen counter, and the bowl out of the drawer, to the
table.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

from robocram.costmaps.batch_fk import batch_frame_poses
from robocram.costmaps.occupancy import facing_radius, footprint_radii
from robocram.kinematics import IKOptions, solve_ik
from robocram.kinematics.robot_kinematics import robot_kinematics
from robocram.motion import JointTrajectory
from robocram.motion.joint_trajectory import TrajectoryPoint
from robocram.plans import pick_up
from robocram.plans.attempt_log import AttemptLog
from robocram.plans.container_access import open_from_front
from robocram.projection import simulated_robot
from robocram.robot_check import check_robot, description_from
from robocram.robots import (
    JointCoupling,
    LoadedDescription,
    MissingMeshWarning,
    load_description,
)
from robocram.robots.arm_envelope import arm_envelope
from robocram.robots.arm_roles import arm_roles
from robocram.robots.draft.model_tree import ModelTree
from robocram.robots.draft.telescope import find_telescopes
from robocram.robots.model_pose import link_pose
from robocram.ros.coupled_trajectory import with_coupled_followers
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose
from robocram.tf import quaternion as quat
from robocram.world import World
from tests.drafts import drafted
from tests.kitchen_transports import SHARED, Transports

STRETCH = Path(__file__).resolve().parents[1] / "data" / "stretch"
URDF = STRETCH / "stretch_description" / "urdf" / "stretch_description.urdf"
DESCRIPTION = STRETCH / "stretch.py"
TELESCOPE = ("joint_arm_l3", "joint_arm_l2", "joint_arm_l1", "joint_arm_l0")
WRIST = ("joint_wrist_yaw", "joint_wrist_pitch", "joint_wrist_roll")
FINGERS = ("joint_gripper_finger_right", "joint_gripper_finger_left")
EXTENSION = 4 * 0.13  # [m] the telescope's travel: four segments of 0.13 m each
pytestmark = SHARED  # its kitchen transports are other modules' too (tests/kitchen_transports.py)


@pytest.fixture(scope="module")
def stretch() -> Iterator[LoadedDescription]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)  # the camera's mesh is left out
        yield load_description(str(DESCRIPTION))


def test_the_description_is_the_draft_unedited() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        draft = drafted(URDF)
    assert draft.source(DESCRIPTION) == DESCRIPTION.read_text(encoding="utf-8")


def test_a_missing_mesh_package_loads_as_boxes_with_a_warning() -> None:
    with pytest.warns(MissingMeshWarning, match="realsense2_description"):
        desc = load_description(str(DESCRIPTION))
    assert desc.model.links["camera_link"].collisions


def test_the_roles_come_from_the_kinematics(stretch: LoadedDescription) -> None:
    assert stretch.torso_joint is None  # the lift raises the arm only: the camera is on the mast
    arm = stretch.arms["arm"]
    assert arm.joints == ("joint_lift", "joint_arm_l3", *WRIST)
    assert arm.end_effector_link == "link_wrist_roll"
    assert arm.tool_frame == "link_grasp_center"
    roles = arm_roles(stretch.model, arm)
    assert roles.lift == ("joint_lift",)
    assert roles.telescope == TELESCOPE  # joint_arm_l0, next to the wrist, is no finger
    assert roles.wrist == WRIST
    assert roles.fingers == FINGERS  # revolute, no <mimic>: a pair closing on the grasp centre
    assert stretch.coupled_joints == (JointCoupling(TELESCOPE[0], TELESCOPE[1:]),)


def test_no_earlier_robot_has_a_telescope() -> None:
    for robot in ("pr2", "hsrb", "boxy", "examples/robots/tiago_pro.py"):
        assert find_telescopes(ModelTree(load_description(robot).model)) == [], robot


def test_the_reach_is_measured_over_the_telescope_range(stretch: LoadedDescription) -> None:
    envelope = arm_envelope(stretch.model, stretch.arms["arm"])
    assert envelope.reach == pytest.approx(0.689, abs=0.005)
    assert envelope.reach > EXTENSION  # retracted (all at zero) it would be 0.17 m
    assert envelope.lift == ("joint_lift",)


def test_the_arm_works_along_the_base_minus_y(stretch: LoadedDescription) -> None:
    assert arm_envelope(stretch.model, stretch.arms["arm"]).working_yaw == -math.pi / 2
    pr2 = load_description("pr2")
    assert {arm_envelope(pr2.model, a).working_yaw for a in pr2.arms.values()} == {0.0}
    assert stretch_fact(stretch) == -math.pi / 2


def stretch_fact(stretch: LoadedDescription) -> float:
    """The working direction the knowledge base states for the arm."""
    with World() as world:
        world.add_robot(stretch)
        answers = list(world.kb.query("arm_working_direction(R, arm, Yaw)"))
        return float(answers[0]["Yaw"])


def test_robot_check_passes_on_the_unedited_draft(stretch: LoadedDescription) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        card = check_robot(description_from(str(DESCRIPTION)))
    assert card.passed, card.render()
    names = {r.name for r in card.results}
    assert {"arm arm: reach", "arm arm: grip", "arm arm: gripper", "look", "detect"} <= names


def test_ik_moves_the_telescope_as_one(stretch: LoadedDescription) -> None:
    tool = Pose((-0.05, -0.75, 0.6), quat.from_euler(0.0, math.pi / 2, 0.0))
    result = solve_ik(stretch, "arm", tool, options=IKOptions(frame="link_wrist_roll"))
    values = [result.joint_positions[j] for j in TELESCOPE]
    assert values[0] > 0.05  # extended
    assert values == pytest.approx([values[0]] * 4, abs=1e-9)


def test_a_trajectory_carries_the_followers(stretch: LoadedDescription) -> None:
    point = TrajectoryPoint((0.3, 0.1), (0.0, 0.02), (0.0, 0.0), 1.0)
    start = TrajectoryPoint((0.3, 0.0), (0.0, 0.0), (0.0, 0.0), 0.0)
    trajectory = JointTrajectory("stretch", ("joint_lift", "joint_arm_l3"), (start, point))
    sent = with_coupled_followers(stretch, trajectory)
    assert sent.joint_names == ("joint_lift", *TELESCOPE)
    assert sent.end == {"joint_lift": 0.3, **dict.fromkeys(TELESCOPE, 0.1)}
    assert sent.points[-1].velocities == (0.0, 0.02, 0.02, 0.02, 0.02)


def test_the_unchanged_pick_up_runs_in_the_tabletop_scene(stretch: LoadedDescription) -> None:
    scene = tabletop_scene(stretch)
    world = scene.world
    try:
        yaw = quat.to_euler(world.pose(scene.robot).orientation)[2]
        assert yaw == pytest.approx(math.pi / 2)  # the arm's -y along the map's x
        assert scene.look_target.position[0] > 0.5  # the table ahead of the arm
        start = world.pose("mug-1").position[2]
        with simulated_robot(world, scene.robot):
            result = pick_up(scene.look_target)
        assert (result.object_name, result.arm) == ("mug-1", "arm")
        assert world.bodies.attached_to("mug-1") is not None
        assert world.pose("mug-1").position[2] > start + 0.05
        joints = world.joint_states(scene.robot)
        telescope = [joints[j] for j in TELESCOPE]
        assert telescope == pytest.approx([telescope[0]] * 4, abs=1e-6)
    finally:
        world.close()


def test_the_unchanged_transport_carries_the_mug_to_the_kitchen_table(
    stretch: LoadedDescription, kitchen_transports: Transports
) -> None:
    run = kitchen_transports(stretch, "mug")
    world, result = run.world, run.done
    assert result.object_name == "mug-1"
    assert world.bodies.attached_to("mug-1") is None
    touching = {p.link_b for p in world.contacts.contact_points("mug-1", "kitchen")}
    assert touching == {"table_top"}
    assert world.pose("mug-1").position[:2] == pytest.approx(result.spot.position[:2], abs=0.03)
    joints = world.joint_states(run.robot)
    for joint, value in stretch.arms["arm"].parking.items():
        assert joints[joint] == pytest.approx(value, abs=0.01), joint
    assert [joints[j] for j in TELESCOPE] == pytest.approx([joints[TELESCOPE[0]]] * 4)


def test_the_unchanged_transport_takes_the_bowl_out_of_the_drawer(
    stretch: LoadedDescription, kitchen_transports: Transports
) -> None:
    """Stretch has no torso to raise: from the handle stand its camera, at 1.29 m, sees the
    bowl only when it looks at the middle of what the drawer pulled out, not its front.

    Its head, still turned down at the drawer, stood in its lift's way when the bowl was
    raised over the table's height (``link_lift`` hit ``link_head_tilt``: every stand at
    the table was then refused); the lift now looks ahead and is tried again."""
    run = kitchen_transports(stretch, "bowl")
    world, result = run.world, run.done
    assert result.object_name == "bowl-1"
    assert [o.container.link for o in result.opened] == ["drawer_unit_drawer_3"]
    assert [a.stage for a in result.log.attempts if a.succeeded] == [
        "open",
        "fetch",
        "deliver",
        "close",
    ]
    assert world.bodies.attached_to("bowl-1") is None
    assert {p.link_b for p in world.contacts.contact_points("bowl-1", "kitchen")} == {"table_top"}
    drawer = world.joint_states("kitchen")[result.opened[0].container.joint]
    assert drawer == pytest.approx(0.0, abs=0.01)  # closed again


def test_batched_fk_extends_the_coupled_telescope(stretch: LoadedDescription) -> None:
    """The reachability map's FK sets the followers too: the telescope extends 0.52 m."""
    kin = robot_kinematics(stretch.model)
    values = {"joint_arm_l3": np.array([0.0, 0.13])}
    _, positions = batch_frame_poses(kin, "link_wrist_roll", values)
    for value, position in zip((0.0, 0.13), positions, strict=True):
        expected = link_pose(stretch.model, "link_wrist_roll", {"joint_arm_l3": value}).position
        assert position == pytest.approx(expected, abs=1e-6)
    assert positions[0][1] - positions[1][1] == pytest.approx(EXTENSION, abs=1e-3)


def test_a_sideways_base_keeps_its_side_from_obstacles(stretch: LoadedDescription) -> None:
    with World() as world:
        robot = world.add_robot(stretch)
        inner, _ = footprint_radii(world, robot)
        assert inner == pytest.approx(0.06, abs=0.01)  # the origin is at the base's front
        assert facing_radius(world, robot) == pytest.approx(0.18, abs=0.01)  # its -y side
        pr2 = world.add_robot("pr2", pose=Pose((3.0, 0.0, 0.0)))
        assert facing_radius(world, pr2) == footprint_radii(world, pr2)[0]


def test_the_arm_faces_the_drawer_it_opens(stretch: LoadedDescription) -> None:
    scene = kitchen_scene(stretch)
    world = scene.world
    try:
        with simulated_robot(world, scene.robot):
            opened = open_from_front("drawer_unit_drawer_3", AttemptLog())
        joint = opened.container.joint
        assert world.joint_states("kitchen")[joint] == pytest.approx(opened.container.opened)
        assert opened.container.opened > 0.3
        yaw = quat.to_euler(opened.stand.pose.orientation)[2]
        # the drawer opens towards the map's -y; the arm, along the base's -y, points at
        # the drawer (+y) when the base heads along -x
        assert math.remainder(yaw - math.pi, 2 * math.pi) == pytest.approx(0.0, abs=1e-3)
    finally:
        world.close()
