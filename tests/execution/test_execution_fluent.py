"""Fluents: waits with timeouts, derived fluents, pulses and whenever loops."""

from __future__ import annotations

import gc
import threading
import time
from typing import TypeVar

import pytest

from robocram.execution import (
    Fluent,
    TaskStatus,
    fl_and,
    fl_not,
    fl_or,
    pursue,
    sleep,
    top_level,
    whenever,
)
from robocram.execution.failures import FluentWaitTimeout, NotInTopLevel

T = TypeVar("T")


def after(seconds: float, value: T) -> T:
    """Sleep (a stop point), then give ``value``."""
    sleep(seconds)
    return value


def set_later(fluent: Fluent, value: object, delay: float) -> threading.Timer:
    timer = threading.Timer(delay, lambda: fluent.set(value))
    timer.start()
    return timer


def test_get_set_and_value_property() -> None:
    fl = Fluent(1, name="count")
    fl.value = 5
    assert fl.get() == 5
    fl.set(6)
    assert fl.value == 6
    assert repr(fl) == "Fluent('count', 6)"


def test_wait_for_returns_the_value_once_it_holds() -> None:
    fl = Fluent(0, name="battery")
    timer = set_later(fl, 80, 0.02)
    assert fl.wait_for(lambda v: v > 50, timeout=1.0) == 80
    timer.join()


def test_wait_for_times_out_with_a_typed_failure() -> None:
    fl = Fluent(False, name="door-open")
    started = time.monotonic()
    with pytest.raises(FluentWaitTimeout) as caught:
        fl.wait_for(timeout=0.05)
    assert time.monotonic() - started >= 0.04  # waited its timeout (a load only adds to it)
    assert caught.value.fluent == "door-open"
    assert caught.value.value is False


def test_comparison_and_arithmetic_fluents_follow_their_sources() -> None:
    x, y = Fluent(1, name="x"), Fluent(2, name="y")
    total = x + y
    below = total < 10
    scaled = 2 * x - 1
    assert (total.get(), below.get(), scaled.get()) == (3, True, 1)
    x.set(9)
    assert (total.get(), below.get(), scaled.get()) == (11, False, 17)
    assert total.name == "(x + y)"


def test_eq_and_logic_combinators() -> None:
    mode = Fluent("idle", name="mode")
    ready = Fluent(False, name="ready")
    go = fl_and(mode.eq("active"), ready)
    either = fl_or(mode.eq("active"), ready)
    idle = fl_not(mode.ne("idle"))
    assert (go.get(), either.get(), idle.get()) == (False, False, True)
    mode.set("active")
    assert (go.get(), either.get(), idle.get()) == (False, True, False)
    ready.set(True)
    assert go.get() is True


def test_waiting_on_a_derived_fluent() -> None:
    distance = Fluent(5.0, name="distance")
    arrived = distance < 0.1
    timers = [set_later(distance, d, 0.01 * (i + 1)) for i, d in enumerate([2.0, 0.5, 0.05])]
    assert arrived.wait_for(timeout=1.0) is True
    assert distance.get() == pytest.approx(0.05)
    for timer in timers:
        timer.join()


def test_fluents_refuse_truth_tests_and_derived_refuse_set() -> None:
    fl = Fluent(3, name="n")
    with pytest.raises(TypeError, match="use .get"):
        bool(fl < 5)
    with pytest.raises(TypeError, match="derived"):
        (fl < 5).set(True)
    assert fl in {fl}  # identity equality keeps fluents usable as keys


def test_pulse_wakes_update_waiters_without_a_change() -> None:
    fl = Fluent(1, name="tick")
    start = fl.generation
    timer = threading.Timer(0.02, fl.pulse)
    timer.start()
    value, generation = fl.wait_for_update(start, timeout=1.0)
    timer.join()
    assert (value, generation) == (1, start + 1)
    fl.set(1)  # no change: no new generation
    assert fl.generation == start + 1


def test_whenever_runs_on_each_true_update_until_stopped() -> None:
    trigger = Fluent(False, name="trigger")
    runs: list[object] = []

    def driver() -> None:
        for value in [True, False, True, True]:
            sleep(0.02)
            trigger.set(value)
        sleep(0.02)
        trigger.pulse()
        sleep(0.03)

    runner = top_level(name="plan")
    with runner:
        pursue(("loop", lambda: whenever(trigger, lambda: runs.append(trigger.get()))), driver)
    # True, (False skipped), True, (True is no change), pulse while True
    assert runs == [True, True, True]
    loop = runner.tree.find("plan/pursue/loop")
    assert loop.status is TaskStatus.EVAPORATED


def test_fluent_waits_are_stop_points() -> None:
    never = Fluent(False, name="never")
    runner = top_level(name="plan")
    with runner:
        result = pursue(("wait", lambda: never.wait_for()), lambda: after(0.02, "done"))
    assert result == "done"  # a wait that ignored the stop would never return
    assert runner.tree.find("plan/pursue/wait").status is TaskStatus.EVAPORATED


def test_whenever_outside_a_top_level_raises() -> None:
    with pytest.raises(NotInTopLevel):
        whenever(Fluent(True), lambda: None)


def test_concurrent_setters_leave_derived_fluents_consistent() -> None:
    sources = [Fluent(0, name=f"s{i}") for i in range(4)]
    total = sources[0] + sources[1] + sources[2] + sources[3]

    def bump(fl: Fluent) -> None:
        for i in range(1, 201):
            fl.set(i)

    threads = [threading.Thread(target=bump, args=(fl,)) for fl in sources]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert total.get() == 800


def test_pulse_reaches_derived_fluents_and_set_during_pulse_is_kept() -> None:
    level = Fluent(3, name="level")
    high = level > 2
    start = high.generation
    level.pulse()
    assert high.generation == start + 1 and high.get() is True
    level.set(1)
    level.pulse()
    assert (level.get(), high.get()) == (1, False)


def test_collected_derived_fluents_are_dropped() -> None:
    source = Fluent(0, name="src")
    for _ in range(100):
        source < 1  # noqa: B015 - built and dropped on purpose
    gc.collect()
    keep = source + 1
    assert len(source._dependents) == 1
    source.set(4)
    assert keep.get() == 5
