"""The projection's process modules follow the motion table: every command, any arm names."""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import replace

import pytest

from robocram.designators import MOTION_TYPES, a, an, commands_of
from robocram.execution import perform
from robocram.projection import recorded_robot, simulated_robot
from robocram.projection.process_modules import PROJECTION_MODULES
from robocram.robots import load_description
from robocram.tf import Pose, PoseStamped
from robocram.world import World


def test_every_table_resource_has_a_projection_module_named_after_it() -> None:
    resources = {m.resource for m in MOTION_TYPES.values()}
    assert set(PROJECTION_MODULES) == resources
    for resource, cls in PROJECTION_MODULES.items():
        assert cls.name == f"projection_{resource}"
        assert all(callable(getattr(cls, n)) for n, _ in commands_of(MOTION_TYPES, resource))


@pytest.fixture(scope="module")
def sided() -> Iterator[World]:
    """A PR2 whose arms are called ``port`` and ``starboard``, on the left and the right."""
    pr2 = load_description("pr2")
    arms = {
        "port": replace(pr2.arms["left"], name="port", side="left"),
        "starboard": replace(pr2.arms["right"], name="starboard", side="right"),
    }
    world = World()
    world.bodies.add_floor()
    world.add_robot(replace(pr2, name="sided", arms=arms, model=None))
    world.add_box("table", (0.6, 1.0, 0.7), pose=Pose((0.9, 0.0, 0.35)))
    world.add_item("mug-1", "mug", pose=Pose((0.7, 0.0, 0.7)))
    yield world
    world.close()


def test_two_armed_motions_reach_the_arms_on_each_side_whatever_their_names(
    sided: World,
) -> None:
    left = PoseStamped("base_footprint", (0.6, 0.3, 0.9))
    right = PoseStamped("base_footprint", (0.6, -0.3, 0.9))
    with sided.snapshots.stored_state(), simulated_robot(sided, "sided"):
        perform(a.motion(type="moving-tcp", left_target=left, right_target=right))
        perform(a.motion(type="opening", gripper="starboard"))
        base = sided.pose("sided").inverse()
        for target, tool in ((left, "l_gripper_tool_frame"), (right, "r_gripper_tool_frame")):
            reached = base * sided.link_pose("sided", tool)
            assert reached.distance_to(target.pose) < 0.01
        assert sided.joint_states("sided")["r_gripper_l_finger_joint"] > 0.4


def test_inspecting_answers_the_perceived_object(sided: World) -> None:
    look = PoseStamped("map", (0.7, 0.0, 0.7))
    with sided.snapshots.stored_state(), simulated_robot(sided, "sided"):
        perform(a.motion(type="looking", target=look))
        seen = perform(a.motion(type="inspecting", object=an.object(type="mug")))
    assert seen.get("name") == "mug-1"
    expected = sided.pose("sided").inverse() * sided.pose("mug-1")
    assert math.dist(seen.get("pose").position, expected.position) < 1e-6


def test_the_recorder_answers_inspecting_and_both_arm_motions_from_the_table() -> None:
    mug = PoseStamped("base_footprint", (0.62, -0.15, 0.70))
    left, right = (0.6, 0.3, 0.9), (0.6, -0.3, 0.9)
    with recorded_robot("pr2", objects={"mug": mug}) as run:
        seen = perform(a.motion(type="inspecting", object=an.object(type="mug")))
        both = perform(a.motion(type="moving-tcp", left_target=left, right_target=right))
    assert seen.get("pose") == mug and seen.get("name") == "mug-1"
    assert both == (left, right, "avoid_all")
    assert [(m, t.name) for m, t in run.log] == [
        ("recorded_perception", "inspect"),
        ("recorded_arms", "move_tcp_both"),
    ]
    with recorded_robot("quadrotor") as flight:
        reach = perform(a.motion(type="distance-sensing", direction=(1, 0, 0)))
        reached = perform(a.motion(type="flying", target=(0, 0, 2)))
    assert reach == math.inf and reached == (0, 0, 2)
    assert [m for m, _ in flight.log] == ["recorded_distance_sensor", "recorded_flying"]
