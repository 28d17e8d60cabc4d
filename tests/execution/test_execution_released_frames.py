"""A task tree keeps its failures, but not everything their frames held.

Each failure's traceback holds every frame it passed through, with their locals; a long
activity recovers from hundreds of failures, and kept whole they held every failed
motion's collision scene (a drafted Stretch's clearing grew past 20 GB). The tree's latest
:data:`WHOLE_FAILURES` stay whole for a debugger's post-mortem; older ones lose their
frames' locals and keep their tracebacks' text. Judged by weak references to what the
frames held, not by the code that releases them.
"""

from __future__ import annotations

import gc
import traceback
import weakref
from collections.abc import Iterator

from robocram.execution import TopLevel, run_top_level
from robocram.execution.failures import PlanFailure
from robocram.execution.task import WHOLE_FAILURES
from robocram.execution.task_context import sub_task


class Heavy:
    """Stands in for a collision scene: something only a frame's locals hold."""


def _fails(held: list[weakref.ref[Heavy]], k: int) -> None:
    heavy = Heavy()
    held.append(weakref.ref(heavy))
    raise PlanFailure(f"try {k} failed")


def _alive(held: list[weakref.ref[Heavy]]) -> list[bool]:
    gc.collect()
    return [ref() is not None for ref in held]


def test_only_the_latest_failures_keep_what_their_frames_held() -> None:
    held: list[weakref.ref[Heavy]] = []

    def plan() -> list[PlanFailure]:
        caught = []
        for k in range(10):
            try:
                with sub_task(f"try {k}"):
                    _fails(held, k)
            except PlanFailure as failure:
                caught.append(failure)  # a plan keeps its causes, as fetch and pick do
        return caught

    top = TopLevel("trying")
    caught = top.run(plan)
    assert _alive(held) == [False] * (10 - WHOLE_FAILURES) + [True] * WHOLE_FAILURES
    # every failure is still in the tree, and still says where it came from
    failed = [t.failure for t in top.tree.root.children]
    assert failed == caught
    text = "".join(traceback.format_exception(caught[0]))
    assert "_fails" in text and "try 0 failed" in text
    assert "raise PlanFailure" in text


class EveryTryFailed(PlanFailure):
    causes: list[PlanFailure] | None = None


def test_a_failure_a_plan_wraps_lets_go_of_its_causes_frames() -> None:
    held: list[weakref.ref[Heavy]] = []

    def tries() -> None:
        causes = []
        for k in range(3):
            try:
                _fails(held, k)  # no task of its own: only the wrapping failure is kept
            except PlanFailure as failure:
                causes.append(failure)
        raise EveryTryFailed("every try failed", causes=causes)

    def activity() -> None:
        for k in range(WHOLE_FAILURES + 1):
            try:
                with sub_task(f"step {k}"):
                    if k == 0:
                        tries()
                    raise PlanFailure(f"step {k} failed")
            except PlanFailure:
                pass

    run_top_level(activity)
    assert _alive(held) == [False, False, False]


def test_a_generator_that_kept_a_failure_still_runs_to_its_end() -> None:
    """Clearing a suspended generator's frame would close it: its frames are left alone."""
    held: list[weakref.ref[Heavy]] = []

    def stands() -> Iterator[int]:
        for k in range(WHOLE_FAILURES + 3):
            try:
                with sub_task(f"stand {k}"):
                    _fails(held, k)
            except PlanFailure:
                pass
            yield k

    def plan() -> list[int]:
        return list(stands())

    assert run_top_level(plan) == list(range(WHOLE_FAILURES + 3))
    assert _alive(held)[:3] == [False, False, False]
