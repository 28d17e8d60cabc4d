"""``project_variants``: run one plan many ways, in parallel worlds, streaming the results."""

from __future__ import annotations

import pickle
from collections.abc import Iterable, Iterator
from pathlib import Path
from types import TracebackType

from robocram.batch.errors import BatchError, UnknownBackend
from robocram.batch.process_pool import ProcessPool
from robocram.batch.result import VariantResult
from robocram.batch.variant import Variant
from robocram.batch.worker import Plan, SceneFactory, WorkerConfig
from robocram.plans import pick_up
from robocram.scenes import tabletop_scene

BACKENDS = ("processes",)


class BatchRun:
    """The running batch: iterate it for results as they finish; ``cancel()`` stops it.

    Also a context manager: leaving the block cancels whatever has not finished.
    """

    def __init__(self, pool: ProcessPool, variants: list[Variant]) -> None:
        self._pool = pool
        self._stream = pool.results(variants)
        self.count = len(variants)

    def __iter__(self) -> Iterator[VariantResult]:
        return self

    def __next__(self) -> VariantResult:
        return next(self._stream)

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
        """Stop every worker now; the results not yet yielded are dropped."""
        self._stream.close()
        self._pool.close()

    def collect(self) -> list[VariantResult]:
        """Wait for every result; return them in the order of the variants."""
        return sorted(self, key=lambda r: r.index)


def project_variants(
    variants: Iterable[Variant],
    plan: Plan = pick_up,
    robot: str = "pr2",
    scene: SceneFactory = tabletop_scene,
    workers: int = 2,
    backend: str = "processes",
    traces: str | Path | None = None,
) -> BatchRun:
    """Start running ``plan`` once per variant on ``workers`` spawned processes.

    ``plan(look_target, **variant.parameters)`` runs inside ``simulated_robot`` in the
    world ``scene(robot)``, which each worker builds once per robot and restores after
    every variant. ``plan`` and ``scene`` must be importable functions (they are pickled to
    the workers). With ``traces``, each variant's run is written to that trace database.

    Raises:
        UnknownBackend: ``backend`` is not one of :data:`BACKENDS`.
        BatchError: ``workers`` is not a positive integer, a variant is not a Variant, or
            ``plan`` or ``scene`` cannot be pickled (a lambda, a local function).
    """
    if backend not in BACKENDS:
        raise UnknownBackend(backend, BACKENDS)
    if not isinstance(workers, int) or workers < 1:
        raise BatchError(f"workers={workers!r}: give a positive number of processes")
    batch = list(variants)
    for item in batch:
        if not isinstance(item, Variant):
            raise BatchError(f"{item!r} is not a Variant; build one with Variant(name, ...)")
    config = WorkerConfig(plan, scene, robot, None if traces is None else Path(traces))
    _check_picklable(config)
    return BatchRun(ProcessPool(config, workers), batch)


def _check_picklable(config: WorkerConfig) -> None:
    """Fail here, naming the culprit, rather than in the first worker's start."""
    try:
        pickle.dumps(config)
    except (pickle.PicklingError, AttributeError, TypeError) as err:
        raise BatchError(
            f"plan {config.plan!r} or scene {config.scene!r} cannot be sent to a worker "
            f"({err}); pass functions defined at the top level of an importable module"
        ) from err
