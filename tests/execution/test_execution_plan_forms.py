"""Plan forms: values, failure propagation, stopping, ordering and thread hygiene."""

from __future__ import annotations

import threading
import time
from collections.abc import Iterator
from typing import TypeVar

import pytest

from robocram.execution import (
    NotInTopLevel,
    PlanFailure,
    TaskStatus,
    TaskStopped,
    TopLevel,
    current_task,
    par,
    partial_order,
    pursue,
    run_top_level,
    seq,
    sleep,
    tagged,
    top_level,
    try_all,
    try_in_order,
    with_tags,
)
from robocram.execution.failures import (
    CompositeFailure,
    NavigationPoseUnreachable,
    PerceptionObjectNotFound,
    TorsoGoalNotReached,
)

T = TypeVar("T")


def after(seconds: float, value: T) -> T:
    """Sleep (a stop point), then give ``value``."""
    sleep(seconds)
    return value


@pytest.fixture(autouse=True)
def no_leaked_threads() -> Iterator[None]:
    before = {t.ident for t in threading.enumerate()}
    yield
    leaked = [t.name for t in threading.enumerate() if t.ident not in before]
    assert leaked == []


def fail_after(seconds: float, failure: PlanFailure) -> None:
    sleep(seconds)
    raise failure


def test_seq_returns_last_value_and_records_each_step() -> None:
    order: list[str] = []
    tl = TopLevel("top-level")
    result = tl.run(
        lambda: seq(("a", lambda: order.append("a") or 1), ("b", lambda: order.append("b") or 2))
    )
    tree = tl.tree
    assert result == 2
    assert order == ["a", "b"]
    seq_node = tree.find("top-level/seq")
    assert [c.name for c in seq_node.children] == ["a", "b"]
    assert [c.result for c in seq_node.children] == [1, 2]


def test_seq_stops_at_first_failure() -> None:
    ran: list[str] = []
    failure = TorsoGoalNotReached(goal=0.5, reached=0.3)
    with pytest.raises(TorsoGoalNotReached) as caught:
        run_top_level(
            lambda: seq(lambda: ran.append("a"), lambda: fail_after(0, failure), ran.clear)
        )
    assert caught.value is failure
    assert ran == ["a"]


def test_par_returns_all_results_in_step_order() -> None:
    result = run_top_level(
        lambda: par(lambda: after(0.03, "slow"), lambda: after(0.01, "mid"), lambda: "fast")
    )
    assert result == ["slow", "mid", "fast"]


def test_par_first_failure_stops_the_others_and_is_raised() -> None:
    first = NavigationPoseUnreachable(target=(1.0, 2.0, 0.0))
    second = PerceptionObjectNotFound(object_designator="cup")
    runner = top_level(name="plan")
    with pytest.raises(NavigationPoseUnreachable) as caught, runner:
        par(
            ("fails_first", lambda: fail_after(0.02, first)),
            ("fails_later", lambda: fail_after(0.3, second)),
            ("long", lambda: sleep(5.0)),
        )
    assert caught.value is first
    # "long" evaporated: its 5 s sleep was cut short by the stop, not waited out
    statuses = {c.name: c.status for c in runner.tree.find("plan/par").children}
    assert statuses == {
        "fails_first": TaskStatus.FAILED,
        "fails_later": TaskStatus.EVAPORATED,
        "long": TaskStatus.EVAPORATED,
    }
    assert runner.task.status is TaskStatus.FAILED


def test_par_with_many_children_loses_no_result() -> None:
    n = 150
    result = run_top_level(
        lambda: par(*[(f"c{i}", lambda i=i: after(0.001, i * i)) for i in range(n)])
    )
    assert result == [i * i for i in range(n)]


def test_pursue_returns_winner_and_stops_losers() -> None:
    runner = top_level(name="plan")
    with runner:
        value = pursue(("slow", lambda: after(5.0, "slow")), ("quick", lambda: after(0.01, 7)))
    assert value == 7
    children = {c.name: c.status for c in runner.tree.find("plan/pursue").children}
    assert children == {"slow": TaskStatus.EVAPORATED, "quick": TaskStatus.SUCCEEDED}


def test_pursue_raises_when_the_first_finisher_fails() -> None:
    failure = TorsoGoalNotReached(goal=0.2)
    with pytest.raises(TorsoGoalNotReached):
        run_top_level(lambda: pursue(lambda: fail_after(0.01, failure), lambda: sleep(5.0)))


def test_try_in_order_returns_first_success_and_skips_the_rest() -> None:
    ran: list[int] = []

    def attempt(i: int, ok: bool) -> int:
        ran.append(i)
        if not ok:
            raise NavigationPoseUnreachable(target=i)
        return i * 10

    result = run_top_level(
        lambda: try_in_order(
            lambda: attempt(1, False), lambda: attempt(2, True), lambda: attempt(3, True)
        )
    )
    assert result == 20
    assert ran == [1, 2]


def test_try_in_order_all_failing_raises_composite_with_every_failure() -> None:
    failures = [
        NavigationPoseUnreachable(target=1),
        PerceptionObjectNotFound(object_designator="x"),
    ]
    with pytest.raises(CompositeFailure) as caught:
        run_top_level(lambda: try_in_order(*[lambda f=f: fail_after(0, f) for f in failures]))
    assert caught.value.failures == failures
    assert caught.value.form == "try_in_order"


