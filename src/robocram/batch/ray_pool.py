"""The ``"ray"`` backend: Ray actors that each hold worlds, on one machine or a cluster.

Each actor is a :class:`~robocram.batch.worker.VariantRunner` in its own Ray worker process:
it builds a robot's scene once and restores it between variants, exactly like a spawned
worker, so both backends give the same results. One variant is in flight per actor:

- an actor that dies on a live node (a crash, ``kill -9``) loses only that variant, reported
  ``LOST`` (it may be what killed the actor), and a new actor takes its place;
- an actor whose node is lost (Ray reports it unavailable, or its node dead) has its variant
  run once more by another actor. A replacement starts only if the cluster has a free CPU
  for it; otherwise the batch goes on with the actors that remain. Replacements start in
  the background, so the others keep working while one is placed.

Leaving the stream kills every actor and waits for the ones on this machine to exit.

If Ray is not running yet, the pool starts it (``ray.init()`` reads ``RAY_ADDRESS``, so
that variable points it at a cluster) and shuts it down when the batch ends; a Ray the
caller started (``ray.init(address=...)``) is used and left running.
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import pickle
import signal
import sys
import time
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
        return os.getpid(), _node_id()

    def run(self, index: int, variant: Variant) -> VariantResult:
        """Run one variant (see :meth:`VariantRunner.run`)."""
        return replace(self._runner.run(index, variant), worker=os.getpid(), node=_node_id())


def _node_id() -> str:
    import ray

    return str(ray.get_runtime_context().get_node_id())


@dataclass
class _Job:
    index: int  # of the variant in the batch
    variant: Variant  # kept to run it again should its node be lost
    ref: object  # the ObjectRef of its result


@dataclass
class _Actor:
    handle: Any  # a Ray actor handle
    pid: int
    node: str
    job: _Job | None = None


@dataclass
class _Starting:
    """An actor asked for in place of a dead one, not placed and started yet."""

    handle: Any  # a Ray actor handle
    where: object  # the ObjectRef of its ``where()``
    deadline: float  # [s] on the monotonic clock: given up after this


def _ray() -> Any:
    try:
        import ray
    except ImportError as err:
        raise BackendMissing("ray", "pip install 'robocram[ray]'") from err
    return ray


def _check_client(address: str) -> None:
    """A ``ray://`` address is Ray Client's, which needs ``ray[client]`` (grpc), not in Ray."""
    if not address.startswith("ray://"):
        return
    if importlib.util.find_spec("grpc") is None:
        fix = f"RAY_ADDRESS={address} connects through Ray Client: pip install 'robocram[ray]'"
        raise BackendMissing("ray[client]", f"{fix} (it installs ray[client])")


class RayPool(WorkerPool):
    """Ray actors running the variants of one batch; iterate :meth:`results`."""

    def __init__(self, config: WorkerConfig, workers: int) -> None:
        super().__init__(workers)
        self._ray = _ray()
        self._config = pickle.dumps(config)
        self._actors: list[_Actor] = []
        self._starting: list[_Starting] = []
        self._owns_ray = False
        self._node = ""

    def pids(self) -> list[int]:
        """Process ids of the live actors (on their nodes)."""
        return [a.pid for a in self._actors]

    def _connect(self) -> None:
        ray = self._ray
        if not ray.is_initialized():
            _check_client(os.environ.get("RAY_ADDRESS", ""))
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

    def _busy(self, pending: Pending) -> bool:
        working = any(a.job is not None for a in self._actors)
        return working or (bool(pending) and bool(self._starting))

    def _assign(self, actor: _Actor, pending: Pending) -> None:
        if pending:
            index, variant = pending.popleft()
            actor.job = _Job(index, variant, actor.handle.run.remote(index, variant))

    def _collect(self, pending: Pending) -> Iterator[VariantResult]:
        busy = {a.job.ref: (a, a.job) for a in self._actors if a.job is not None}
        starting = {s.where: s for s in self._starting}
        ready, _ = self._ray.wait([*busy, *starting], num_returns=1, timeout=POLL)
        for ref in ready:
            if ref in starting:
                self._started(starting[ref], pending)
                continue
            actor, job = busy[ref]
            try:
                result: VariantResult = self._ray.get(ref)
            except self._ray.exceptions.RayActorError as err:
                lost = self._replace(actor, job, err, pending)
                if lost is not None:
                    yield lost
                continue
            actor.job = None
            self._assign(actor, pending)
            yield result
        self._give_up_starting(pending)

    def _replace(
        self, dead: _Actor, job: _Job, err: Exception, pending: Pending
    ) -> VariantResult | None:
        """Stop a dead actor; run its variant again if its node was lost, else report it lost.

        A replacement is asked for when there is work left and room for it: always after a
        crash on a live node (the dead actor's CPU is freed), after a lost node only if the
        cluster has a free CPU (it shrank, and the actors that remain go on alone).
        """
        node_lost = self._node_lost(dead, err)
        self._stop([dead])
        again = node_lost and pending.retry(job.index, job.variant)
        for idle in [a for a in self._actors if a.job is None]:
            self._assign(idle, pending)
        if pending and (not node_lost or self._free_cpus() >= 1):
            self._start_replacement()
        if again:
            return None
        cause = str(err).strip().splitlines()[0] if str(err).strip() else type(err).__name__
        what = f"was lost with its node {dead.node}" if node_lost else "died"
        why = f"Ray actor in process {dead.pid} {what} running this variant ({cause})"
        return self._lost(job.index, dead.pid, why, dead.node)

    def _node_lost(self, actor: _Actor, err: Exception) -> bool:
        """Whether ``actor`` died with its node: unreachable, or its node no longer alive."""
        unavailable = getattr(self._ray.exceptions, "ActorUnavailableError", ())  # Ray 2.2x+
        if isinstance(err, unavailable):
            return True  # its raylet is gone (a dead process on a live node is "died")
        alive = {n["NodeID"] for n in self._ray.nodes() if n["Alive"]}
        return actor.node not in alive

    def _free_cpus(self) -> float:
        return float(self._ray.available_resources().get("CPU", 0.0))

    def _start_replacement(self) -> None:
        """Ask for one actor; :meth:`_collect` puts it to work once it is placed."""
        handle = self._remote.remote(self._config, list(sys.path))
        deadline = time.monotonic() + START_TIMEOUT
        self._starting.append(_Starting(handle, handle.where.remote(), deadline))

    def _started(self, start: _Starting, pending: Pending) -> None:
        """Put a replacement that started to work (or drop it if it died starting)."""
        self._starting.remove(start)
        try:
            pid, node = self._ray.get(start.where)
        except self._ray.exceptions.RayError:
            self._ray.kill(start.handle, no_restart=True)
            return
        actor = _Actor(start.handle, pid, node)
        self._actors.append(actor)
        self._assign(actor, pending)
        if actor.job is None:  # the others finished everything meanwhile
            self._stop([actor])

    def _give_up_starting(self, pending: Pending) -> None:
        """Kill replacements not needed any more, or not placed within START_TIMEOUT."""
        now = time.monotonic()
        for start in list(self._starting):
            if not pending or now > start.deadline:
                self._starting.remove(start)
                self._ray.kill(start.handle, no_restart=True)

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
        if self._starting and self._ray.is_initialized():
            for start in self._starting:
                self._ray.kill(start.handle, no_restart=True)
        self._starting.clear()
        if self._owns_ray and self._ray.is_initialized():
            self._ray.shutdown()
        self._owns_ray = False
