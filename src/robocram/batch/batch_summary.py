"""What a batch found, in a few numbers: success rate, failure types, median duration."""

from __future__ import annotations

import statistics
from collections import Counter
from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from robocram.batch.result import VariantResult, VariantStatus


@dataclass(frozen=True)
class BatchSummary:
    """Counts over a batch's results; ``failure_types`` counts failed and lost variants."""

    variants: int
    succeeded: int
    failed: int
    lost: int
    failure_types: tuple[tuple[str, int], ...]  # most frequent first
    median_duration: float  # [s] over the variants that ran to an answer

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
        yield f"{'median duration [s]':<26}{self.median_duration:>8.2f}"
        if self.failure_types:
            yield ""
            yield f"{'failure type':<26}{'count':>8}"
            yield from (f"{name:<26}{count:>8}" for name, count in self.failure_types)
