"""The kitchen over ROS: the unchanged transport on the driver's kitchen with the real
PR2's controllers and a robot clock 10 s off, planned in a mirror of the robot side.

The mug goes from the counter to the table; the bowl comes out of a drawer the PR2 opens
(moving-articulation: one arm trajectory along the handle, the driver moving the drawer
with the hand) and closes again. Same seeds, same world: the same stands as projection.
"""

from __future__ import annotations

import xmlrpc.client

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.plans import pick_up
from robocram.plans.transport import TransportResult, transport
from robocram.ros import Roscore, ros_robot
from robocram.scenes import kitchen_scene, tabletop_scene
from robocram.tf import Pose
from robocram.world import World
from tests.kitchen_transports import SHARED, Transports
from tests.ros.driver_pool import DriverPool
from tests.ros.served_state import assert_same_state, served_state

TABLE = ("kitchen", "table_top")
pytestmark = SHARED  # its projected transports are other modules' too
DRAWER_JOINT = "drawer_unit_drawer_3_joint"
RESTING = 0.015  # [m] the driver lets go without simulating: the mug may stand this high
SAME = 1e-6  # [m | rad] stands chosen by the same seeds in the same world
DRAWN = 0.005  # [m | rad] ... in a world whose drawer the driver's hand moved
# [s] the driver's /tf this late, as our node's tf thread handles it on a loaded machine
# (transforms from before a goal's end handled after its result: the stamps must decide)
TF_LAG = 0.05
SAME_STATE = 1e-9  # [m | rad] a reset driver's state is a fresh one's (float64 on the wire)
DRIVER_NODE = "/robocram_driver"


def _to_the_table(object_type: str, item: str) -> TransportResult:
    return transport(object_type, a.location(on=TABLE, for_=item))


def _stands(result: TransportResult) -> list[tuple[str, Pose]]:
    return [(attempt.stage, attempt.stand) for attempt in result.log.attempts]


def _on_the_table_top(world: World, item: str, pose: Pose) -> None:
    """``item`` (at ``pose`` in the driver's world) stands upright on the table top,
    inside its outline; the mirror shows it there too."""
    low, _ = world.aabb(item)
    table_low, table_high = world.contacts.link_aabb("kitchen", "table_top")
    assert world.pose(item).distance_to(pose) < 1e-6
    assert low[2] == pytest.approx(table_high[2], abs=RESTING)
    assert table_low[0] < pose.position[0] < table_high[0]
    assert table_low[1] < pose.position[1] < table_high[1]
    assert abs(pose.orientation[0]) < 1e-3 and abs(pose.orientation[1]) < 1e-3  # upright


def _same_stands(result: TransportResult, expected: TransportResult, within: float) -> None:
    """The stages tried in the same order, from stands at most ``within`` [m | rad] apart."""
    assert [stage for stage, _ in _stands(result)] == [stage for stage, _ in _stands(expected)]
    for (_, stand), (_, projected) in zip(_stands(result), _stands(expected), strict=True):
        assert stand.distance_to(projected) < within
        assert stand.angle_to(projected) < within


def test_the_mug_goes_to_the_table_on_the_real_pr2_with_its_clock_ahead(
    roscore: Roscore, drivers: DriverPool, kitchen_transports: Transports
) -> None:
    expected = kitchen_transports("pr2", "mug").done
    scene = kitchen_scene("pr2")
    with (
        drivers(controllers="pr2", clock_offset=10.0, scene="kitchen"),
        ros_robot("pr2", roscore.uri, world=scene.world) as run,
    ):
        result = _to_the_table("mug", "mug-1")
        mug = run.transforms.lookup("map", "mug-1")  # in the driver's world
        skew = run.environment.client.clock_skew
    assert run.tree.root.status.name == "SUCCEEDED"
    assert skew == pytest.approx(10.0, abs=0.5)
    assert result.object_name == "mug-1"
    assert result.opened == []
    _on_the_table_top(scene.world, "mug-1", mug)
    assert mug.position[:2] == pytest.approx(result.spot.position[:2], abs=0.01)
    assert scene.world.bodies.attachments("pr2") == {}  # let go in the mirror too
    _same_stands(result, expected, SAME)  # the same seeds in the same world


