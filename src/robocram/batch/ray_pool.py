"""The ``"ray"`` backend: Ray actors that each hold worlds, on one machine or a cluster.

Each actor is a :class:`~robocram.batch.worker.VariantRunner` in its own Ray worker process:
it builds a robot's scene once and restores it between variants, exactly like a spawned
worker, so both backends give the same results. One variant is in flight per actor, so a
dead actor (a crash, ``kill -9``, a lost node) loses only that variant, reported ``LOST``,
and a new actor takes its place. Leaving the stream kills every actor and waits for the
ones on this machine to exit.

If Ray is not running yet, the pool starts it (``ray.init()`` reads ``RAY_ADDRESS``, so
that variable points it at a cluster) and shuts it down when the batch ends; a Ray the
caller started (``ray.init(address=...)``) is used and left running.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import signal
import sys
from collections.abc import Iterator
from dataclasses import dataclass, replace
from typing import Any

import psutil

from robocram.batch.errors import BackendMissing, BatchError
from robocram.batch.result import VariantResult
from robocram.batch.variant import Variant
from robocram.batch.worker import VariantRunner, WorkerConfig
from robocram.batch.worker_pool import Pending, WorkerPool

POLL = 0.5  # [s] the parent wakes this often, so a pending Ctrl-C is handled promptly
STOP_GRACE = 5.0  # [s] a killed actor's process gets this long to exit before SIGKILL
START_TIMEOUT = 120.0  # [s] for an actor to be placed and started (free CPUs on a node)
LOCAL_OBJECT_STORE = 128 * 2**20  # [bytes] results are small; keep /dev/shm use low


class VariantActor:
    """A Ray actor holding one :class:`VariantRunner` (its worlds live as long as it does)."""

    def __init__(self, config: bytes, paths: list[str]) -> None:
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the driver's to handle
        # like a spawned worker: find the driver's modules (plans defined next to a script)
        sys.path[:0] = [p for p in paths if p not in sys.path]
        self._runner = VariantRunner(pickle.loads(config))

    def where(self) -> tuple[int, str]:
        """This actor's process id and Ray node id."""
        import ray

        return os.getpid(), ray.get_runtime_context().get_node_id()

    def run(self, index: int, variant: Variant) -> VariantResult:
        """Run one variant (see :meth:`VariantRunner.run`)."""
        return replace(self._runner.run(index, variant), worker=os.getpid())


@dataclass
class _Actor:
    handle: Any  # a Ray actor handle
    pid: int
    node: str
    job: tuple[int, Any] | None = None  # (variant index, its result's ObjectRef)


def _ray() -> Any:
    try:
        import ray
    except ImportError as err:
        raise BackendMissing("ray", "pip install 'robocram[ray]'") from err
    return ray


class RayPool(WorkerPool):
    """Ray actors running the variants of one batch; iterate :meth:`results`."""

    def __init__(self, config: WorkerConfig, workers: int) -> None:
        super().__init__(workers)
        self._ray = _ray()
        self._config = pickle.dumps(config)
        self._actors: list[_Actor] = []
        self._owns_ray = False
        self._node = ""

    def pids(self) -> list[int]:
        """Process ids of the live actors (on their nodes)."""
        return [a.pid for a in self._actors]

    def _connect(self) -> None:
        ray = self._ray
        if not ray.is_initialized():
            local = "RAY_ADDRESS" not in os.environ
            options = {"object_store_memory": LOCAL_OBJECT_STORE} if local else {}
            ray.init(include_dashboard=False, log_to_driver=False, **options)
            self._owns_ray = True
        self._node = ray.get_runtime_context().get_node_id()
        self._remote = ray.remote(num_cpus=1, max_restarts=0, max_task_retries=0)(VariantActor)

    def _start_actors(self, count: int) -> list[_Actor]:
        """Start ``count`` actors at once (each imports robocram: seconds) and wait for all."""
        handles = [self._remote.remote(self._config, list(sys.path)) for _ in range(count)]
        errors = self._ray.exceptions
        try:
            places = self._ray.get([h.where.remote() for h in handles], timeout=START_TIMEOUT)
        except (errors.GetTimeoutError, errors.RayError) as err:
            for handle in handles:
                self._ray.kill(handle, no_restart=True)
            if isinstance(err, errors.GetTimeoutError):
                raise BatchError(
                    f"no Ray node started a batch actor within {START_TIMEOUT:.0f} s; the "
                    f"cluster needs a free CPU per worker ({self.size}): use fewer workers"
                ) from err
            raise BatchError(f"a Ray batch actor could not start: {err}") from err
        actors = [_Actor(h, pid, node) for h, (pid, node) in zip(handles, places, strict=True)]
        self._actors.extend(actors)
        return actors

    def _start(self, count: int, pending: Pending) -> None:
        self._connect()
        for actor in self._start_actors(count):
            self._assign(actor, pending)

    def _busy(self) -> bool:
        return any(a.job is not None for a in self._actors)

    def _assign(self, actor: _Actor, pending: Pending) -> None:
        if pending:
            index, variant = pending.popleft()
            actor.job = (index, actor.handle.run.remote(index, variant))

    def _collect(self, pending: Pending) -> Iterator[VariantResult]:
        busy = {a.job[1]: (a, a.job[0]) for a in self._actors if a.job is not None}
        ready, _ = self._ray.wait(list(busy), num_returns=1, timeout=POLL)
        for ref in ready:
            actor, index = busy[ref]
            try:
                result: VariantResult = self._ray.get(ref)
            except self._ray.exceptions.RayActorError as err:
                yield self._replace(actor, index, err, pending)
                continue
            actor.job = None
            self._assign(actor, pending)
            yield result

    def _replace(self, dead: _Actor, index: int, err: Exception, pending: Pending) -> VariantResult:
        """Report a dead actor's variant ``index`` lost and start an actor in its place."""
        self._stop([dead])
        if pending:
            self._assign(self._start_actors(1)[0], pending)
        cause = str(err).strip().splitlines()[0] if str(err).strip() else type(err).__name__
        why = f"Ray actor in process {dead.pid} died running this variant ({cause})"
        return self._lost(index, dead.pid, why)

    def _stop(self, actors: list[_Actor]) -> None:
        """Kill ``actors`` and wait for those on this machine to exit."""
        local: list[psutil.Process] = []
        for actor in actors:
            self._actors.remove(actor)
            if not self._ray.is_initialized():
                continue  # Ray was shut down, and its actors with it
            if actor.node == self._node:
                with contextlib.suppress(psutil.NoSuchProcess):
                    local.append(psutil.Process(actor.pid))
            self._ray.kill(actor.handle, no_restart=True)
        _, alive = psutil.wait_procs(local, timeout=STOP_GRACE)
        for process in alive:
            with contextlib.suppress(psutil.NoSuchProcess):
                process.kill()
        psutil.wait_procs(alive, timeout=STOP_GRACE)

    def close(self) -> None:
        """Kill every actor; shut Ray down if this pool started it."""
        if self._actors:
            self._stop(list(self._actors))
        if self._owns_ray and self._ray.is_initialized():
            self._ray.shutdown()
        self._owns_ray = False
