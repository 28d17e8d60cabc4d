"""Long built-ins and slow inferences check the query's limits as they go.

`numlist(1, 3000000, _)` is one inference, and inferences can each take milliseconds:
before, a 0.2 s limit let such work run to its end (27 s; 10 s over with slow
inferences). The tests count the limit checks with a stop hook, so that they prove
the work stopped early without timing the machine.
"""

from __future__ import annotations

import time
from collections.abc import Iterator

import pytest

from robocram.logic import KnowledgeBase, TimeLimitExceeded
from robocram.logic.limits import CHECK_EVERY, checking_stop
from robocram.logic.long_work import CHUNK


class Stop(Exception):
    """Raised by the counting hook once it has been asked often enough."""


@pytest.mark.parametrize(
    "goal",
    [
        "numlist(1, 3000000, _)",
        "length(_, 3000000)",
        "numlist(1, 400000, L), msort(L, _)",
        "numlist(1, 400000, L), sort(0, @>=, L, _)",
        "length(L, 400000), maplist(=(0'a), L), atom_codes(_, L)",
        "findall(X, between(1, 3000000, X), _)",
    ],
)
def test_long_built_ins_ask_the_stop_hook_as_they_go(goal: str) -> None:
    kb = KnowledgeBase()
    calls = [0]

    def hook() -> None:
        calls[0] += 1
        if calls[0] == 3:
            raise Stop

    with checking_stop(hook), pytest.raises(Stop):
        kb.holds(goal)
    assert calls[0] == 3  # stopped at the third check, well inside the one long call


def test_text_built_ins_ask_the_stop_hook_while_they_build_a_list() -> None:
    kb = KnowledgeBase()
    kb.holds("length(L, 400000), maplist(=(0'a), L), atom_codes(A, L), assertz(big(A))")
    calls = [0]

    def hook() -> None:
        calls[0] += 1
        if calls[0] == 3:
            raise Stop

    for goal in ("big(A), atom_chars(A, _)", "big(A), atom_codes(A, _)"):
        calls[0] = 0
        with checking_stop(hook), pytest.raises(Stop):
            kb.holds(goal)


def test_a_time_limit_ends_numlist_long_before_it_could_finish() -> None:
    kb = KnowledgeBase()
    chunks = [0]

    def count() -> None:
        chunks[0] += 1

    with checking_stop(count), pytest.raises(TimeLimitExceeded):
        kb.holds("numlist(1, 30000000, _)", time_limit=0.2)
    assert chunks[0] < 30_000_000 // CHUNK  # it raised before the last chunk


def test_slow_inferences_make_the_clock_read_sooner() -> None:
    kb = KnowledgeBase()
    done = [0]

    def slow(_: object) -> Iterator[tuple[object]]:
        time.sleep(0.002)  # [s] one costly inference
        done[0] += 1
        yield (None,)

    kb.add_predicate("slow", 1, slow)
    kb.consult("spin :- slow(_), spin.")
    with pytest.raises(TimeLimitExceeded):
        kb.holds("spin", time_limit=0.1)
    # Checking every CHECK_EVERY inferences ran CHECK_EVERY slow calls (4 s); the clock
    # is now read about every 5 ms, so 0.1 s holds at most ~50 calls of 2 ms (fewer on a
    # loaded machine, where a 2 ms sleep lasts longer: only the upper bound is the claim).
    assert 0 < done[0] < CHECK_EVERY // 8
