"""Kitchen transports in projection, the stands a ROS run must match: run once for every
ROS test comparing with one (``test_ros_kitchen_transport.py`` and ``test_ros2_kitchen.py``
compare with the same PR2 mug and bowl transports; the conftest's ``projected_transports``
keeps them for the session)."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from robocram.designators import a
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.robots import RobotDescription
from robocram.scenes import kitchen_scene

TABLE = ("kitchen", "table_top")
# the modules sharing these runs: one xdist worker runs them, so each run is made once
SHARED = pytest.mark.xdist_group("ros/projected_transports")
# what the conftest's ``projected_transports`` gives: (robot, object type, item) -> result
Projected = Callable[[str | RobotDescription, str, str], TransportResult]


def projected_transport(
    robot: str | RobotDescription, object_type: str, item: str
) -> TransportResult:
    """``item`` (an ``object_type``) taken to the kitchen's table top on ``robot``, projected."""
    scene = kitchen_scene(robot)
    with simulated_robot(scene.world, scene.robot):
        result = transport(object_type, a.location(on=TABLE, for_=item))
    scene.world.close()
    return result
