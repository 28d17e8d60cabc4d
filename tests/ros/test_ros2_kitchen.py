"""ROS 2 in the kitchen: the unchanged transport through rclpy on the real PR2's
controllers, and on the Stretch (a differential base, coupled joints), against the
projection driver's kitchen; one driver per robot, reset between the tests."""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.designators import a
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans.transport import TransportResult, transport
from robocram.robots import load_description
from robocram.ros import ros_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.world import World
from tests.kitchen_transports import SHARED, Transports
from tests.ros.driver_pool import DriverPool
from tests.ros.received_goals import assert_same_goal

TABLE = ("kitchen", "table_top")
DRAWER_JOINT = "drawer_unit_drawer_3_joint"
RESTING = 0.015  # [m] the driver lets go without simulating: the bowl may stand this high
DRAWN = 0.005  # [m] stands in a world whose drawer the driver's hand moved
STRETCH = Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py"
STRETCH_FACTS = STRETCH.with_name("stretch_ros2.pl")
pytestmark = SHARED  # its projected transports are other modules' too


def _on_the_table_top(world: World, item: str, pose: Pose) -> None:
    """``item`` (at ``pose`` in the driver's world) stands on the table top, inside it."""
    low, _ = world.aabb(item)
    table_low, table_high = world.contacts.link_aabb("kitchen", "table_top")
    assert world.pose(item).distance_to(pose) < 1e-6  # the mirror shows it there too
    assert low[2] == pytest.approx(table_high[2], abs=RESTING)
    assert table_low[0] < pose.position[0] < table_high[0]
    assert table_low[1] < pose.position[1] < table_high[1]


def _same_stands(result: TransportResult, expected: TransportResult, within: float) -> None:
    """The stages tried in the same order, from stands at most ``within`` [m] apart."""
    stages = [(attempt.stage, attempt.stand) for attempt in result.log.attempts]
    projected = [(attempt.stage, attempt.stand) for attempt in expected.log.attempts]
    assert [stage for stage, _ in stages] == [stage for stage, _ in projected]
    for (_, stand), (_, want) in zip(stages, projected, strict=True):
        assert stand.distance_to(want) < within


@pytest.mark.parametrize(
    ("object_type", "item", "clock_offset"), [("mug", "mug-1", 0.0), ("bowl", "bowl-1", -10.0)]
)
def test_the_kitchen_transport_over_ros2_on_the_real_pr2s_controllers(
    drivers2: DriverPool,
    kitchen_transports: Transports,
    object_type: str,
    item: str,
    clock_offset: float,
) -> None:
    expected = kitchen_transports("pr2", object_type).done
    scene = kitchen_scene("pr2")
    serving = drivers2("pr2", controllers="pr2", clock_offset=clock_offset, scene="kitchen")
    with serving, ros_robot("pr2", ros=2, world=scene.world) as run:
        result = transport(object_type, a.location(on=TABLE, for_=item))
        placed = run.transforms.lookup("map", item)
        drawers = run.environment.client.transport.environment_joint_states()
        skew = run.environment.client.clock_skew
    assert run.tree.root.status.name == "SUCCEEDED"
    assert skew == pytest.approx(clock_offset, abs=0.5)
    _on_the_table_top(scene.world, item, placed)
    assert scene.world.bodies.attachments("pr2") == {}  # let go in the mirror too
    if object_type == "bowl":  # out of the drawer, which is shut again
        assert [opened.container.joint for opened in result.opened] == [DRAWER_JOINT]
        assert drawers["/kitchen/joint_states"][DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)
    else:
        assert result.opened == []
    _same_stands(result, expected, DRAWN)  # the same seeds, the same stands


@pytest.mark.parametrize(("object_type", "item"), [("mug", "mug-1"), ("bowl", "bowl-1")])
def test_the_stretch_transports_over_ros2_turning_its_base_for_its_sideways_arm(
    drivers2: DriverPool,
    kitchen_transports: Transports,
    tmp_path: Path,
    object_type: str,
    item: str,
) -> None:
    """A differential base with coupled joints: IK moves the base with the arm (Nav2
    goals; the drawer is opened and shut a step at a time, base and arm), a finger meeting
    the mug first pushes it into the grip (the robot side), and every trajectory goal is
    the one the plan side planned."""
    desc = load_description(STRETCH)
    expected = kitchen_transports(desc, object_type).done
    scene = kitchen_scene(desc)
    sent: list[JointTrajectory] = []
    serving = drivers2(
        str(STRETCH), scene="kitchen", ros_facts=STRETCH_FACTS, goal_log=tmp_path / "g"
    )
    facts = STRETCH_FACTS.read_text(encoding="utf-8")
    with (
        serving as driver,
        ros_robot(desc, ros=2, world=scene.world, ros_facts=facts) as run,
        trajectory_listener(sent.append),
    ):
        result = transport(object_type, a.location(on=TABLE, for_=item))
        placed = run.transforms.lookup("map", item)
        drawers = run.environment.client.transport.environment_joint_states()
        servers = ("/stretch_controller/follow_joint_trajectory",
                   "/head_controller/follow_joint_trajectory")  # fmt: skip
        received = {s: driver.received_goals(s) for s in servers}
        drives = driver.received_goals("/navigate_to_pose")
    assert run.tree.root.status.name == "SUCCEEDED"
    _on_the_table_top(scene.world, item, placed)
    _same_stands(result, expected, DRAWN)
    assert drawers["/kitchen/joint_states"][DRAWER_JOINT] == pytest.approx(0.0, abs=0.01)
    stands = [attempt.stand for attempt in result.log.attempts if attempt.stand is not None]
    assert len(drives) > len(stands)  # IK's base moves went to Nav2 as goals of their own
    assert len(sent) == sum(len(goals) for goals in received.values()) >= 6
    for trajectory in sent:  # in order per controller, as planned
        server = servers[trajectory.joint_names[0].startswith("joint_head")]
        assert_same_goal(received[server].pop(0), trajectory)
