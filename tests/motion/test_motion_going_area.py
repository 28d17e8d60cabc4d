"""A base goal or a location anchor far outside the world is refused at once, naming the
bound, and never rasterised (issue 42, bad 4)."""

from __future__ import annotations

import time
import tracemalloc

import pytest

from robocram.costmaps import CostmapLocations, LocationOutsideArea
from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import NavigationGoalOutsideArea
from robocram.motion import plan_base_path
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.world import AREA_MARGIN, RobotHandle, World


def test_a_goal_10_km_away_is_refused_at_once(kitchen: World) -> None:
    start = kitchen.pose("pr2")
    tracemalloc.start()
    began = time.perf_counter()
    try:
        with pytest.raises(NavigationGoalOutsideArea) as caught:
            plan_base_path(RobotHandle.of(kitchen, "pr2"), Pose((10_000.0, 0.0, 0.0)))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert time.perf_counter() - began < 5.0 and peak < 50e6  # [s], [bytes]
    assert caught.value.margin == AREA_MARGIN
    (low_x, _), (high_x, _) = caught.value.area
    assert high_x < 100.0 and low_x > -100.0
    assert "(10000, 0) m" in str(caught.value) and "AREA_MARGIN" in str(caught.value)
    assert kitchen.pose("pr2") == start


def test_a_goal_within_the_margin_is_still_planned(kitchen: World) -> None:
    here = kitchen.pose("pr2")
    goal = Pose((here.position[0], here.position[1] - 0.5, 0.0), here.orientation)
    path = plan_base_path(RobotHandle.of(kitchen, "pr2"), goal)
    assert path.poses[-1][:2] == pytest.approx(goal.position[:2], abs=1e-9)
    assert kitchen.pose("pr2") == here


def test_going_far_through_the_process_module_is_a_navigation_failure(kitchen: World) -> None:
    with simulated_robot(kitchen, "pr2"), pytest.raises(NavigationGoalOutsideArea) as caught:
        perform(a.motion(type="going", target=PoseStamped("map", (0.0, 10_000.0, 0.0))))
    assert "AREA_MARGIN" in str(caught.value)


def test_a_stand_for_a_target_100_km_away_is_refused(kitchen: World) -> None:
    locations = CostmapLocations(kitchen, seed=0)
    designator = a.location(reachable_for="pr2", target=(100_000.0, 0.0, 0.8))
    with pytest.raises(LocationOutsideArea) as caught:
        next(iter(locations.poses(designator)))
    assert caught.value.culprit == (100_000.0, 0.0, 0.8)
    assert "AREA_MARGIN" in str(caught.value) and "(100000, 0, 0.8) m" in str(caught.value)
