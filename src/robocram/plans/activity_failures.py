"""The failure of an everyday activity: what it finished, what it could not, and why."""

from __future__ import annotations

from robocram.execution.failures import HighLevelFailure


class ActivityIncomplete(HighLevelFailure):
    """An activity (setting or clearing a table) ended with things left undone.

    Everything it could do is done, and every container it opened is closed again, before
    this is raised; ``causes`` holds the failure of each thing left, in order (an item
    not found anywhere is a ``SearchExhausted``).
    """

    activity: str | None = None  # the action type, e.g. "setting-table"
    done: tuple[str, ...] | None = None  # the objects it put where they belong
    missing: tuple[str, ...] | None = None  # what is not where it belongs (types or names)
    causes: tuple[Exception, ...] | None = None  # one failure per thing missing
    hint = "put the missing things where the KB says they are kept, or fix the causes listed"
