"""Stopping queries: inference and time limits, and the stop hook a task installs."""

from __future__ import annotations

import threading

import pytest

from robocram.logic import InferenceLimitExceeded, KnowledgeBase, TimeLimitExceeded
from robocram.logic.limits import CHECK_EVERY, checking_stop

LOOPS = """
p :- p.
spin(a) :- spin(a).
spin(b).
count(0) :- !.
count(N) :- M is N - 1, count(M).
"""


@pytest.mark.parametrize("goal", ["p", "spin(a)", "repeat, fail", "count(-1)"])
def test_inference_limit_stops_every_kind_of_loop(goal: str) -> None:
    kb = KnowledgeBase()
    kb.consult(LOOPS)
    for _ in range(3):  # warm: procedures and compiled clauses loop inside generated code
        with pytest.raises(InferenceLimitExceeded, match="limit of 20000 inferences"):
            kb.holds(goal, max_inferences=20_000)


def test_inference_limit_leaves_short_queries_alone_and_is_catchable() -> None:
    kb = KnowledgeBase()
    kb.consult(LOOPS)
    assert kb.holds("count(1000)", max_inferences=10 * CHECK_EVERY)
    answer = kb.first("catch(p, error(resource_error(R), _), true)", max_inferences=5000)
    assert answer == {"R": "inferences"}


def test_time_limit_stops_a_loop() -> None:
    kb = KnowledgeBase()
    kb.consult(LOOPS)
    with pytest.raises(TimeLimitExceeded, match="time limit of 0.2 s"):
        kb.holds("p", time_limit=0.2)


def test_bad_limits_are_refused() -> None:
    with pytest.raises(ValueError, match="max_inferences"):
        KnowledgeBase().holds("true", max_inferences=-1)


class Stop(Exception):
    """What a task's checkpoint raises when the task was asked to stop."""


def test_stop_hook_ends_a_looping_query_from_another_thread() -> None:
    kb = KnowledgeBase()
    kb.consult(LOOPS)
    stop = threading.Event()
    outcome: list[BaseException] = []

    def check() -> None:
        if stop.is_set():
            raise Stop("stopped")

    def run() -> None:
        with checking_stop(check):
            try:
                kb.holds("catch(p, _, true)")  # catch/3 must not swallow the stop
            except Stop as err:
                outcome.append(err)

    thread = threading.Thread(target=run)
    thread.start()
    stop.set()
    thread.join(timeout=30)
    assert not thread.is_alive()
    assert len(outcome) == 1 and isinstance(outcome[0], Stop)


def _least_limit(kb: KnowledgeBase, goal: str) -> int:
    """The smallest max_inferences under which `goal` succeeds (a binary search)."""
    lo, hi = 1, 1 << 14  # fails at lo - 1 (none), succeeds at hi
    assert kb.holds(goal, max_inferences=hi)
    while lo < hi:
        mid = (lo + hi) // 2
        try:
            ok = kb.holds(goal, max_inferences=mid)
        except InferenceLimitExceeded:
            ok = False
        if ok:
            hi = mid
        else:
            lo = mid + 1
    return lo


@pytest.mark.parametrize("n", [300, 700, 2100])
def test_every_loop_costs_the_same_inferences_past_the_machines_chunks(n: int) -> None:
    # the machine counts goals in chunks of cached small ints: each iteration costs the
    # same number of inferences wherever the chunks end
    kb = KnowledgeBase()
    kb.consult("a.\np(N) :- between(1, N, _), a, fail.\np(_).\n")
    step = _least_limit(kb, "p(2)") - _least_limit(kb, "p(1)")
    assert step > 0
    assert _least_limit(kb, f"p({n})") == _least_limit(kb, "p(1)") + (n - 1) * step
