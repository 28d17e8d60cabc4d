"""``pursue``: run steps in parallel; the first to finish decides, the rest are stopped."""

from __future__ import annotations

from typing import Any

from robocram.execution.child_group import ChildGroup, Step, named_steps
from robocram.execution.par import raise_failure_of
from robocram.execution.task import Task, TaskStatus
from robocram.execution.task_context import require_task, sub_task


def pursue(*steps: Step, name: str = "pursue") -> Any:
    """Run ``steps`` in threads; return the first finisher's value or raise its failure.

    The others are stopped (they evaporate) and joined before this returns. Children
    stopped from outside do not count as finishing; if all are, the value is None.
    """
    require_task("pursue")
    named = named_steps("pursue", steps)
    winner: Task | None = None
    with sub_task(name) as node:
        with ChildGroup(node, named) as group:
            for child in group.finished():
                if child.status is not TaskStatus.EVAPORATED:
                    winner = child
                    group.stop_all()
                    break
        node.check_stop()
        if winner is not None and winner.status is TaskStatus.FAILED:
            raise_failure_of(winner)
        node.result = None if winner is None else winner.result
    return node.result
