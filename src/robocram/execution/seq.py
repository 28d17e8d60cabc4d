"""``seq``: run steps one after another in the calling thread, each as a child task."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robocram.execution.child_group import Step, named_steps
from robocram.execution.task_context import require_task, sub_task


def seq(*steps: Step, name: str = "seq") -> Any:
    """Run ``steps`` (thunks or ``(name, thunk)``) in order; return the last step's value.

    The first failure stops the sequence and propagates.
    """
    require_task("seq")
    named = named_steps("seq", steps)
    with sub_task(name) as node:
        for step_name, fn in named:
            node.result = run_step(step_name, fn)
    return node.result


def run_step(name: str, fn: Callable[[], Any]) -> Any:
    """Run ``fn`` as a child task of the current task in this thread; return its value."""
    with sub_task(name) as step:
        step.result = fn()
    return step.result
