"""Task listeners: observers see every start, finish and PERFORM, also in par's threads."""

from __future__ import annotations

import threading
from typing import Any

import pytest

from robocram.designators import a, install_common_motions
from robocram.execution import (
    Task,
    TaskListener,
    listening,
    par,
    perform,
    run_top_level,
    seq,
    task_listeners,
)
from robocram.execution.failures import TorsoGoalNotReached
from robocram.execution.process_module import ProcessModule
from robocram.execution.process_module_matching import (
    install_process_module_interface,
    process_modules_running,
)
from robocram.logic import KnowledgeBase, Term, using_kb


class Log(TaskListener):
    def __init__(self) -> None:
        self.events: list[tuple[str, str, str]] = []
        self.lock = threading.Lock()

    def task_started(self, task: Task) -> None:
        with self.lock:
            self.events.append(("start", task.path, task.status.value))

    def task_finished(self, task: Task) -> None:
        with self.lock:
            self.events.append(("end", task.path, task.status.value))

    def performing(self, task: Task, designator: Any) -> None:
        with self.lock:
            self.events.append(("perform", task.path, designator.type))


class TorsoPM(ProcessModule):
    name = "torso"

    def execute(self, command: Term) -> Any:
        (angle,) = command.args
        if angle > 0.3:
            raise TorsoGoalNotReached(goal=angle, reached=0.3)
        return angle


def test_listener_sees_tasks_in_threads_in_order() -> None:
    log = Log()
    with listening(log):
        run_top_level(lambda: par(("a", lambda: 1), ("b", lambda: 2)), name="plan")
    assert log.events[0] == ("start", "plan", "running")
    assert log.events[-1] == ("end", "plan", "succeeded")
    for child in ("plan/par/a", "plan/par/b"):
        start = log.events.index(("start", child, "running"))
        assert log.events.index(("end", child, "succeeded")) > start
    assert len(log.events) == 8  # plan, par, a, b: each started and finished once


def test_listener_sees_perform_and_failure() -> None:
    kb = install_common_motions(KnowledgeBase())
    install_process_module_interface(kb)
    kb.consult(
        "matching_process_module(D, torso) :- desig_prop(D, type, 'moving-torso').\n"
        "available_process_module(torso).\n",
        group="torso",
    )
    log = Log()

    def plan() -> None:
        seq(lambda: perform(a.motion(type="moving-torso", joint_angle=0.5)))

    running = process_modules_running(TorsoPM())
    with using_kb(kb), running, listening(log), pytest.raises(TorsoGoalNotReached):
        run_top_level(plan, name="plan")
    performs = [e for e in log.events if e[0] == "perform"]
    assert performs == [("perform", "plan/seq/seq[0]/perform moving-torso", "moving-torso")]
    assert ("end", "plan/seq/seq[0]/perform moving-torso", "failed") in log.events


def test_listeners_are_scoped_to_the_block() -> None:
    log = Log()
    with listening(log):
        assert task_listeners() == (log,)
    assert task_listeners() == ()
    run_top_level(lambda: 1)
    assert log.events == []


def test_listening_rejects_non_listeners() -> None:
    with pytest.raises(TypeError, match="TaskListener"):
        listening(object()).__enter__()  # type: ignore[arg-type]
