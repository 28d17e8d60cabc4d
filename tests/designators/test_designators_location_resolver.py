"""Location resolution: priorities, verdicts, the rejection cap, laziness and scoping."""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from typing import Any

import pytest

from robocram.designators import (
    LocationResolver,
    Verdict,
    a,
    current_location_resolver,
    scoped_location_generator,
    scoped_location_validator,
    using_location_resolver,
)


def counting(start: int) -> Any:
    def generate(designator: Any) -> Iterator[int]:
        yield from itertools.count(start)

    return generate


def test_generators_run_in_priority_order_lower_first() -> None:
    resolver = (
        LocationResolver(generators=())
        .with_generator("late", lambda d: ["late"], priority=20)
        .with_generator("early", lambda d: ["early1", "early2"], priority=5)
    )
    assert list(resolver.solutions(a.location())) == ["early1", "early2", "late"]


def test_verdicts_accept_unknown_maybe_reject_and_reject() -> None:
    def odd_accept(d: Any, c: int) -> Verdict:
        return Verdict.ACCEPT if c % 2 else Verdict.UNKNOWN

    def small_maybe(d: Any, c: int) -> Verdict:
        return Verdict.MAYBE_REJECT if c < 4 else Verdict.UNKNOWN

    def no_seven(d: Any, c: int) -> Verdict:
        return Verdict.REJECT if c == 7 else Verdict.UNKNOWN

    resolver = (
        LocationResolver(generators=())
        .with_generator("numbers", lambda d: range(10))
        .with_validator("odd", odd_accept)
        .with_validator("small", small_maybe)
        .with_validator("seven", no_seven)
    )
    # 0, 2: maybe-rejected, nobody accepts; 1, 3: accepted despite maybe; 7: rejected
    assert list(resolver.solutions(a.location())) == [1, 3, 4, 5, 6, 8, 9]


def test_stream_ends_after_the_cap_of_consecutive_rejections() -> None:
    seen: list[int] = []

    def reject_even(d: Any, c: int) -> Verdict:
        seen.append(c)
        return Verdict.REJECT if c >= 3 else Verdict.ACCEPT

    resolver = LocationResolver(generators=(), max_consecutive_rejections=30)
    resolver = resolver.with_generator("n", counting(0)).with_validator("v", reject_even)
    assert list(resolver.solutions(a.location())) == [0, 1, 2]
    assert len(seen) == 3 + 30
    five = LocationResolver(generators=(), max_consecutive_rejections=5)
    five = five.with_generator("n", counting(0)).with_validator("v", reject_even)
    assert len(list(five.solutions(a.location()))) == 3


def test_solutions_are_lazy_and_cached_per_designator() -> None:
    pulled: list[int] = []

    def generate(d: Any) -> Iterator[int]:
        for i in itertools.count():
            pulled.append(i)
            yield i

    resolver = LocationResolver(generators=()).with_generator("n", generate)
    loc = a.location(near="sink")
    assert loc.reference(resolver=resolver) == 0 and pulled == [0]
    nxt = loc.next_solution(resolver=resolver)
    assert nxt is not None and nxt.reference(resolver=resolver) == 1
    assert loc.reference(resolver=resolver) == 0 and pulled == [0, 1]


def test_removal_and_replacement_by_name() -> None:
    resolver = (
        LocationResolver().with_generator("g", lambda d: [1]).with_generator("g", lambda d: [2])
    )
    assert [g.name for g in resolver.generators] == ["pose_property", "g"]
    assert list(resolver.solutions(a.location())) == [2]
    assert list(resolver.without_generator("g").solutions(a.location())) == []
    with pytest.raises(KeyError, match="no location validator named 'v'; registered: \\[\\]"):
        resolver.without_validator("v")


def test_scoped_generators_and_validators_end_with_their_block() -> None:
    with using_location_resolver(LocationResolver()):
        with scoped_location_generator("ten", lambda d: [10, 11]):
            with scoped_location_validator(
                "no_ten", lambda d, c: Verdict("reject" if c == 10 else "unknown")
            ):
                assert a.location().reference() == 11
            assert a.location().reference() == 10
        assert [g.name for g in current_location_resolver().generators] == ["pose_property"]


def test_a_validator_must_answer_a_verdict() -> None:
    resolver = LocationResolver().with_validator("sloppy", lambda d, c: True)
    with pytest.raises(Exception, match="'sloppy' returned True; it must return a Verdict"):
        a.location(pose=(0, 0, 0)).reference(resolver=resolver)
