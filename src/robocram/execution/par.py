"""``par``: run steps in parallel; all must succeed; the first failure stops the rest."""

from __future__ import annotations

from typing import Any

from robocram.execution.child_group import ChildGroup, Step, named_steps
from robocram.execution.errors import ExecutionStateError
from robocram.execution.task import Task, TaskStatus
from robocram.execution.task_context import require_task, sub_task


def par(*steps: Step, name: str = "par") -> list[Any]:
    """Run ``steps`` in threads; return their values in step order.

    The first child to fail (in time) stops the others, which evaporate, and its failure
    is raised once they have all finished. A child stopped from outside (e.g. by tag)
    contributes None.
    """
    require_task("par")
    named = named_steps("par", steps)
    with sub_task(name) as node:
        with ChildGroup(node, named) as group:
            for child in group.finished():
                if child.status is TaskStatus.FAILED:
                    group.stop_all()
                    raise_failure_of(child)
        node.check_stop()
        node.result = [task.result for task in group.tasks]
    return node.result


def raise_failure_of(task: Task) -> None:
    """Re-raise the failure recorded on a failed task in the calling thread."""
    if task.failure is None:
        raise ExecutionStateError(f"task {task.path} is {task.status.value}, it has no failure")
    raise task.failure
