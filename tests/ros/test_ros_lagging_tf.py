"""The state after a goal does not depend on how late the client handles transforms.

On a loaded machine our node's tf thread lags behind its joint-state thread: transforms
published before a goal ended are handled after the goal's result. The driver's
``tf_lag`` sends them that late on purpose; the mirror must still show the robot where
the goal left it (the robot's results and states stamped by one clock, its own).
"""

from __future__ import annotations

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.ros import Roscore, ros_robot
from robocram.scenes import tabletop_scene
from robocram.tf import Pose
from tests.ros.driver_pool import DriverPool

LAG = 0.3  # [s] ~10 publications of the driver's state: far more than a loaded machine's
GOALS = (Pose((-0.3, 0.2, 0.0)), Pose((-0.6, -0.2, 0.0)), Pose((-0.2, 0.0, 0.0)))
THERE = 1e-3  # [m | rad] the driver jumps to a free base goal


@pytest.mark.parametrize("offset", [-10.0, 0.0], ids=["clock_behind", "same_clock"])
def test_the_mirror_shows_the_base_where_each_goal_left_it_though_tf_lags(
    roscore: Roscore, drivers: DriverPool, offset: float
) -> None:
    world = tabletop_scene("pr2").world
    seen = []
    with (
        drivers(controllers="pr2", clock_offset=offset, tf_lag=LAG),
        ros_robot("pr2", roscore.uri, world=world),
    ):
        for goal in GOALS:
            perform(a.motion(type="going", target=a.location(pose=goal)))
            seen.append(world.pose("pr2"))  # as the state after the goal put it
    for base, goal in zip(seen, GOALS, strict=True):
        assert base.distance_to(goal) < THERE
        assert base.angle_to(goal) < THERE
