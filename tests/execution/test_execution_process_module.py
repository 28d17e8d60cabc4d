"""Process modules: lifecycle, FIFO serialisation, failure naming, stop and cancellation."""

from __future__ import annotations

import threading
import time
from typing import Any

import pytest

from robocram.execution import PlanFailure, pursue, run_top_level, sleep
from robocram.execution.failures import (
    NavigationGoalNotReached,
    ProcessModuleFailure,
    SetupFailure,
)
from robocram.execution.process_module import ProcessModule


class RecordingPM(ProcessModule):
    """Appends each command to a log; holds the resource for ``hold`` seconds."""

    name = "recorder"

    def __init__(self, hold: float = 0.0) -> None:
        super().__init__()
        self.hold = hold
        self.log: list[Any] = []
        self.overlaps = 0
        self.holds_cut_short = 0  # holds a stop ended before their time
        self._inside = 0
        self.lifecycle: list[str] = []

    def initialise(self) -> None:
        self.lifecycle.append("initialise")

    def terminate(self) -> None:
        self.lifecycle.append("terminate")

    def execute(self, command: Any) -> Any:
        self._inside += 1
        if self._inside > 1:
            self.overlaps += 1
        try:
            if self.hold:
                try:
                    sleep(self.hold)
                except BaseException:
                    self.holds_cut_short += 1
                    raise
            if command == "fail":
                raise NavigationGoalNotReached(target=(1, 2))
            if command == "bug":
                raise ZeroDivisionError("division by zero")
            self.log.append(command)
            return f"done {command}"
        finally:
            self._inside -= 1


def test_lifecycle_hooks_run_in_order_and_calls_return_results() -> None:
    pm = RecordingPM()
    pm.start()
    assert pm.running and pm.call("a") == "done a"
    pm.stop()
    assert not pm.running
    assert pm.lifecycle == ["initialise", "terminate"]
    assert pm.executed == 1


def test_module_without_name_is_refused() -> None:
    class Nameless(ProcessModule):
        def execute(self, command: Any) -> Any:
            return command

    with pytest.raises(TypeError, match="needs a class attribute name"):
        Nameless()


def test_call_on_stopped_module_names_module_and_command() -> None:
    with pytest.raises(ProcessModuleFailure, match="'recorder' is not running.*move"):
        RecordingPM().call("move")


def test_many_callers_are_serialised_none_lost_none_doubled() -> None:
    pm = RecordingPM()
    pm.start()
    threads = [threading.Thread(target=pm.call, args=(i,)) for i in range(64)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(10)
    pm.stop()
    assert sorted(pm.log) == list(range(64))
    assert pm.overlaps == 0 and pm.executed == 64


def test_second_caller_waits_in_arrival_order() -> None:
    pm = RecordingPM(hold=0.05)
    pm.start()
    first = threading.Thread(target=pm.call, args=("first",))
    first.start()
    while not pm.busy:
        time.sleep(0.001)
    second = threading.Thread(target=pm.call, args=("second",))
    second.start()
    while pm.waiting < 1:
        time.sleep(0.001)
    third = threading.Thread(target=pm.call, args=("third",))
    third.start()
    for t in (first, second, third):
        t.join(5)
    pm.stop()
    assert pm.log == ["first", "second", "third"]


def test_plan_failure_keeps_its_type_and_gains_module_and_command() -> None:
    pm = RecordingPM()
    pm.start()
    with pytest.raises(NavigationGoalNotReached) as caught:
        pm.call("fail")
    pm.stop()
    assert caught.value.context == {"process_module": "recorder", "command": "fail"}
    assert caught.value.target == (1, 2)


def test_other_errors_are_wrapped_with_their_cause() -> None:
    pm = RecordingPM()
    pm.start()
    with pytest.raises(ProcessModuleFailure, match="'recorder' failed on bug") as caught:
        pm.call("bug")
    pm.stop()
    assert isinstance(caught.value.__cause__, ZeroDivisionError)
    assert caught.value.module == "recorder" and caught.value.command == "bug"
    assert isinstance(caught.value, PlanFailure)


def test_stop_releases_waiting_callers_with_a_failure() -> None:
    pm = RecordingPM(hold=0.2)
    pm.start()
    errors: list[BaseException] = []

    def call(command: str) -> None:
        try:
            pm.call(command)
        except PlanFailure as failure:
            errors.append(failure)

    threads = [threading.Thread(target=call, args=(c,)) for c in ("busy", "queued")]
    threads[0].start()
    while not pm.busy:
        time.sleep(0.001)
    threads[1].start()
    while pm.waiting < 1:
        time.sleep(0.001)
    pm.stop()
    for t in threads:
        t.join(5)
    assert pm.log == ["busy"]
    assert len(errors) == 1 and "not running" in str(errors[0])
    assert not pm.busy and pm.waiting == 0


def test_cancelled_callers_leave_nothing_running() -> None:
    pm = RecordingPM(hold=5.0)
    pm.start()

    def plan() -> Any:
        return pursue(lambda: sleep(0.1), lambda: pm.call("slow"), lambda: pm.call("queued"))

    run_top_level(plan)
    # the slow command's hold was cut short by the stop, not waited out: right after the
    # plan returns, nothing runs, nothing waits and no command finished
    assert (pm.holds_cut_short, pm.busy, pm.waiting, pm.log) == (1, False, 0, [])
    pm.stop(timeout=1.0)
    assert pm.lifecycle == ["initialise", "terminate"]


class BadName(SetupFailure):
    """A caller's mistake raised inside a module."""


class PickyPM(ProcessModule):
    name = "picky"

    def execute(self, command: Any) -> Any:
        raise BadName(f"no joint {command!r}; did you mean 'torso'?")


def test_a_setup_failure_in_a_module_is_wrapped_naming_module_and_command() -> None:
    pm = PickyPM()
    pm.start()
    try:
        with pytest.raises(ProcessModuleFailure) as info:
            pm.call("torsoo")
    finally:
        pm.stop()
    assert isinstance(info.value.error, BadName)
    assert (info.value.module, info.value.command) == ("picky", "torsoo")
    assert "did you mean 'torso'" in str(info.value)
