"""The beginner tutorial scenarios on the turtle, through designators and PERFORM."""

from __future__ import annotations

import math
import threading
from typing import Any

import pytest

from robocram.designators import a, an
from robocram.execution import PlanFailure, TopLevel, par, pursue, seq
from robocram.execution.failures import DesignatorReferenceFailure
from robocram.execution.perform import perform
from robocram.execution.top_level import run_top_level
from robocram.turtlesim import (
    NothingHeard,
    TurtlePose,
    TurtleWorld,
    house_corners,
    noisy_turtle_environment,
    out_of_bounds_fluent,
    turtle_environment,
    voice_environment,
)


def test_driving_motion_moves_by_speed_and_angle() -> None:
    world = TurtleWorld(start=TurtlePose(3.0, 3.0, 0.0))
    with turtle_environment(world):
        pose = run_top_level(lambda: perform(a.motion(type="driving", speed=2, angle=0)))
    assert pose.x == pytest.approx(5.0) and pose.y == pytest.approx(3.0)


def test_moving_motion_ends_within_a_tenth_of_its_goal() -> None:
    world = TurtleWorld()
    with turtle_environment(world):
        pose = run_top_level(lambda: perform(a.motion(type="moving", goal=(5, 5, 0))))
    assert pose.distance_to(5, 5) < 0.1 and world.pose == pose


def test_parallel_performs_on_one_module_serialise() -> None:
    world = TurtleWorld(start=TurtlePose(1.0, 1.0, 0.0))
    env = turtle_environment(world)
    goals = [(2.0 + i % 7, 1.0 + i // 7) for i in range(16)]
    with env:
        poses = run_top_level(
            lambda: par(*[(lambda g=g: perform(a.motion(type="moving", goal=g))) for g in goals])
        )
    nav = env.module("turtle_navigation")
    assert nav.executed == 16 and not nav.running
    for goal, pose in zip(goals, poses, strict=True):
        assert pose.distance_to(*goal) < 0.1  # each reached its goal: none interleaved


def test_location_designator_of_a_grid_cell_gives_points_in_that_cell() -> None:
    world = TurtleWorld()
    with turtle_environment(world, seed=3):
        loc = a.location(horizontal_position="right", vertical_position="top")
        points = []
        current: Any = loc
        for _ in range(20):
            points.append(current.reference())
            current = current.next_solution()
        pose = run_top_level(lambda: perform(a.motion(type="moving", goal=loc)))
    assert len(set(points)) == 20
    assert all(11 * 2 / 3 <= x <= 11 and 11 * 2 / 3 <= y <= 11 for x, y, _ in points)
    assert pose.distance_to(*points[0][:2]) < 0.1


def test_drawing_a_house_is_a_sequence_of_navigation_actions() -> None:
    world = TurtleWorld()
    with turtle_environment(world):
        drawing = TopLevel("top-level")
        drawing.run(lambda: perform(an.action(type="drawing", shape="house")))
        tree = drawing.tree
    corners = house_corners((2, 2), 4)
    lines = world.lines
    assert len(lines) == 8
    for line, start, end in zip(lines, corners[:-1], corners[1:], strict=True):
        assert math.dist(line.start, start) < 0.1 and math.dist(line.end, end) < 0.1
    text = tree.render()
    assert text.count("perform navigating") == 9 and text.count("perform moving") == 9


def test_same_plan_runs_unchanged_in_a_noisy_logging_environment() -> None:
    log: list[str] = []
    exact, noisy = TurtleWorld(), TurtleWorld()

    def plan() -> Any:
        return perform(an.action(type="drawing", shape="house", origin=(1, 1), size=3))

    with turtle_environment(exact):
        run_top_level(plan)
    with noisy_turtle_environment(noisy, sigma=0.2, seed=7, log=log.append) as env:
        run_top_level(plan)
        assert env.module("noisy_turtle_navigation").executed == 9
    assert len(log) == 9 and log[0].startswith("go_to (1.00, 1.00)")
    errors = [math.dist(x.end, y.end) for x, y in zip(exact.lines, noisy.lines, strict=True)]
    assert max(errors) > 0.1 and all(e < 1.0 for e in errors)


def test_pursue_out_of_bounds_then_recover_by_clamping_the_goal() -> None:
    world = TurtleWorld(start=TurtlePose(5.5, 5.5, 0.0), step_delay=0.001)
    outside = out_of_bounds_fluent(world)
    goal = (15.0, 5.5)
    env = turtle_environment(world)

    def plan() -> TurtlePose:
        pursue(
            lambda: outside.wait_for(timeout=10),
            lambda: perform(a.motion(type="moving", goal=goal)),
        )
        assert outside.get()
        clamped = (min(max(goal[0], 0.5), world.size - 0.5), min(max(goal[1], 0.5), 10.5))
        return perform(a.motion(type="moving", goal=clamped))  # type: ignore[no-any-return]

    with env:
        pose = run_top_level(plan)
        nav = env.module("turtle_navigation")
        assert not nav.busy and nav.waiting == 0
    assert pose.distance_to(10.5, 5.5) < 0.1 and not outside.get()
    assert not nav.running


def test_unknown_motion_type_fails_with_the_known_types() -> None:
    with turtle_environment(TurtleWorld()), pytest.raises(DesignatorReferenceFailure) as caught:
        run_top_level(lambda: perform(a.motion(type="flying", height=3)))
    assert "(a motion (type flying) (height 3))" in str(caught.value)
    assert "'driving'" in str(caught.value) and "'moving'" in str(caught.value)


def test_a_robot_without_a_body_says_and_listens() -> None:
    env = voice_environment()
    voice = env.module("voice")

    def dialogue() -> str:
        perform(a.motion(type="saying", text="What shall I draw?"))
        answer: str = perform(a.motion(type="listening", timeout=2.0))
        perform(a.motion(type="saying", text=f"I will draw a {answer}."))
        return answer

    threading.Timer(0.05, voice.hear, args=("house",)).start()  # type: ignore[attr-defined]
    with env:
        answer = run_top_level(dialogue)
        with pytest.raises(NothingHeard, match="within 0.1 s"):
            run_top_level(lambda: perform(a.motion(type="listening", timeout=0.1)))
    assert answer == "house"
    assert voice.transcript == ["What shall I draw?", "I will draw a house."]  # type: ignore[attr-defined]


def test_failures_and_seq_compose_with_turtle_motions() -> None:
    world = TurtleWorld()
    steps = (
        lambda: perform(a.motion(type="moving", goal=(2, 2))),
        lambda: perform(a.motion(type="moving", goal="nowhere")),
    )
    with turtle_environment(world), pytest.raises(PlanFailure, match="cannot read a turtle goal"):
        run_top_level(lambda: seq(*steps))
    assert world.pose.distance_to(2, 2) < 0.1
