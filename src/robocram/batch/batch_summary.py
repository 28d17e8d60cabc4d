"""What a batch found, in a few numbers: success rate, failure types, median duration.

Why variants failed is grouped by cause: each cause is one :func:`failure_line` (the failure
type and what went wrong, no designator dump), with the variants it ended. Each variant counts
once, with its final outcome; ``rerun`` says how many of them ran a second time because
their first worker's node was lost.
"""

from __future__ import annotations

import statistics
from collections import Counter
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from robocram.batch.result import VariantResult, VariantStatus
from robocram.execution.failures import failure_line

LINE_WIDTH = 160  # [characters] of every line about a cause, its count and indent included
COUNT_WIDTH = 7  # [characters] of the count column before a cause: "   41  "


@dataclass(frozen=True)
class FailureCause:
    """One reason variants did not succeed, and which variants it ended."""

    line: str  # the failure's type and what went wrong, one short line
    variants: tuple[str, ...]  # their names, in batch order

    def lines(self) -> Iterator[str]:
        """The count and the cause, then the variants' names, each within LINE_WIDTH."""
        yield f"{len(self.variants):>{COUNT_WIDTH - 2}}  {self.line}"
        names = " ".join(self.variants)
        width = LINE_WIDTH - COUNT_WIDTH
        if len(names) > width:
            names = names[: width - 2].rsplit(" ", 1)[0] + " …"
        yield " " * COUNT_WIDTH + names


@dataclass(frozen=True)
class BatchSummary:
    """Counts over a batch's results; ``failure_types`` counts failed and lost variants."""

    variants: int
    succeeded: int
    failed: int
    lost: int
    failure_types: tuple[tuple[str, int], ...]  # most frequent first
    median_duration: float  # [s] over the variants that ran to an answer
    causes: tuple[FailureCause, ...] = ()  # of failed and lost variants, most frequent first
    rerun: int = 0  # variants run again after their worker's node was lost

    @classmethod
    def of(cls, results: Iterable[VariantResult]) -> BatchSummary:
        """Summarise ``results``."""
        done = list(results)
        status = Counter(r.status for r in done)
        types = Counter(r.failure_type or "?" for r in done if not r.succeeded)
        ran = [r.duration for r in done if r.status is not VariantStatus.LOST]
        return cls(
            len(done),
            status[VariantStatus.SUCCEEDED],
            status[VariantStatus.FAILED],
            status[VariantStatus.LOST],
            tuple(sorted(types.items(), key=lambda kv: (-kv[1], kv[0]))),
            statistics.median(ran) if ran else 0.0,
            _causes(done),
            sum(r.rerun for r in done),
        )

    @property
    def success_rate(self) -> float:
        """Fraction of the variants that succeeded (0 for an empty batch)."""
        return self.succeeded / self.variants if self.variants else 0.0

    def lines(self) -> Iterator[str]:
        """The summary as a text table."""
        yield f"{'variants':<26}{self.variants:>8}"
        yield f"{'succeeded':<26}{self.succeeded:>8}  ({100 * self.success_rate:.1f} %)"
        yield f"{'failed':<26}{self.failed:>8}"
        yield f"{'lost':<26}{self.lost:>8}"
        if self.rerun:
            yield f"{'re-run after a lost node':<26}{self.rerun:>8}"
        yield f"{'median duration [s]':<26}{self.median_duration:>8.2f}"
        if self.failure_types:
            yield ""
            yield f"{'failure type':<26}{'count':>8}"
            yield from (f"{name:<26}{count:>8}" for name, count in self.failure_types)

    def cause_lines(self) -> Iterator[str]:
        """Why variants did not succeed: one group per cause, most frequent first."""
        if self.causes:
            yield "variants that did not succeed, by cause:"
        for cause in self.causes:
            yield from cause.lines()


def _causes(results: list[VariantResult]) -> tuple[FailureCause, ...]:
    width = LINE_WIDTH - COUNT_WIDTH
    groups: dict[str, list[str]] = {}
    for r in results:
        if not r.succeeded:
            groups.setdefault(failure_line(r.failure_type, r.message, width), []).append(r.name)
    ordered = sorted(groups.items(), key=lambda kv: -len(kv[1]))  # stable: first seen first
    return tuple(FailureCause(line, tuple(names)) for line, names in ordered)
