"""Tags: name tasks so that other parts of the plan can find, suspend or stop them."""

from __future__ import annotations

import difflib
from collections.abc import Callable

from robocram.execution.par import par
from robocram.execution.task import Task
from robocram.execution.task_context import require_task, sub_task


def tag(name: str, fn: Callable[[], object]) -> Callable[[], object]:
    """Wrap ``fn`` so that it runs as a child task named and tagged ``name``."""

    def tagged_step() -> object:
        with sub_task(name, frozenset({name})) as task:
            task.result = fn()
        return task.result

    tagged_step.__name__ = f"tag_{name}" if name.isidentifier() else "tagged_step"
    return tagged_step


def with_tags(name: str = "with_tags", **named_fns: Callable[[], object]) -> dict[str, object]:
    """Run the keyword thunks in parallel, each tagged by its keyword; return values by tag.

    A step can reach a sibling with ``tagged("other")`` to suspend, resume or stop it.
    """
    require_task("with_tags")
    names = list(named_fns)
    results = par(*[(n, tag(n, fn)) for n, fn in named_fns.items()], name=name)
    return dict(zip(names, results, strict=True))


def tagged(name: str) -> Task:
    """Return the latest task tagged ``name`` in the current top level."""
    root = require_task(f"tagged({name!r})").root
    found = [t for t in root.descendants() if name in t.tags]
    if found:
        return found[-1]
    known = sorted({t for task in root.descendants() for t in task.tags})
    close = difflib.get_close_matches(name, known, n=1)
    guess = f"; did you mean {close[0]!r}?" if close else f"; known tags: {known}"
    raise LookupError(f"no task tagged {name!r} in this top level{guess}")
