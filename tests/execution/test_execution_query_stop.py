"""A looping Prolog query inside a plan ends when the top level is stopped (issue 10)."""

from __future__ import annotations

import threading

from robocram.execution.top_level import TopLevel
from robocram.logic import KnowledgeBase


def test_top_level_stop_ends_a_looping_grounding_rule() -> None:
    kb = KnowledgeBase()
    kb.consult("grounding(X) :- grounding(X).")
    top = TopLevel("loop")
    started = threading.Event()
    raised: list[BaseException] = []

    def plan() -> None:
        started.set()
        kb.holds("catch(grounding(cup), _, true)")  # loops until stopped

    def run() -> None:
        try:
            top.run(plan)
        except BaseException as err:  # TaskStopped: the plan evaporated
            raised.append(err)

    thread = threading.Thread(target=run)
    thread.start()
    assert started.wait(timeout=30)
    top.stop()
    thread.join(timeout=30)
    assert not thread.is_alive(), "the query ignored the stop request"
    assert [type(e).__name__ for e in raised] == ["TaskStopped"]
