"""The ``"processes"`` backend: worker processes, one variant in flight per worker.

Workers are forked from a server with robocram imported (:mod:`~robocram.batch.warm_start`),
so they start warm; the batch's plan and scene travel once per worker, at its start.

Each worker talks to the parent over its own pipe, so the parent always knows which variant
a worker holds: when a worker dies (a crash, ``kill -9``) its variant is reported lost and a
new worker takes its place. Leaving the stream early (cancel, Ctrl-C, an error) terminates
every worker before control returns.
"""

from __future__ import annotations

import contextlib
import os
import socket
from collections.abc import Iterator
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from multiprocessing.process import BaseProcess

from robocram.batch.result import VariantResult
from robocram.batch.warm_start import worker_context
from robocram.batch.worker import WorkerConfig, worker_main
from robocram.batch.worker_pool import Pending, WorkerPool

POLL = 0.5  # [s] the parent wakes this often, so a pending Ctrl-C is handled promptly
# One core per worker: BLAS threads of one worker would take the cores of the others (on 2
# cores, 2 workers with threaded OpenBLAS ran slower than 1). A value the user set is kept.
ONE_THREAD = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
STOP_GRACE = 2.0  # [s] a terminated worker gets this long before it is killed


@dataclass
class _Worker:
    process: BaseProcess
    conn: Connection
    job: int | None = None  # index of the variant it holds


class ProcessPool(WorkerPool):
    """Worker processes running the variants of one batch; iterate :meth:`results`."""

    def __init__(self, config: WorkerConfig, workers: int) -> None:
        super().__init__(workers)
        self.config = config
        self._context = worker_context(config)
        self._workers: list[_Worker] = []

    def pids(self) -> list[int]:
        """Process ids of the live workers (for monitoring, and the fault tests)."""
        return [w.process.pid for w in self._workers if w.process.pid is not None]

    def _start_worker(self) -> _Worker:
        parent, child = self._context.Pipe()
        process = self._context.Process(
            target=worker_main, args=(self.config, child), name="robocram-batch", daemon=True
        )
        with _one_thread_each():
            process.start()
        child.close()
        worker = _Worker(process, parent)
        self._workers.append(worker)
        return worker

    def _start(self, count: int, pending: Pending) -> None:
        for _ in range(count):
            self._start_worker()
        for worker in self._workers:
            self._assign(worker, pending)

    def _busy(self, pending: Pending) -> bool:
        return any(w.job is not None for w in self._workers)

    def _assign(self, worker: _Worker, pending: Pending) -> None:
        if pending:
            index, variant = pending.popleft()
            worker.job = index
            # if it died since its last answer, its sentinel reports this variant lost
            with contextlib.suppress(OSError):
                worker.conn.send((index, variant))

    def _collect(self, pending: Pending) -> Iterator[VariantResult]:
        busy = {w.conn: w for w in self._workers if w.job is not None}
        deaths = {w.process.sentinel: w for w in busy.values()}
        for ready in wait([*busy, *deaths], timeout=POLL):
            if isinstance(ready, Connection) and ready in busy:
                worker = busy[ready]
                try:
                    result: VariantResult = ready.recv()
                except (EOFError, OSError):
                    continue  # it died mid-answer; its sentinel reports the loss
                worker.job = None
                self._assign(worker, pending)
                yield result
            elif isinstance(ready, int) and ready in deaths:
                lost = self._replace(deaths[ready], pending)
                if lost is not None:
                    yield lost

    def _replace(self, dead: _Worker, pending: Pending) -> VariantResult | None:
        """Report a dead worker's variant lost and start a worker in its place."""
        if dead.job is None or dead.process.is_alive():
            return None
        index = dead.job
        answered = _last_answer(dead.conn)
        dead.process.join()
        dead.conn.close()
        self._workers.remove(dead)
        if pending:
            self._assign(self._start_worker(), pending)
        if answered is not None:
            return answered
        pid, code = dead.process.pid or -1, dead.process.exitcode
        why = f"worker {pid} died (exit code {code}) running this variant"
        return self._lost(index, pid, why, socket.gethostname())

    def close(self) -> None:
        """Terminate every worker and wait until each is gone (killing stragglers)."""
        for worker in self._workers:
            if worker.process.is_alive():
                worker.process.terminate()
        for worker in self._workers:
            worker.process.join(STOP_GRACE)
            if worker.process.is_alive():
                worker.process.kill()
                worker.process.join()
            worker.conn.close()
        self._workers.clear()


def _last_answer(conn: Connection) -> VariantResult | None:
    """The result a worker sent just before it died, if it got that far."""
    try:
        return conn.recv() if conn.poll() else None
    except (EOFError, OSError):
        return None


@contextlib.contextmanager
def _one_thread_each() -> Iterator[None]:
    """Start a worker with :data:`ONE_THREAD` in its environment (read as BLAS loads)."""
    added = {k: v for k, v in ONE_THREAD.items() if k not in os.environ}
    os.environ.update(added)
    try:
        yield
    finally:
        for key in added:
            os.environ.pop(key, None)
