"""Location resolution: generators propose candidate poses, validators judge them.

Generators run in priority order (lower value first, as in CRAM) and their candidates
are concatenated lazily. Each candidate is shown to every validator, which answers a
:class:`Verdict`. A candidate is taken if no validator rejects it and either one accepts
or all are unknown; ``maybe_reject`` rejects unless another validator accepts. After
``max_consecutive_rejections`` rejections in a row (CRAM's 30) the stream ends.

A resolver is an immutable value: ``with_generator``/``without_generator`` return new
ones. The current resolver is bound per context with :func:`using_location_resolver`;
:func:`scoped_location_generator` and :func:`scoped_location_validator` add one for a block.
"""

from __future__ import annotations

import contextvars
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace
from enum import Enum
from typing import Any, TypeVar

from robocram.designators.errors import (
    DesignatorArgumentError,
    DesignatorUnknownKey,
    DesignatorUsageError,
)

GeneratorFunction = Callable[[Any], Iterable[object]]
ValidatorFunction = Callable[[Any, Any], "Verdict"]
_Item = TypeVar("_Item", "LocationGenerator", "LocationValidator")


class Verdict(Enum):
    """A validator's answer about one candidate solution."""

    ACCEPT = "accept"
    MAYBE_REJECT = "maybe-reject"
    UNKNOWN = "unknown"
    REJECT = "reject"


@dataclass(frozen=True)
class LocationGenerator:
    """A named function ``designator -> iterable of candidates`` with a priority."""

    name: str
    function: GeneratorFunction
    priority: int = 0


@dataclass(frozen=True)
class LocationValidator:
    """A named function ``(designator, candidate) -> Verdict`` with a priority."""

    name: str
    function: ValidatorFunction
    priority: int = 0


def pose_property_generator(designator: Any) -> Iterator[Any]:
    """Yield the values of the designator's ``pose`` properties (``(a location (pose ?p))``)."""
    yield from designator.get_all("pose")


def combine_verdicts(verdicts: Iterable[Verdict]) -> bool:
    """Return whether a candidate with these verdicts is taken.

    >>> combine_verdicts([Verdict.UNKNOWN, Verdict.ACCEPT])
    True
    >>> combine_verdicts([Verdict.ACCEPT, Verdict.MAYBE_REJECT]), combine_verdicts([])
    (True, True)
    >>> combine_verdicts([Verdict.MAYBE_REJECT]), combine_verdicts([Verdict.ACCEPT, Verdict.REJECT])
    (False, False)
    """
    seen = set(verdicts)
    if Verdict.REJECT in seen:
        return False
    return Verdict.ACCEPT in seen or Verdict.MAYBE_REJECT not in seen


@dataclass(frozen=True)
class LocationResolver:
    """Generators and validators that turn location designators into lazy pose streams."""

    generators: tuple[LocationGenerator, ...] = (
        LocationGenerator("pose_property", pose_property_generator, priority=0),
    )
    validators: tuple[LocationValidator, ...] = ()
    max_consecutive_rejections: int = 30

    def __post_init__(self) -> None:
        if self.max_consecutive_rejections < 1:
            raise DesignatorArgumentError(
                f"max_consecutive_rejections must be >= 1, got {self.max_consecutive_rejections}"
            )
        for items, what in ((self.generators, "generator"), (self.validators, "validator")):
            names = [item.name for item in items]
            duplicates = sorted({n for n in names if names.count(n) > 1})
            if duplicates:
                raise DesignatorArgumentError(
                    f"location {what} names must be unique, repeated: {duplicates}"
                )
        object.__setattr__(self, "generators", _by_priority(self.generators))
        object.__setattr__(self, "validators", _by_priority(self.validators))

    def with_generator(
        self, name: str, function: GeneratorFunction, priority: int = 0
    ) -> LocationResolver:
        """Return a resolver that also (or instead, same name) runs this generator."""
        kept = tuple(g for g in self.generators if g.name != name)
        return replace(self, generators=(*kept, LocationGenerator(name, function, priority)))

    def with_validator(
        self, name: str, function: ValidatorFunction, priority: int = 0
    ) -> LocationResolver:
        """Return a resolver that also (or instead, same name) runs this validator."""
        kept = tuple(v for v in self.validators if v.name != name)
        return replace(self, validators=(*kept, LocationValidator(name, function, priority)))

    def without_generator(self, name: str) -> LocationResolver:
        """Return a resolver without generator ``name``."""
        _require(name, [g.name for g in self.generators], "generator")
        return replace(self, generators=tuple(g for g in self.generators if g.name != name))

    def without_validator(self, name: str) -> LocationResolver:
        """Return a resolver without validator ``name``."""
        _require(name, [v.name for v in self.validators], "validator")
        return replace(self, validators=tuple(v for v in self.validators if v.name != name))

    def solutions(self, designator: object) -> Iterator[object]:
        """Yield the accepted candidates for ``designator`` lazily."""
        rejections = 0
        for candidate in self._candidates(designator):
            verdicts = [v.function(designator, candidate) for v in self.validators]
            for validator, verdict in zip(self.validators, verdicts, strict=True):
                if not isinstance(verdict, Verdict):
                    raise DesignatorUsageError(
                        f"location validator {validator.name!r} returned {verdict!r}; "
                        "it must return a Verdict (ACCEPT, MAYBE_REJECT, UNKNOWN or REJECT)"
                    )
            if combine_verdicts(verdicts):
                rejections = 0
                yield candidate
                continue
            rejections += 1
            if rejections >= self.max_consecutive_rejections:
                return

    def _candidates(self, designator: object) -> Iterator[object]:
        for generator in self.generators:
            yield from generator.function(designator)


def _by_priority(items: tuple[_Item, ...]) -> tuple[_Item, ...]:
    return tuple(sorted(items, key=lambda item: item.priority))


def _require(name: str, names: list[str], what: str) -> None:
    if name not in names:
        raise DesignatorUnknownKey(f"no location {what} named {name!r}; registered: {names}")


_CURRENT_RESOLVER: contextvars.ContextVar[LocationResolver | None] = contextvars.ContextVar(
    "robocram_location_resolver", default=None
)


def current_location_resolver() -> LocationResolver:
    """Return the resolver bound in this context, or a default one (pose properties only)."""
    return _CURRENT_RESOLVER.get() or LocationResolver()


@contextmanager
def using_location_resolver(resolver: LocationResolver) -> Iterator[LocationResolver]:
    """Bind ``resolver`` as the current location resolver for the block."""
    token = _CURRENT_RESOLVER.set(resolver)
    try:
        yield resolver
    finally:
        _CURRENT_RESOLVER.reset(token)


@contextmanager
def scoped_location_generator(
    name: str, function: GeneratorFunction, priority: int = 0
) -> Iterator[LocationResolver]:
    """Add a generator to the current resolver for the block only."""
    resolver = current_location_resolver().with_generator(name, function, priority)
    with using_location_resolver(resolver):
        yield resolver


@contextmanager
def scoped_location_validator(
    name: str, function: ValidatorFunction, priority: int = 0
) -> Iterator[LocationResolver]:
    """Add a validator to the current resolver for the block only."""
    resolver = current_location_resolver().with_validator(name, function, priority)
    with using_location_resolver(resolver):
        yield resolver