def test_the_bowl_comes_out_of_the_drawer_on_the_real_pr2_with_its_clock_behind(
    roscore: Roscore, drivers: DriverPool, kitchen_transports: Transports
) -> None:
    expected = kitchen_transports("pr2", "bowl").done
    scene = kitchen_scene("pr2")
    with (
        drivers(controllers="pr2", clock_offset=-10.0, scene="kitchen", tf_lag=TF_LAG),
        ros_robot("pr2", roscore.uri, world=scene.world) as run,
    ):
        result = _to_the_table("bowl", "bowl-1")
        bowl = run.transforms.lookup("map", "bowl-1")
        drawer = run.environment.client.transport.environment_joint_states()
    assert run.tree.root.status.name == "SUCCEEDED"
    assert [opened.container.joint for opened in result.opened] == [DRAWER_JOINT]
    _on_the_table_top(scene.world, "bowl-1", bowl)
    assert drawer["/kitchen/joint_states"][DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)  # shut
    assert scene.world.joint_states("kitchen")[DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)
    # the driver moves the drawer with the hand, not as projection sets it: the bowl ends a
    # fraction of a millimetre elsewhere in it, and the stands that depend on it with it
    _same_stands(result, expected, DRAWN)


def _driver_topics(uri: str) -> dict[str, set[str]]:
    """What the driver node publishes and serves, as the master lists them."""
    code, _, (publishers, _, services) = xmlrpc.client.ServerProxy(uri).getSystemState("/t")
    assert code == 1
    return {
        kind: {name for name, nodes in listed if DRIVER_NODE in nodes}
        for kind, listed in (("publishes", publishers), ("serves", services))
    }


def test_a_reset_driver_serves_what_a_fresh_one_does(roscore: Roscore, drivers: DriverPool) -> None:
    """The module's driver, moved by the test before (the bowl out of its drawer, the
    drawer opened and shut) and here (torso, base, clock, lag), is reset: it serves the
    joints of the robot and the kitchen, every transform and its topics as a fresh one."""
    topics = ["/joint_states", "/kitchen/joint_states"]
    with (
        drivers(controllers="pr2", scene="kitchen", clock_offset=-10.0, tf_lag=TF_LAG),
        ros_robot("pr2", roscore.uri) as run,
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.2))
        perform(a.motion(type="going", target=a.location(pose=Pose((-0.4, 0.3, 0.0)))))
        moved = run.environment.client.joint_states()["torso_lift_joint"]
    with drivers(controllers="pr2", scene="kitchen"):
        reset = served_state(topics, roscore.uri)
        reset_topics = _driver_topics(roscore.uri)
    drivers.close()  # the next driver of the pool is started fresh (the tests after use it)
    started = drivers.started
    with drivers(controllers="pr2", scene="kitchen"):
        fresh = served_state(topics, roscore.uri)
        fresh_topics = _driver_topics(roscore.uri)
    assert drivers.started == started + 1
    assert moved == pytest.approx(0.2, abs=0.005)
    assert fresh["/joint_states"]["torso_lift_joint"] != pytest.approx([0.2], abs=0.005)
    assert_same_state(reset, fresh, SAME_STATE)
    assert reset_topics == fresh_topics
    assert "/kitchen/joint_states" in fresh_topics["publishes"]


def test_the_mirror_takes_the_kitchen_joints_and_objects_from_the_robot_side(
    roscore: Roscore,
    drivers: DriverPool,
) -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    believed = world.pose("mug-1")
    world.set_joint_states("kitchen", {DRAWER_JOINT: 0.3})  # what the caller got wrong
    world.set_pose("mug-1", Pose((0.0, 0.0, 2.0)))
    with (
        drivers(controllers="pr2", scene="kitchen"),
        ros_robot("pr2", roscore.uri, world=world),
    ):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
    assert world.joint_states("pr2")["torso_lift_joint"] == pytest.approx(0.1, abs=0.005)
    assert world.joint_states("kitchen")[DRAWER_JOINT] == pytest.approx(0.0)
    assert world.pose("mug-1").distance_to(believed) < 1e-6


def test_what_the_gripper_holds_moves_with_the_hand_in_the_mirror(
    roscore: Roscore, drivers: DriverPool
) -> None:
    scene = tabletop_scene("pr2")
    world = scene.world
    with (
        drivers(controllers="pr2"),
        ros_robot("pr2", roscore.uri, world=world) as run,
    ):
        result = pick_up(scene.look_target)
        mug = run.transforms.lookup("map", "mug-1")
    hand = world.robot("pr2").description.arms[result.arm].end_effector_link
    assert world.bodies.attachments("pr2") == {"mug-1": hand}
    assert world.pose("mug-1").distance_to(mug) < 1e-3  # lifted with the hand, as there
