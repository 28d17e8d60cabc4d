"""Errors of the predicate table: a query that names no argument, facts a robot lacks.

``KnowledgeError`` is the layer's root; every error names the predicate and what to do.
"""

from __future__ import annotations

from dataclasses import dataclass


class KnowledgeError(Exception):
    """Root of the errors of :mod:`robocram.knowledge`."""


class UnknownArgumentError(KnowledgeError, ValueError):
    """A typed query bound an argument its predicate does not have."""

    def __init__(self, indicator: str, name: str, valid: tuple[str, ...]) -> None:
        super().__init__(f"{indicator} has no argument {name!r}; its arguments: {', '.join(valid)}")
        self.indicator, self.name, self.valid = indicator, name, valid


class ImplementationMismatch(KnowledgeError):
    """Python implementations of a source's predicates differ from the table."""

    def __init__(self, source: str, missing: list[str], unknown: list[str]) -> None:
        parts = []
        if missing:
            parts.append(f"no implementation of {', '.join(missing)}")
        if unknown:
            parts.append(f"{', '.join(unknown)} not in the predicate table (add a row)")
        super().__init__(f"{source} predicates: {'; '.join(parts)}")
        self.source, self.missing, self.unknown = source, missing, unknown


@dataclass(frozen=True)
class MissingFact:
    """One required predicate without a fact for a robot (or one of its arms)."""

    robot: str
    arm: str | None
    indicator: str
    meaning: str

    def __str__(self) -> str:
        whose = f"robot {self.robot!r}" + (f" arm {self.arm!r}" if self.arm else "")
        return f"{whose} has no {self.indicator}: {self.meaning}"


class MissingFactsError(KnowledgeError):
    """A robot's description lacks predicates the table marks required; lists them all."""

    def __init__(self, missing: list[MissingFact]) -> None:
        super().__init__(
            "the robot description misses required facts:\n"
            + "\n".join(f"  - {m}" for m in missing)
        )
        self.missing = tuple(missing)


class KnowledgeUsageError(KnowledgeError, TypeError):
    """A typed predicate was handed the wrong kind of thing: the caller's mistake."""

    summary = "a typed predicate was handed the wrong kind of thing"
    hint = "pass what the message asks for"
