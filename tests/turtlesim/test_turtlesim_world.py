"""The turtle simulator and its go-to controller."""

from __future__ import annotations

import math

import pytest

from robocram.execution.failures import NavigationGoalNotReached
from robocram.turtlesim import GoToGains, TurtlePose, TurtleWorld, go_to, house_corners


def test_drive_integrates_speed_and_turn_rate() -> None:
    world = TurtleWorld(start=TurtlePose(2.0, 2.0, 0.0))
    pose = world.drive(1.0, 0.0, duration=1.0)
    assert pose.x == pytest.approx(3.0) and pose.y == pytest.approx(2.0)
    pose = world.drive(0.0, math.pi / 2, duration=1.0)
    assert pose.theta == pytest.approx(math.pi / 2) and pose.x == pytest.approx(3.0)
    # a full circle of radius 1 returns to the start
    world.teleport(TurtlePose(5.0, 5.0, 0.0))
    pose = world.drive(1.0, 1.0, duration=2 * math.pi)
    assert pose.distance_to(5.0, 5.0) < 0.05


def test_pen_draws_merged_straight_lines_only_when_down() -> None:
    world = TurtleWorld(start=TurtlePose(1.0, 1.0, 0.0))
    world.set_pen(False)
    world.drive(1.0, 0.0)
    world.set_pen(True, "red")
    world.drive(2.0, 0.0)
    world.drive(0.0, math.pi / 2)
    world.drive(1.0, 0.0)
    lines = world.lines
    assert len(lines) == 2
    assert lines[0].start == pytest.approx((2.0, 1.0)) and lines[0].end == pytest.approx((4.0, 1.0))
    assert lines[1].end == pytest.approx((4.0, 2.0), abs=1e-6) and lines[1].colour == "red"


def test_go_to_ends_within_a_tenth_of_the_goal_by_stepping() -> None:
    world = TurtleWorld()
    for goal in [(1.0, 1.0), (10.0, 1.0), (10.0, 10.0), (5.5, 0.5)]:
        pose = go_to(world, *goal)
        assert pose.distance_to(*goal) < 0.1
    assert world.steps > 300  # it drove there, no teleport


def test_go_to_gives_up_with_a_typed_failure() -> None:
    world = TurtleWorld(start=TurtlePose(1.0, 1.0, 0.0))
    with pytest.raises(NavigationGoalNotReached) as caught:
        go_to(world, 10.0, 10.0, GoToGains(max_time=1.0))
    assert caught.value.target == (10.0, 10.0) and caught.value.error > 1.0


def test_world_rejects_bad_input() -> None:
    with pytest.raises(ValueError, match="size > 0"):
        TurtleWorld(size=0)
    with pytest.raises(ValueError, match="finite"):
        TurtleWorld().step(float("nan"), 0.0)
    with pytest.raises(ValueError, match="origin"):
        house_corners((1.0,), 2.0)
