"""Where the ``processes`` backend's workers come from: a server with robocram imported.

A spawned worker starts a new interpreter and imports robocram (about a second), before
its first variant. Workers are forked instead from a forkserver, a process started once
per parent that has imported the batch worker's modules: each worker starts with them
loaded. The server only imports; it builds no world, so no PyBullet client exists when
a worker is forked (a client does not survive a fork). The server keeps running for the
parent's later batches. Where the platform has no forkserver, workers are spawned.

A worker still imports the parent's ``__main__`` script (to find plans defined there) and
the plan's own module, as a spawned one does; robocram's modules are not imported again.
"""

from __future__ import annotations

import multiprocessing
from multiprocessing.context import ForkServerContext, SpawnContext
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from robocram.batch.worker import WorkerConfig

# imported by the server before it forks a worker: what every worker needs (the last two
# are imported by a first variant's world and plan otherwise)
PRELOAD = (
    "robocram.batch.worker", "robocram.plans", "robocram.scenes", "robocram.world.predicates",
    "numpy.random",
)  # fmt: skip


def worker_context(config: WorkerConfig) -> ForkServerContext | SpawnContext:
    """A forkserver context preloading robocram (and the batch's plan and scene when they
    are robocram's), or the spawn context where forkserver is missing."""
    if "forkserver" not in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("spawn")
    context = multiprocessing.get_context("forkserver")
    own = {f.__module__ for f in (config.plan, config.scene) if _is_robocram(f.__module__)}
    if config.traces is not None:  # the trace store (SQLAlchemy) only for a traced batch
        own.add("robocram.traces")
    if config.robot.isidentifier():  # a built-in robot's description (the server skips a
        own.add(f"robocram.robots.builtin.{config.robot}")  # module it cannot import)
    # read when the server starts: a server already running keeps what it imported
    context.set_forkserver_preload([*PRELOAD, *sorted(own - set(PRELOAD))])
    return context


def _is_robocram(module: str) -> bool:
    """Whether ``module`` is robocram's own (a user's module may do anything on import)."""
    return module == "robocram" or module.startswith("robocram.")
