"""The kitchen over ROS: the unchanged transport on the driver's kitchen with the real
PR2's controllers and a robot clock 10 s off, planned in a mirror of the robot side."""

from __future__ import annotations

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.plans import pick_up
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.ros import Roscore, ros_robot
from robocram.ros_driver.driver_process import DriverProcess
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose
from robocram.world import World

TABLE = ("kitchen", "table_top")
DRAWER_JOINT = "drawer_unit_drawer_3_joint"
RESTING = 0.015  # [m] the driver lets go without simulating: the mug may stand this high
SAME = 1e-6  # [m] stands chosen by the same seeds


def _mug_to_the_table() -> TransportResult:
    return transport("mug", a.location(on=TABLE, for_="mug-1"))


def _stands(result: TransportResult) -> list[tuple[str, Pose]]:
    return [(attempt.stage, attempt.stand) for attempt in result.log.attempts]


def _on_the_table_top(world: World, mug: Pose) -> None:
    """The mug (at ``mug``, map) stands upright on the table top, inside its outline."""
    low, high = world.aabb("mug-1")
    table_low, table_high = world.link_aabb("kitchen", "table_top")
    assert world.pose("mug-1").distance_to(mug) < 1e-6  # the mirror shows the driver's mug
    assert low[2] == pytest.approx(table_high[2], abs=RESTING)
    assert table_low[0] < mug.position[0] < table_high[0]
    assert table_low[1] < mug.position[1] < table_high[1]
    assert abs(mug.orientation[0]) < 1e-3 and abs(mug.orientation[1]) < 1e-3  # upright


@pytest.fixture(scope="module")
def in_projection() -> TransportResult:
    scene = kitchen_scene("pr2")
    with simulated_robot(scene.world, scene.robot):
        result = _mug_to_the_table()
    scene.world.close()
    return result


@pytest.mark.parametrize("offset", [-10.0, 10.0], ids=["clock_behind", "clock_ahead"])
def test_the_mug_goes_to_the_table_on_the_real_pr2_controllers(
    roscore: Roscore, in_projection: TransportResult, offset: float
) -> None:
    scene = kitchen_scene("pr2")
    with (
        DriverProcess(roscore.uri, controllers="pr2", clock_offset=offset, scene="kitchen"),
        ros_robot("pr2", roscore.uri, world=scene.world) as run,
    ):
        result = _mug_to_the_table()
        mug = run.transforms.lookup("map", "mug-1")  # in the driver's world
        drawer = run.environment.client.transport.environment_joint_states()
    assert run.tree.root.status.name == "SUCCEEDED"
    assert result.object_name == "mug-1"
    assert result.opened == []
    _on_the_table_top(scene.world, mug)
    assert mug.position[:2] == pytest.approx(result.spot.position[:2], abs=0.01)
    assert scene.world.attachments("pr2") == {}  # let go in the mirror too
    assert drawer["/kitchen/joint_states"][DRAWER_JOINT] == pytest.approx(0.0)
    # the same seeds, the same world: the same stands (and failed stands) as in projection
    expected = _stands(in_projection)
    assert [stage for stage, _ in _stands(result)] == [stage for stage, _ in expected]
    for (_, stand), (_, projected) in zip(_stands(result), expected, strict=True):
        assert stand.distance_to(projected) < SAME


def test_the_mirror_takes_the_kitchen_joints_and_objects_from_the_robot_side(
    roscore: Roscore,
) -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    believed = world.pose("mug-1")
    world.set_joint_states("kitchen", {DRAWER_JOINT: 0.3})  # what the caller got wrong
    world.set_pose("mug-1", Pose((0.0, 0.0, 2.0)))
    with (
        DriverProcess(roscore.uri, controllers="pr2", scene="kitchen"),
        ros_robot("pr2", roscore.uri, world=world),
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
    assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(0.1, abs=0.005)
    assert world.joint_states("kitchen")[DRAWER_JOINT] == pytest.approx(0.0)
    assert world.pose("mug-1").distance_to(believed) < 1e-6


def test_what_the_gripper_holds_moves_with_the_hand_in_the_mirror(roscore: Roscore) -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    with (
        DriverProcess(roscore.uri, controllers="pr2"),
        ros_robot("pr2", roscore.uri, world=world) as run,
    ):
        result = pick_up(scene.look_target)
        mug = run.transforms.lookup("map", "mug-1")
    hand = world.robot("pr2").description.arms[result.arm].end_effector_link
    assert world.attachments("pr2") == {"mug-1": hand}
    assert world.pose("mug-1").distance_to(mug) < 1e-3  # lifted with the hand, as there
