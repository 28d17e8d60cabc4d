"""A task tree as text: folded for reading, or every task in full (``verbose``).

A plan that works often fails on the way: a stand where the robot would collide gives way
to the next one. Unfolded, those tries bury the tree in long failure texts. Folded, a failed
try the plan recovered from is one short line without its subtree (:func:`failure_line`),
and tries of the same kind under one parent (same task, same failure line) are one line
with a count, where the first of them was: ``✗ perform going ×12: NavigationPoseUnreachable:
pr2 at (…) would collide with ['kitchen/table_top']``. A failure that was not recovered
keeps its subtree, on short lines. Traces keep the full texts; this is only their display.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

from robocram.execution.failures.failure_line import failure_line
from robocram.execution.task import TaskStatus
from robocram.execution.task_snapshot import STATUS_MARKS, TaskSnapshot

_REPEAT = re.compile(r"#\d+$")  # the number a repeated sibling's name gets: going#3


def tree_text(snapshot: TaskSnapshot, verbose: bool = False) -> str:
    """``snapshot`` and its subtree as unicode text, one line per task or folded group."""
    return "\n".join([snapshot.label(verbose), *_branches(snapshot, "", verbose)])


def recovered(child: TaskSnapshot, parent: TaskSnapshot) -> bool:
    """Whether ``child`` failed and its failure stopped there: handled, or wrapped in another.

    A failure ``parent`` passed on as it was keeps its subtree in view.
    """
    if child.status is not TaskStatus.FAILED:
        return False
    source = parent.failure_source
    return source is None or not (source == child.path or source.startswith(child.path + "/"))


def _branches(parent: TaskSnapshot, indent: str, verbose: bool) -> Iterator[str]:
    entries = list(_entries(parent, verbose))
    for i, (line, child) in enumerate(entries):
        last = i == len(entries) - 1
        yield f"{indent}{'└── ' if last else '├── '}{line}"
        if child is not None:
            yield from _branches(child, indent + ("    " if last else "│   "), verbose)


def _entries(parent: TaskSnapshot, verbose: bool) -> Iterator[tuple[str, TaskSnapshot | None]]:
    """Each child's line and the child to expand below it (None: shown folded)."""
    if verbose:
        yield from ((child.label(verbose=True), child) for child in parent.children)
        return
    groups: dict[tuple[str, str], list[TaskSnapshot]] = {}
    for child in parent.children:
        if recovered(child, parent):
            groups.setdefault(_kind(child), []).append(child)
    for child in parent.children:
        if not recovered(child, parent):
            yield child.label(verbose=False), child
            continue
        group = groups[_kind(child)]
        if group[0] is child:
            yield _folded(group), None


def _kind(child: TaskSnapshot) -> tuple[str, str]:
    return _REPEAT.sub("", child.name), failure_line(child.failure_type, child.failure_message)


def _folded(group: list[TaskSnapshot]) -> str:
    """One line for failed tries of one kind; a single try keeps its own label."""
    if len(group) == 1:
        return group[0].label(verbose=False)
    name, line = _kind(group[0])
    return f"{STATUS_MARKS[TaskStatus.FAILED]} {name} ×{len(group)}: {line}"
