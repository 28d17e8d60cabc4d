"""Negative cases: each projected motion fails with its typed CRAM failure and leaves the
world consistent."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.designators import a, an
from robocram.execution import perform
from robocram.execution.failures import (
    GripperClosedCompletely,
    ManipulationPoseUnreachable,
    NavigationPoseUnreachable,
    PerceptionObjectNotFound,
    ProcessModuleFailure,
    PtuGoalNotReached,
    TorsoGoalNotReached,
)
from robocram.plans.basic_actions import park_arms
from robocram.projection import ProjectionError, simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.world import World

GRASP_Z = 0.763  # [m] a top grasp of the mug: 4 cm under the top of its box (issue 35)


@pytest.fixture(scope="module")
def scene() -> Iterator[World]:
    world = World()
    world.bodies.add_floor()
    world.add_robot("pr2")
    world.add_box("table", (0.6, 1.0, 0.7), pose=Pose((0.9, 0.0, 0.35)))
    world.add_item("mug-1", "mug", pose=Pose((0.7, 0.0, 0.7)))
    yield world
    world.close()


@pytest.fixture
def world(scene: World) -> Iterator[World]:
    with scene.snapshots.stored_state():
        yield scene


def test_torso_out_of_range_applies_the_clamped_value(world: World) -> None:
    with simulated_robot(world, "pr2"), pytest.raises(TorsoGoalNotReached) as info:
        perform(a.motion(type="moving-torso", joint_angle=0.5))
    assert info.value.goal == 0.5
    assert info.value.limits == (0.0, pytest.approx(0.31))
    assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(0.31)
    assert info.value.context["process_module"] == "projection_torso"


def test_driving_into_the_table_leaves_the_robot_where_it_was(world: World) -> None:
    start = Pose((0.1, 0.2, 0.0), (0.0, 0.0, 0.0998334, 0.9950042))
    world.set_pose("pr2", start)
    target = PoseStamped("map", (0.9, 0.0, 0.0))
    with simulated_robot(world, "pr2"), pytest.raises(NavigationPoseUnreachable) as info:
        perform(a.motion(type="going", target=a.location(pose=target)))
    assert "table" in info.value.colliding
    now = world.pose("pr2")
    assert now.distance_to(start) < 1e-6
    assert now.angle_to(start) < 1e-6


def test_driving_to_free_space_keeps_height_and_yaw(world: World) -> None:
    target = PoseStamped("map", (-1.0, 0.5, 0.3), (0.0, 0.0, 0.7071068, 0.7071068))
    with simulated_robot(world, "pr2"):
        park_arms()  # stretched over the table, the arms would sweep the mug off it
        perform(a.motion(type="going", target=a.location(pose=target)))
    now = world.pose("pr2")
    assert now.position == pytest.approx((-1.0, 0.5, 0.0), abs=1e-6)
    assert now.angle_to(Pose((0, 0, 0), target.orientation)) < 1e-6


def test_detecting_what_is_not_visible_fails(world: World) -> None:
    world.set_pose("mug-1", Pose((-1.5, 0.0, 0.0)))  # behind the robot
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="looking", target=a.location(pose=PoseStamped("map", (1, 0, 0.7)))))
        asked = an.object(type="mug")
        with pytest.raises(PerceptionObjectNotFound) as info:
            perform(a.motion(type="detecting", object=asked))
    assert info.value.object_designator is asked


def test_detecting_an_absent_type_fails(world: World) -> None:
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="looking", target=a.location(pose=PoseStamped("map", (0.7, 0, 0.7)))))
        assert perform(a.motion(type="detecting", object=an.object(type="mug"))).get("name") == (
            "mug-1"
        )
        with pytest.raises(PerceptionObjectNotFound):
            perform(a.motion(type="detecting", object=an.object(type="pot")))


def test_unreachable_tcp_names_arm_and_target(world: World) -> None:
    joints = world.joint_states("pr2")
    far = PoseStamped("base_footprint", (2.5, 0.0, 1.0))
    with simulated_robot(world, "pr2"), pytest.raises(ManipulationPoseUnreachable) as info:
        perform(a.motion(type="moving-tcp", arm="left", target=a.location(pose=far)))
    assert info.value.arm == "left"
    assert info.value.target == far
    assert world.joint_states("pr2") == joints  # the arm did not move


def test_moving_tcp_with_cram_left_target_form(world: World) -> None:
    target = PoseStamped("base_footprint", (0.6, 0.2, 0.9))
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="moving-tcp", left_target=a.location(pose=target)))
    tool = world.pose("pr2").inverse() * world.link_pose("pr2", "l_gripper_tool_frame")
    assert tool.distance_to(target.pose) < 0.01
    assert tool.angle_to(target.pose) < 0.05


def test_gripping_nothing_closes_completely(world: World) -> None:
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="opening", gripper="right"))
        with pytest.raises(GripperClosedCompletely) as info:
            perform(a.motion(type="gripping", gripper="right"))
    assert info.value.gripper == "right"
    assert world.joint_states("pr2")["r_gripper_l_finger_joint"] == pytest.approx(0.0)
    assert world.bodies.attachments("pr2") == {}


def test_gripping_beside_the_mug_closes_completely(world: World) -> None:
    down = (-0.5, -0.5, 0.5, -0.5)  # tool x down, the fingers across the body (not the handle)
    beside = PoseStamped("base_footprint", (0.7, -0.15, GRASP_Z), (0.0, 0.7071068, 0.0, 0.7071068))
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="moving-torso", joint_angle=0.3))
        perform(a.motion(type="opening", gripper="right"))
        grasping = {"collision_mode": "allow_hand"}
        perform(
            a.motion(type="moving-tcp", arm="right", target=a.location(pose=beside), **grasping)
        )
        with pytest.raises(GripperClosedCompletely):
            perform(a.motion(type="gripping", gripper="right"))
        assert world.bodies.attachments("pr2") == {}
        perform(a.motion(type="opening", gripper="right"))
        over = PoseStamped("base_footprint", (0.7, 0.0, GRASP_Z + 0.1), down)  # not through it
        perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=over)))
        above = PoseStamped("base_footprint", (0.7, 0.0, GRASP_Z), down)
        perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=above), **grasping))
        assert perform(a.motion(type="gripping", gripper="right")) == "mug-1"
    assert world.bodies.attachments("pr2") == {"mug-1": "r_wrist_roll_link"}


def test_avoid_all_refuses_a_grasp_pose_that_allow_hand_accepts(world: World) -> None:
    down = (-0.5, -0.5, 0.5, -0.5)  # tool x down, the fingers across the body (not the handle)
    at_mug = PoseStamped("base_footprint", (0.7, 0.0, GRASP_Z - 0.006), down)  # 0.8 mm in
    before = world.joint_states("pr2")
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="moving-torso", joint_angle=0.3))
        perform(a.motion(type="opening", gripper="right"))
        opened = world.joint_states("pr2")
        with pytest.raises(ManipulationPoseUnreachable, match="rejected in collision") as info:
            perform(a.motion(type="moving-tcp", arm="right", target=a.location(pose=at_mug)))
        assert info.value.arm == "right"
        assert world.joint_states("pr2") == pytest.approx(opened)  # IK trials left no trace
        target = a.location(pose=at_mug)
        reached = perform(
            a.motion(type="moving-tcp", arm="right", target=target, collision_mode="allow_hand")
        )
    assert reached.distance_to(world.pose("pr2") * at_mug.pose) < 0.01
    assert before != world.joint_states("pr2")


def test_allow_hand_touching_another_object_refuses_the_mug_and_names_it(world: World) -> None:
    """The hand 0.8 mm in the mug: allowed when the motion names the mug, refused (naming
    it) when it names the table, before anything moves."""
    down = (-0.5, -0.5, 0.5, -0.5)  # tool x down, the fingers across the body (not the handle)
    at_mug = a.location(pose=PoseStamped("base_footprint", (0.7, 0.0, GRASP_Z - 0.006), down))
    mode = {"collision_mode": "allow_hand"}
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="moving-torso", joint_angle=0.3))
        perform(a.motion(type="opening", gripper="right"))
        opened = world.joint_states("pr2")
        with pytest.raises(ManipulationPoseUnreachable) as info:
            perform(
                a.motion(type="moving-tcp", arm="right", target=at_mug, touching="table", **mode)
            )
        links = set(world.link_names("pr2"))  # candidates may also touch the robot itself
        hit = {other for _, other in info.value.colliding_pairs or ()} - links
        assert hit == {"mug-1"}
        assert "mug-1" in str(info.value)
        assert world.joint_states("pr2") == pytest.approx(opened)
        perform(a.motion(type="moving-tcp", arm="right", target=at_mug, touching="mug-1", **mode))
    fingers = [
        -p.distance
        for p in world.contacts.contact_points("pr2", "mug-1")
        if p.link_a.startswith("r_")
    ]
    assert fingers and 0.0 < max(fingers) <= 0.005  # touching the mug, within the bound


def test_opening_releases_the_held_object(world: World) -> None:
    world.attach("mug-1", "pr2", "r_wrist_roll_link")
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="opening", gripper="right"))
    assert world.bodies.attachments("pr2") == {}
    assert world.joint_states("pr2")["r_gripper_l_finger_joint"] == pytest.approx(0.548)


def test_looking_behind_the_robot_is_clamped(world: World) -> None:
    behind = PoseStamped("map", (-2.0, 0.0, 1.2))
    with simulated_robot(world, "pr2"), pytest.raises(PtuGoalNotReached) as info:
        perform(a.motion(type="looking", target=a.location(pose=behind)))
    assert abs(info.value.reached["head_pan_joint"]) == pytest.approx(3.007)
    assert abs(world.joint_states("pr2")["head_pan_joint"]) == pytest.approx(3.007)


def test_looking_at_a_frame_and_a_direction(world: World) -> None:
    with simulated_robot(world, "pr2"):
        perform(a.motion(type="looking", frame="mug-1"))
        optical = world.link_pose("pr2", "wide_stereo_optical_frame").matrix()
        to_mug = world.pose("mug-1").position - optical[:3, 3]
        assert optical[:3, 2] @ to_mug / (to_mug @ to_mug) ** 0.5 == pytest.approx(1.0, abs=1e-4)
        perform(a.motion(type="looking", direction=(1.0, 1.0, 0.0)))
        optical = world.link_pose("pr2", "wide_stereo_optical_frame").matrix()
        assert optical[:3, 2] == pytest.approx((0.5**0.5, 0.5**0.5, 0.0), abs=1e-3)


def test_unknown_arm_is_a_clear_error(world: World) -> None:
    target = PoseStamped("base_footprint", (0.6, 0.2, 0.9))
    with simulated_robot(world, "pr2"), pytest.raises(ProcessModuleFailure) as info:
        perform(a.motion(type="moving-tcp", arm="rigth", target=a.location(pose=target)))
    assert isinstance(info.value.error, ProjectionError)
    assert "did you mean 'right'" in str(info.value)


def test_unknown_collision_mode_is_a_clear_error(world: World) -> None:
    target = a.location(pose=PoseStamped("base_footprint", (0.6, -0.2, 0.9)))
    motion = a.motion(type="moving-tcp", arm="right", target=target, collision_mode="sometimes")
    with simulated_robot(world, "pr2"), pytest.raises(ProcessModuleFailure) as info:
        perform(motion)
    assert isinstance(info.value.error, ProjectionError)
    assert "allow_hand" in str(info.value)


def test_unknown_robot_is_a_clear_error(world: World) -> None:
    with pytest.raises(ProjectionError, match="did you mean 'pr2'"), simulated_robot(world, "pr"):
        pass
