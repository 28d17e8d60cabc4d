"""``try_all`` and ``try_in_order``: alternatives, the first success wins.

Only plan failures count as a failed alternative; any other exception is a bug and
propagates at once. When every alternative fails, a CompositeFailure lists the reasons
in step order.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from robocram.execution.child_group import ChildGroup, Step, named_steps
from robocram.execution.errors import ExecutionArgumentError
from robocram.execution.failures import CompositeFailure, PlanFailure
from robocram.execution.par import raise_failure_of
from robocram.execution.seq import run_step
from robocram.execution.task import Task, TaskStatus
from robocram.execution.task_context import require_task, sub_task


def try_in_order(*steps: Step, name: str = "try_in_order") -> Any:
    """Run ``steps`` one by one until one succeeds; return its value."""
    require_task("try_in_order")
    named = _alternatives("try_in_order", steps)
    failures: list[PlanFailure] = []
    with sub_task(name) as node:
        for step_name, fn in named:
            try:
                node.result = run_step(step_name, fn)
            except PlanFailure as failure:
                failures.append(failure)
            else:
                return node.result
        raise CompositeFailure(form=name, failures=failures) from failures[-1]


def try_all(*steps: Step, name: str = "try_all") -> Any:
    """Run ``steps`` in threads; the first success wins and the rest are stopped."""
    require_task("try_all")
    named = _alternatives("try_all", steps)
    winner: Task | None = None
    with sub_task(name) as node:
        with ChildGroup(node, named) as group:
            for child in group.finished():
                if child.status is TaskStatus.SUCCEEDED or _is_bug(child):
                    winner = child
                    group.stop_all()
                    break
        node.check_stop()
        if winner is not None:
            if winner.status is TaskStatus.FAILED:
                raise_failure_of(winner)
            node.result = winner.result
            return node.result
        failures = [t.failure for t in group.tasks if isinstance(t.failure, PlanFailure)]
        if failures:
            raise CompositeFailure(form=name, failures=failures) from failures[-1]
    return None


def _is_bug(task: Task) -> bool:
    return task.status is TaskStatus.FAILED and not isinstance(task.failure, PlanFailure)


def _alternatives(form: str, steps: tuple[Step, ...]) -> list[tuple[str, Callable[[], Any]]]:
    if not steps:
        raise ExecutionArgumentError(f"{form} needs at least one alternative; got none")
    return named_steps(form, steps)
