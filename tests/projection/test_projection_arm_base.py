"""Reaching with the base in projection: the HSR's five-joint arm moves its base first."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Iterator

import pytest

from robocram.execution.failures import ManipulationPoseUnreachable
from robocram.plans import pick_up
from robocram.projection import ProjectedRobot, simulated_robot
from robocram.projection.arm import move_tcp
from robocram.robots import LoadedDescription, load_description
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.scenes.placement import TABLE_DEPTH
from robocram.tf import Pose, PoseStamped
from robocram.tf import quaternion as quat

DOWN = quat.from_euler(0.0, math.pi / 2, 0.0)  # a tool's approach axis (x) pointing down


def hsr(base_in_ik: bool | None) -> LoadedDescription:
    desc = load_description("hsrb")
    arm = dataclasses.replace(desc.arms["arm"], base_in_ik=base_in_ik)
    return dataclasses.replace(desc, arms={"arm": arm})


@pytest.fixture(params=[None, False], ids=["with-base", "arm-alone"])
def scene(request: pytest.FixtureRequest) -> Iterator[TabletopScene]:
    made = tabletop_scene(hsr(request.param))
    yield made
    made.world.close()


def _mug_aside(scene: TabletopScene) -> PoseStamped:
    """Move the mug 30 cm to the robot's right of where its arm alone picks it."""
    world = scene.world
    height = world.pose("mug-1").position[2]
    spot = (world.pose("table").position[0] - TABLE_DEPTH / 2 + 0.15, -0.25, height)
    world.set_pose("mug-1", Pose(spot))
    return PoseStamped("map", spot)


def test_the_hsr_picks_a_mug_its_arm_alone_cannot_reach(scene: TabletopScene) -> None:
    world = scene.world
    target = _mug_aside(scene)
    with_base = world.robot(scene.robot).description.arms["arm"].base_in_ik is None
    if not with_base:
        with pytest.raises(ManipulationPoseUnreachable), simulated_robot(world, scene.robot):
            pick_up(target)
        assert world.pose(scene.robot).position == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
        assert world.bodies.attached_to("mug-1") is None
        return
    with simulated_robot(world, scene.robot):
        result = pick_up(target)
    base = world.pose(scene.robot).position
    assert math.hypot(base[0], base[1]) > 0.05  # the base moved towards the mug
    assert base[2] == pytest.approx(0.0, abs=1e-9)
    assert world.bodies.attached_to("mug-1") is not None
    mug = world.pose("mug-1").position
    assert mug[0] == pytest.approx(target.position[0], abs=0.01)
    assert mug[1] == pytest.approx(target.position[1], abs=0.01)
    assert mug[2] == pytest.approx(target.position[2] + 0.10, abs=0.01)  # lifted 10 cm
    tool = world.link_pose(scene.robot, "hand_tool_frame")
    assert result.lifted.frame_id == "map"  # kept in the fixed frame while the base moved
    assert tool.distance_to(result.lifted.pose) < 0.01


def test_what_the_hand_holds_rides_along_when_the_base_moves() -> None:
    scene = tabletop_scene("hsrb")
    world = scene.world
    robot = ProjectedRobot.of(world, scene.robot)
    world.set_joint_states(robot.name, {"arm_lift_joint": 0.4})
    world.attach("mug-1", robot.name, "hand_palm_link")
    held = world.link_pose(robot.name, "hand_palm_link").inverse() * world.pose("mug-1")
    goal = Pose((0.55, -0.3, 0.85), quat.multiply(quat.from_euler(0.0, 0.0, 0.7), DOWN))
    reached = move_tcp(robot, "arm", goal)
    assert reached.distance_to(goal) < 0.01 and reached.angle_to(goal) < 0.05
    assert math.hypot(*world.pose(robot.name).position[:2]) > 0.01
    still = world.link_pose(robot.name, "hand_palm_link").inverse() * world.pose("mug-1")
    assert still.distance_to(held) < 1e-6
    world.close()


def test_a_six_joint_arm_moves_its_base_only_when_asked() -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    robot = ProjectedRobot.of(world, scene.robot)
    goal = Pose((1.35, -0.2, 0.9), DOWN)  # beyond the right arm's reach from the origin
    with pytest.raises(ManipulationPoseUnreachable):
        move_tcp(robot, "right", goal, collision_mode="allow_all")
    assert world.pose(robot.name).position == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    reached = move_tcp(robot, "right", goal, collision_mode="allow_all", move_base=True)
    assert reached.distance_to(goal) < 0.01 and reached.angle_to(goal) < 0.05
    assert world.pose(robot.name).position[0] > 0.05
    world.close()
