"""What every backend shares: the loop that hands out variants and streams their results.

A backend (:mod:`~robocram.batch.process_pool`, :mod:`~robocram.batch.ray_pool`) starts its
workers, collects whatever finished (replacing a dead worker and reporting its variant
lost), and stops them all; the loop, the stop request and the lost result are here.
"""

from __future__ import annotations

import threading
from abc import ABC, abstractmethod
from collections.abc import Generator, Iterator, Sequence

from robocram.batch.errors import BatchError
from robocram.batch.result import VariantResult, VariantStatus
from robocram.batch.variant import Variant


class Pending:
    """The variants not yet handed out, taken from the batch one at a time.

    A drawn batch (:class:`~robocram.batch.drawn_variants.DrawnVariants`) draws each
    variant here, as a worker becomes free, so a big batch starts at once in little memory.
    """

    def __init__(self, variants: Sequence[Variant]) -> None:
        self._left = len(variants)
        self._variants = enumerate(variants)
        self.names: dict[int, str] = {}  # the variants handed out, for lost results

    def __bool__(self) -> bool:
        return self._left > 0

    def __len__(self) -> int:
        return self._left

    def popleft(self) -> tuple[int, Variant]:
        """The next (index in the batch, variant)."""
        index, variant = next(self._variants)
        self._left -= 1
        if not isinstance(variant, Variant):
            raise BatchError(f"{variant!r} is not a Variant; build one with Variant(name, ...)")
        self.names[index] = variant.name
        return index, variant


class WorkerPool(ABC):
    """Workers running the variants of one batch, one variant in flight per worker."""

    def __init__(self, workers: int) -> None:
        self.size = workers
        self._names: dict[int, str] = {}
        self._stopping = threading.Event()

    def results(self, variants: Sequence[Variant]) -> Generator[VariantResult, None, None]:
        """Yield each variant's result as it finishes; stop every worker on leaving."""
        pending = Pending(variants)
        self._names = pending.names
        try:
            self._start(min(self.size, len(pending)), pending)
            while not self._stopping.is_set() and self._busy():
                yield from self._collect(pending)
        finally:
            self.close()

    def request_stop(self) -> None:
        """Make :meth:`results` return at its next wake-up (safe from any thread)."""
        self._stopping.set()

    def _lost(self, index: int, pid: int, why: str) -> VariantResult:
        """The result of variant ``index``, lost with the worker ``pid`` that held it."""
        name = self._names.get(index, "")
        return VariantResult(index, name, VariantStatus.LOST, "WorkerDied", why, worker=pid)

    @abstractmethod
    def _start(self, count: int, pending: Pending) -> None:
        """Start ``count`` workers and hand each a variant."""

    @abstractmethod
    def _busy(self) -> bool:
        """Whether a worker holds a variant."""

    @abstractmethod
    def _collect(self, pending: Pending) -> Iterator[VariantResult]:
        """Wait a poll interval; yield what finished, handing out the next variants."""

    @abstractmethod
    def pids(self) -> list[int]:
        """Process ids of the live workers."""

    @abstractmethod
    def close(self) -> None:
        """Stop every worker and wait until it is gone (idempotent)."""
