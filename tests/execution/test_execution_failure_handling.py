"""Failure handling: retry with counters, returning values, and never swallowing."""

from __future__ import annotations

import pytest

from robocram.execution import (
    FailureControl,
    PlanFailure,
    RetryCounter,
    TaskStopped,
    failure_handled,
    par,
    retry,
    run_top_level,
    sleep,
    with_failure_handling,
)
from robocram.execution.failures import (
    NavigationLowLevelFailure,
    NavigationPoseUnreachable,
    PerceptionObjectNotFound,
    RetryOutsideHandler,
    TorsoGoalNotReached,
)


def test_retry_reruns_the_body_until_it_succeeds_with_counts() -> None:
    attempts: list[int] = []
    seen_retries: list[int] = []

    def body() -> str:
        attempts.append(len(attempts))
        if len(attempts) < 4:
            raise NavigationPoseUnreachable(target=len(attempts))
        return "arrived"

    def handler(failure: NavigationPoseUnreachable, control: FailureControl) -> None:
        seen_retries.append(control.retries)
        retry()

    assert with_failure_handling(body, {NavigationPoseUnreachable: handler}) == "arrived"
    assert attempts == [0, 1, 2, 3]
    assert seen_retries == [0, 1, 2]


def test_retry_counter_bounds_retries_then_the_failure_propagates() -> None:
    attempts = 0
    counter = RetryCounter(2)

    def body() -> None:
        nonlocal attempts
        attempts += 1
        raise TorsoGoalNotReached(goal=0.5, limits=(0.0, 0.33), reached=0.33)

    with pytest.raises(TorsoGoalNotReached) as caught:
        with_failure_handling(body, {TorsoGoalNotReached: lambda f, c: counter.retry()})
    assert attempts == 3  # the first try and two retries
    assert counter.remaining == 0
    assert caught.value.reached == pytest.approx(0.33)


def test_next_solution_idiom_swaps_the_candidate_and_retries() -> None:
    candidates = iter([(1.0, 0.0), (2.0, 0.0), (3.0, 1.0)])
    target = next(candidates)
    free = {(3.0, 1.0)}

    def go() -> tuple[float, float]:
        if target not in free:
            raise NavigationPoseUnreachable(target=target, colliding=["table"])
        return target

    def next_solution(failure: NavigationPoseUnreachable, control: FailureControl) -> None:
        nonlocal target
        solution = next(candidates, None)
        if solution is not None:
            target = solution
            retry()

    assert run_top_level(
        lambda: with_failure_handling(go, {NavigationPoseUnreachable: next_solution})
    ) == (
        3.0,
        1.0,
    )


def test_handler_can_return_a_value_for_the_form() -> None:
    def body() -> str:
        raise PerceptionObjectNotFound(object_designator="cup")

    handlers = {PlanFailure: lambda f, c: c.return_value(f"fallback for {f.object_designator}")}
    assert with_failure_handling(body, handlers) == "fallback for cup"


def test_falling_off_or_returning_from_a_handler_propagates_the_failure() -> None:
    failure = PerceptionObjectNotFound(object_designator="cup")

    def body() -> None:
        raise failure

    with pytest.raises(PerceptionObjectNotFound) as caught:
        with_failure_handling(body, {PlanFailure: lambda f, c: "returned, not handled"})
    assert caught.value is failure


def test_first_matching_handler_in_order_is_used_and_others_pass_through() -> None:
    called: list[str] = []

    def body() -> None:
        raise NavigationPoseUnreachable(target=1)

    handlers = {
        NavigationLowLevelFailure: lambda f, c: (called.append("navigation"), c.return_value(1)),
        PlanFailure: lambda f, c: (called.append("any"), c.return_value(2)),
    }
    assert with_failure_handling(body, handlers) == 1
    assert called == ["navigation"]
    with pytest.raises(ValueError):
        with_failure_handling(lambda: int("x"), handlers)


def test_nested_handlers_retry_their_own_body() -> None:
    outer_runs = 0
    inner_runs = 0

    def inner_body() -> None:
        nonlocal inner_runs
        inner_runs += 1
        raise TorsoGoalNotReached(goal=1.0)

    def outer_body() -> None:
        nonlocal outer_runs
        outer_runs += 1
        if outer_runs > 1:
            return
        with_failure_handling(inner_body, {PerceptionObjectNotFound: lambda f, c: retry()})

    with_failure_handling(outer_body, {TorsoGoalNotReached: lambda f, c: retry()})
    assert (outer_runs, inner_runs) == (2, 1)


def test_retry_outside_a_handler_is_a_clear_error() -> None:
    with pytest.raises(RetryOutsideHandler, match="outside a failure handler"):
        retry()
    with pytest.raises(RetryOutsideHandler):
        with_failure_handling(retry, {PlanFailure: lambda f, c: None})


def test_task_stopped_cannot_be_handled() -> None:
    with pytest.raises(TypeError, match="stopping a task is not a failure"):
        with_failure_handling(lambda: 1, {TaskStopped: lambda f, c: None})
    with pytest.raises(TypeError, match="not an exception type"):
        with_failure_handling(lambda: 1, {"PlanFailure": lambda f, c: None})  # type: ignore[dict-item]


def test_handlers_do_not_catch_stopping() -> None:
    handled: list[object] = []

    def guarded_sleep() -> None:
        with_failure_handling(lambda: sleep(5.0), {Exception: lambda f, c: handled.append(f)})

    with pytest.raises(NavigationPoseUnreachable):
        run_top_level(lambda: par(guarded_sleep, lambda: (sleep(0.01), retry_free_fail())))
    assert handled == []


def retry_free_fail() -> None:
    raise NavigationPoseUnreachable(target=0)


def test_decorator_form_retries_each_call() -> None:
    calls = 0
    counter = RetryCounter(1)

    @failure_handled({TorsoGoalNotReached: lambda f, c: counter.retry()})
    def move_torso(goal: float) -> float:
        nonlocal calls
        calls += 1
        if calls == 1:
            raise TorsoGoalNotReached(goal=goal)
        return goal

    assert move_torso(0.2) == pytest.approx(0.2)
    assert calls == 2
