"""The quadrotor in projection: flights to waypoints, a collision, and the range sensor."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from robocram.designators import a
from robocram.execution import perform
from robocram.execution.failures import FlyingGoalInCollision, NoMatchingProcessModule
from robocram.projection import simulated_robot
from robocram.tf import Pose, PoseStamped
from robocram.world import World


@pytest.fixture
def world() -> Iterator[World]:
    w = World()
    w.add_floor()
    w.add_robot("quadrotor", pose=Pose((0.0, 0.0, 0.2)))
    w.add_box("crate", (1.0, 1.0, 1.0), pose=Pose((3.0, 0.0, 0.5)))
    yield w
    w.close()


def _distance_down() -> float:
    return float(perform(a.motion(type="distance-sensing", direction=(0.0, 0.0, -1.0))))


def test_flies_three_waypoints_and_senses_the_floor(world: World) -> None:
    waypoints = [(0.0, 0.0, 1.0), (1.5, 1.0, 1.5), (1.5, -1.0, 0.8)]
    heights = []
    with simulated_robot(world, "quadrotor"):
        for point in waypoints:
            perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", point))))
            reached = world.pose("quadrotor")
            assert reached.distance_to(Pose(point)) < 0.01
            heights.append(_distance_down())
    assert heights == pytest.approx([1.0, 1.5, 0.8], abs=0.01)


def test_senses_the_crate_ahead(world: World) -> None:
    with simulated_robot(world, "quadrotor"):
        perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", (0, 0, 0.5)))))
        ahead = perform(a.motion(type="distance-sensing", direction=(1.0, 0.0, 0.0)))
    assert ahead == pytest.approx(2.5, abs=0.01)  # the crate's near face is at x = 2.5


def test_flying_through_the_crate_fails_and_stays(world: World) -> None:
    with simulated_robot(world, "quadrotor"):
        perform(a.motion(type="flying", target=a.location(pose=PoseStamped("map", (0, 0, 0.5)))))
        start = world.pose("quadrotor")
        beyond = PoseStamped("map", (5.0, 0.0, 0.5))
        with pytest.raises(FlyingGoalInCollision) as info:
            perform(a.motion(type="flying", target=a.location(pose=beyond)))
    assert info.value.colliding == ["crate"]
    assert world.pose("quadrotor").distance_to(start) < 1e-9


def test_a_quadrotor_has_no_torso_module(world: World) -> None:
    with simulated_robot(world, "quadrotor"), pytest.raises(NoMatchingProcessModule):
        perform(a.motion(type="moving-torso", joint_angle=0.1))
