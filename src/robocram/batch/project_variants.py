"""``project_variants``: run one plan many ways, in parallel worlds, streaming the results."""

from __future__ import annotations

import pickle
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import TextIO

from robocram.batch.batch_run import BatchRun, WorkerPool
from robocram.batch.drawn_variants import DrawnVariants
from robocram.batch.errors import BatchError, UnknownBackend
from robocram.batch.main_guard import require_main_guard
from robocram.batch.process_pool import ProcessPool
from robocram.batch.progress import ProgressBar
from robocram.batch.variant import Variant
from robocram.batch.worker import Plan, SceneFactory, WorkerConfig
from robocram.plans import pick_up
from robocram.scenes import tabletop_scene

BACKENDS = ("processes", "ray")


def project_variants(
    variants: Iterable[Variant],
    plan: Plan = pick_up,
    robot: str = "pr2",
    scene: SceneFactory = tabletop_scene,
    workers: int = 2,
    backend: str = "processes",
    traces: str | Path | None = None,
    progress: bool | None = None,
    progress_stream: TextIO | None = None,
) -> BatchRun:
    """Start running ``plan`` once per variant on ``workers`` worker processes.

    ``plan(look_target, **variant.parameters)`` runs inside ``simulated_robot`` in the
    world ``scene(robot)``, which each worker builds once per robot and restores after
    every variant. ``plan`` and ``scene`` must be importable functions (they are pickled to
    the workers). With ``traces``, each variant's run is written to that trace database
    (a file every worker can reach). ``backend="ray"`` runs the workers as Ray actors (the
    ``robocram[ray]`` extra). ``progress`` shows a bar on ``progress_stream`` (standard
    output): ``None`` shows it when that stream is a terminal.

    Raises:
        UnknownBackend: ``backend`` is not one of :data:`BACKENDS`.
        BackendMissing: the backend's package is not installed.
        BatchError: ``workers`` is not a positive integer, a variant is not a Variant, or
            ``plan`` or ``scene`` cannot be pickled (a lambda, a local function).
        UnguardedBatch: a script starts the process batch at its top level, outside
            ``if __name__ == "__main__":`` (spawned workers would start it again).
    """
    if backend not in BACKENDS:
        raise UnknownBackend(backend, BACKENDS)
    if not isinstance(workers, int) or isinstance(workers, bool) or workers < 1:
        raise BatchError(f"workers={workers!r}: give a positive number of processes")
    batch = variants if isinstance(variants, DrawnVariants) else list(variants)
    if not isinstance(batch, DrawnVariants):  # a drawn batch is drawn as workers ask
        for item in batch:
            if not isinstance(item, Variant):
                raise BatchError(f"{item!r} is not a Variant; build one with Variant(name, ...)")
    config = WorkerConfig(plan, scene, robot, None if traces is None else Path(traces))
    _check_picklable(config)
    pool: WorkerPool
    if backend == "ray":
        from robocram.batch.ray_pool import RayPool  # Ray is an optional extra

        pool = RayPool(config, workers)
    else:
        require_main_guard(sys._getframe(1))  # spawned workers import the script
        pool = ProcessPool(config, workers)
    return BatchRun(pool, batch, ProgressBar(len(batch), progress, progress_stream))


def _check_picklable(config: WorkerConfig) -> None:
    """Fail here, naming the culprit, rather than in the first worker's start."""
    try:
        pickle.dumps(config)
    except (pickle.PicklingError, AttributeError, TypeError) as err:
        raise BatchError(
            f"plan {config.plan!r} or scene {config.scene!r} cannot be sent to a worker "
            f"({err}); pass functions defined at the top level of an importable module"
        ) from err
