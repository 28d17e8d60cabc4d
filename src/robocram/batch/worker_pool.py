"""What every backend shares: the loop that hands out variants and streams their results.

A backend (:mod:`~robocram.batch.process_pool`, :mod:`~robocram.batch.ray_pool`) starts its
workers, collects whatever finished (replacing a dead worker and reporting its variant
lost), and stops them all; the loop, the stop request and the lost result are here.

A variant whose worker's node was lost (not the variant's fault) is handed out once more
(:meth:`Pending.retry`), and only its final result is yielded, marked ``rerun``: each
variant has exactly one result. Should every worker be gone with variants left (a Ray
cluster that lost all its nodes), the batch ends: those variants are reported ``lost`` as
``NoWorkerLeft``, so the caller still gets one result per variant and what finished.
"""

from __future__ import annotations

import threading
from abc import ABC, abstractmethod
from collections import deque
from collections.abc import Generator, Iterator, Sequence
from dataclasses import replace

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
        self._again: deque[tuple[int, Variant]] = deque()  # handed out again first
        self.names: dict[int, str] = {}  # the variants handed out, for lost results
        self.rerun: set[int] = set()  # the variants handed out a second time

    def __bool__(self) -> bool:
        return self._left > 0 or bool(self._again)

    def __len__(self) -> int:
        return self._left + len(self._again)

    def popleft(self) -> tuple[int, Variant]:
        """The next (index in the batch, variant): one to run again, else a new one."""
        if self._again:
            return self._again.popleft()
        index, variant = next(self._variants)
        self._left -= 1
        if not isinstance(variant, Variant):
            raise BatchError(f"{variant!r} is not a Variant; build one with Variant(name, ...)")
        self.names[index] = variant.name
        return index, variant

    def retry(self, index: int, variant: Variant) -> bool:
        """Hand variant ``index`` out again, next; False if it was already run again once."""
        if index in self.rerun:
            return False
        self.rerun.add(index)
        self._again.append((index, variant))
        return True


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
            while not self._stopping.is_set() and self._busy(pending):
                for result in self._collect(pending):
                    yield replace(result, rerun=result.index in pending.rerun)
            while pending and not self._stopping.is_set():
                index, variant = pending.popleft()
                yield self._not_run(index, variant, index in pending.rerun)
        finally:
            self.close()

    def request_stop(self) -> None:
        """Make :meth:`results` return at its next wake-up (safe from any thread)."""
        self._stopping.set()

    def _lost(self, index: int, pid: int, why: str, node: str = "") -> VariantResult:
        """The result of variant ``index``, lost with the worker ``pid`` (on ``node``)."""
        name = self._names.get(index, "")
        lost = VariantStatus.LOST
        return VariantResult(index, name, lost, "WorkerDied", why, worker=pid, node=node)

    def _not_run(self, index: int, variant: Variant, lost_once: bool) -> VariantResult:
        """The result of a variant left over when every worker was gone."""
        what = "lost with its worker's node, not run again" if lost_once else "not run"
        why = f"{what}: every worker was lost and none could be started in their place"
        return VariantResult(index, variant.name, VariantStatus.LOST, "NoWorkerLeft", why)

    @abstractmethod
    def _start(self, count: int, pending: Pending) -> None:
        """Start ``count`` workers and hand each a variant."""

    @abstractmethod
    def _busy(self, pending: Pending) -> bool:
        """Whether a worker holds a variant (or one is starting to take ``pending`` ones)."""

    @abstractmethod
    def _collect(self, pending: Pending) -> Iterator[VariantResult]:
        """Wait a poll interval; yield what finished, handing out the next variants."""

    @abstractmethod
    def pids(self) -> list[int]:
        """Process ids of the live workers."""

    @abstractmethod
    def close(self) -> None:
        """Stop every worker and wait until it is gone (idempotent)."""
