"""``whenever``: run a body each time a fluent changes or pulses to a true value."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NoReturn

from robocram.execution.fluent import Fluent
from robocram.execution.task_context import checkpoint, require_task


def whenever(
    fluent: Fluent, body: Callable[[], Any], predicate: Callable[[Any], Any] | None = None
) -> NoReturn:
    """Run ``body`` now if the fluent holds, then after each change or pulse that holds.

    Updates that arrive while ``body`` runs are coalesced into one more run. The loop
    ends only when its task is stopped (e.g. as the loser of a ``pursue``), so it needs
    a top level.
    """
    require_task("whenever")
    test = predicate or bool
    seen = -1
    while True:
        value, seen = fluent.wait_for_update(seen)
        if test(value):
            body()
        checkpoint()
