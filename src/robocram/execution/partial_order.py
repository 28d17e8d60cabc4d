"""``partial_order``: run named steps in parallel, each waiting for the steps it must follow."""

from __future__ import annotations

import difflib
import threading
from collections.abc import Callable, Iterable, Mapping

from robocram.execution.child_group import ChildGroup
from robocram.execution.errors import ExecutionArgumentError
from robocram.execution.par import raise_failure_of
from robocram.execution.task import TaskStatus
from robocram.execution.task_context import require_task, sub_task, wait_until


def partial_order(
    steps: Mapping[str, Callable[[], object]],
    orderings: Iterable[tuple[str, str]] = (),
    *,
    name: str = "partial_order",
) -> dict[str, object]:
    """Run ``steps`` so that for each ``(before, after)`` pair ``after`` starts once
    ``before`` has succeeded; return each step's value by name.

    As in ``par``, the first failure stops the others (waiting steps evaporate).
    """
    require_task("partial_order")
    before = _predecessors(steps, orderings)
    succeeded: set[str] = set()
    cond = threading.Condition()

    def gated(step: str, fn: Callable[[], object]) -> Callable[[], object]:
        def run() -> object:
            wait_until(cond, lambda: before[step] <= succeeded)
            result = fn()
            with cond:
                succeeded.add(step)
                cond.notify_all()
            return result

        return run

    with sub_task(name) as node:
        with ChildGroup(node, [(s, gated(s, fn)) for s, fn in steps.items()]) as group:
            for child in group.finished():
                if child.status is TaskStatus.FAILED:
                    group.stop_all()
                    raise_failure_of(child)
        node.check_stop()
        node.result = {task.name: task.result for task in group.tasks}
    return node.result


def _predecessors(
    steps: Mapping[str, Callable[[], object]], orderings: Iterable[tuple[str, str]]
) -> dict[str, set[str]]:
    before: dict[str, set[str]] = {step: set() for step in steps}
    for pair in orderings:
        if len(pair) != 2:
            raise ExecutionArgumentError(
                f"ordering {pair!r} must be a (before, after) pair of step names"
            )
        for step in pair:
            if step not in steps:
                close = difflib.get_close_matches(step, list(steps), n=1)
                guess = f"; did you mean {close[0]!r}?" if close else ""
                raise ExecutionArgumentError(
                    f"ordering {pair!r} names unknown step {step!r}{guess}"
                )
        before[pair[1]].add(pair[0])
    _reject_cycles(before)
    return before


def _reject_cycles(before: dict[str, set[str]]) -> None:
    placed: set[str] = set()
    while len(placed) < len(before):
        ready = {s for s, deps in before.items() if s not in placed and deps <= placed}
        if not ready:
            stuck = sorted(set(before) - placed)
            raise ExecutionArgumentError(
                f"orderings form a cycle among steps {stuck}; remove one pair"
            )
        placed |= ready