def test_try_forms_let_bugs_through_at_once() -> None:
    with pytest.raises(ZeroDivisionError):
        run_top_level(lambda: try_in_order(lambda: 1 / 0, lambda: 1))
    with pytest.raises(ZeroDivisionError):
        run_top_level(lambda: try_all(lambda: 1 / 0, lambda: sleep(5.0)))


def test_try_all_first_success_wins_failures_ignored() -> None:
    runner = top_level(name="plan")
    with runner:
        value = try_all(
            ("bad", lambda: fail_after(0, TorsoGoalNotReached(goal=1.0))),
            ("good", lambda: after(0.02, "ok")),
            ("slow", lambda: after(5.0, "late")),
        )
    assert value == "ok"
    statuses = {c.name: c.status for c in runner.tree.find("plan/try_all").children}
    assert statuses["bad"] is TaskStatus.FAILED
    assert statuses["slow"] is TaskStatus.EVAPORATED


def test_try_all_all_failing_raises_composite_in_step_order() -> None:
    a, b = TorsoGoalNotReached(goal=1.0), NavigationPoseUnreachable(target=2)
    with pytest.raises(CompositeFailure) as caught:
        run_top_level(lambda: try_all(lambda: fail_after(0.02, a), lambda: fail_after(0, b)))
    assert caught.value.failures == [a, b]


def test_partial_order_respects_orderings() -> None:
    log: list[tuple[str, str, float]] = []
    lock = threading.Lock()

    def step(name: str, duration: float) -> str:
        with lock:
            log.append((name, "start", time.monotonic()))
        sleep(duration)
        with lock:
            log.append((name, "end", time.monotonic()))
        return name.upper()

    steps = {n: (lambda n=n: step(n, 0.01)) for n in ["grasp", "open", "look", "lift"]}
    orderings = [("open", "grasp"), ("look", "grasp"), ("grasp", "lift")]
    result = run_top_level(lambda: partial_order(steps, orderings))
    assert result == {"grasp": "GRASP", "open": "OPEN", "look": "LOOK", "lift": "LIFT"}
    at = {(n, what): t for n, what, t in log}
    for before, after in orderings:
        assert at[(before, "end")] <= at[(after, "start")]


def test_partial_order_failure_evaporates_waiting_steps() -> None:
    runner = top_level(name="plan")
    failure = PerceptionObjectNotFound(object_designator="cup")
    with pytest.raises(PerceptionObjectNotFound), runner:
        partial_order(
            {"detect": lambda: fail_after(0.01, failure), "grasp": lambda: 1}, [("detect", "grasp")]
        )
    grasp = runner.tree.find("plan/partial_order/grasp")
    assert grasp.status is TaskStatus.EVAPORATED


def test_partial_order_rejects_unknown_steps_and_cycles() -> None:
    with pytest.raises(ValueError, match="did you mean 'grasp'"):
        run_top_level(lambda: partial_order({"grasp": lambda: 1}, [("grap", "grasp")]))
    with pytest.raises(ValueError, match="cycle"):
        run_top_level(
            lambda: partial_order({"a": lambda: 1, "b": lambda: 2}, [("a", "b"), ("b", "a")])
        )


def test_tags_let_a_sibling_suspend_and_resume_a_task() -> None:
    """No tick while suspended, all of them after: ordered by events, not by timing."""
    ticks: list[int] = []
    suspended = threading.Event()

    def worker() -> int:
        ticks.append(1)
        while not suspended.is_set():  # each sleep is a point where a suspension takes hold
            sleep(0.002)
        for _ in range(5):
            sleep(0.002)
            ticks.append(1)
        return len(ticks)

    def controller() -> tuple[int, int]:
        while not ticks:
            sleep(0.002)
        task = tagged("worker")
        task.suspend()
        suspended.set()
        before = len(ticks)
        sleep(0.1)
        during = len(ticks)
        task.resume()
        return before, during

    runner = top_level(name="plan")
    with runner:
        result = with_tags(worker=worker, controller=controller)
    assert result["worker"] == 6
    assert result["controller"] == (1, 1)  # the worker made no progress while suspended
    assert runner.tree.find_tag("worker")[0].status is TaskStatus.SUCCEEDED


def test_tagged_unknown_name_suggests_the_close_one() -> None:
    def controller() -> None:
        sleep(0.01)
        tagged("wroker")

    with pytest.raises(LookupError, match="did you mean 'worker'"):
        run_top_level(lambda: with_tags(worker=lambda: sleep(0.05), controller=controller))


@pytest.mark.parametrize("form", [seq, par, pursue, try_all, try_in_order])
def test_plan_forms_outside_top_level_raise(form: object) -> None:
    with pytest.raises(NotInTopLevel, match="top_level"):
        form(lambda: 1)  # type: ignore[operator]


def test_non_callable_step_is_named() -> None:
    with pytest.raises(TypeError, match="par step 1 is 42"):
        run_top_level(lambda: par(lambda: 1, 42))  # type: ignore[arg-type]


def test_children_see_their_own_task() -> None:
    paths = run_top_level(
        lambda: par(("x", lambda: current_task().path), ("y", lambda: current_task().path)),  # type: ignore[union-attr]
        name="plan",
    )
    assert paths == ["plan/par/x", "plan/par/y"]


def test_stopping_the_top_level_from_outside_evaporates_everything() -> None:
    runner = top_level(name="plan")
    timer = threading.Timer(0.05, lambda: runner.stop())
    timer.start()
    with pytest.raises(TaskStopped):
        runner.run(lambda: par(lambda: sleep(5.0), lambda: sleep(5.0)))
    timer.join()
    assert all(t.status is TaskStatus.EVAPORATED for t in runner.tree.tasks())
