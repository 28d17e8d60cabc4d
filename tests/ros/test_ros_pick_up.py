"""Acceptance: the pick-up plan runs unchanged through ROS and agrees with projection,
with motions planned straight or in a world of the scene."""

from __future__ import annotations

import multiprocessing
import threading
from collections.abc import Callable

import pytest

from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.ros import Roscore, ros_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose, PoseStamped, transform_pose
from tests.ros.driver_pool import DriverPool

AGREE = 0.01  # [m] ROS and direct projection agree this closely


Direct = tuple[Pose, Pose, Pose, str]


def _direct(robot: str) -> Direct:
    """Tool at grasp, tool lifted, lifted mug, arm: all in map, by direct projection."""
    scene = tabletop_scene(robot)
    world = scene.world
    with simulated_robot(world, robot):
        result = pick_up(scene.look_target)
    assert result.grasp.frame_id == "map"
    direct = (
        result.grasp.pose,
        world.link_pose(robot, result.tool_frame),
        world.pose("mug-1"),
        result.arm,
    )
    world.close()
    return direct


@pytest.fixture(scope="module")
def projected() -> Callable[[str], Direct]:
    """``_direct`` of a robot, projected once for the module's tests of that robot."""
    done: dict[str, Direct] = {}

    def of(robot: str) -> Direct:
        if robot not in done:
            done[robot] = _direct(robot)
        return done[robot]

    return of


@pytest.mark.parametrize(
    ("robot", "with_world"),
    [
        ("pr2", False),
        ("pr2", True),
        ("hsrb", False),
        ("hsrb", True),  # its hand met its head, turned down at the mug: the pick looks
        # ahead and tries again (plans/pick_object.py), over ROS as in projection
    ],
    ids=["pr2-no_world", "pr2-world", "hsrb-no_world", "hsrb-world"],
)
def test_pick_up_through_ros_agrees_with_projection(
    roscore: Roscore,
    drivers: DriverPool,
    projected: Callable[[str], Direct],
    master_nodes: Callable[[], set[str]],
    robot: str,
    with_world: bool,
) -> None:
    grasp, tool, mug, arm = projected(robot)
    scene = tabletop_scene(robot)
    look = scene.look_target
    world = scene.world if with_world else None  # motions checked in it
    threads = set(threading.enumerate())
    with drivers(robot), ros_robot(robot, roscore.uri, world=world) as run:
        result = pick_up(look)
        ros_tool = transform_pose(PoseStamped(result.tool_frame), "map").pose
        ros_mug = run.transforms.lookup("map", "mug-1")
        ros_grasp = transform_pose(result.grasp, "map").pose
        node = run.environment.client.transport.node_name  # type: ignore[attr-defined]
        assert node in master_nodes()
    assert run.tree.root.status.name == "SUCCEEDED"
    assert result.arm == arm
    assert ros_tool.distance_to(tool) < AGREE
    assert ros_mug.distance_to(mug) < AGREE
    assert ros_mug.position[2] > 0.09 + look.position[2]  # lifted
    assert ros_grasp.distance_to(grasp) < AGREE
    assert set(threading.enumerate()) == threads
    assert multiprocessing.active_children() == []
    assert node not in master_nodes()
