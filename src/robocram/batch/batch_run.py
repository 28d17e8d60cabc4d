"""The running batch: results as they finish, a progress bar, cancel; the same for every
backend (a :class:`~robocram.batch.worker_pool.WorkerPool`)."""

from __future__ import annotations

import threading
from collections.abc import Iterator, Sequence
from types import TracebackType

from robocram.batch.progress import ProgressBar
from robocram.batch.result import VariantResult
from robocram.batch.variant import Variant
from robocram.batch.worker_pool import WorkerPool


class BatchRun:
    """The running batch: iterate it for results as they finish; ``cancel()`` stops it.

    Also a context manager: leaving the block cancels whatever has not finished.
    """

    def __init__(
        self, pool: WorkerPool, variants: Sequence[Variant], progress: ProgressBar
    ) -> None:
        self._pool = pool
        self._stream = pool.results(variants)
        self.count = len(variants)
        self.progress = progress
        self._reading = threading.Lock()  # held while a thread waits for the next result

    def __iter__(self) -> Iterator[VariantResult]:
        return self

    def __next__(self) -> VariantResult:
        try:
            with self._reading:
                result = next(self._stream)
        except BaseException:  # the end, Ctrl-C or an error: the bar's line is finished
            self.progress.close()
            raise
        self.progress.update(result)
        return result

    def __enter__(self) -> BatchRun:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, err: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.cancel()

    def worker_pids(self) -> list[int]:
        """Process ids of the live workers."""
        return self._pool.pids()

    def cancel(self) -> None:
        """Stop every worker now; the results not yet yielded are dropped.

        Callable from another thread than the one iterating: that one's wait ends within
        the backend's poll interval, with no further result.
        """
        self._pool.request_stop()
        with self._reading:
            self._stream.close()
        self._pool.close()
        self.progress.close()

    def collect(self) -> list[VariantResult]:
        """Wait for every result; return them in the order of the variants."""
        return sorted(self, key=lambda r: r.index)
