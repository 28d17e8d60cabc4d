"""Batch projection on a real local Ray (``ray.init(num_cpus=2)``): the same results as the
spawned processes, a killed actor loses only its variant, cancelling leaves no actor process.

One Ray for the whole module: starting one takes seconds.
"""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

import psutil
import pytest
import ray

from robocram.batch import Variant, VariantResult, VariantStatus, project_variants
from robocram.batch.ray_pool import LOCAL_OBJECT_STORE


@pytest.fixture(scope="module", autouse=True)
def local_ray() -> Iterator[None]:
    """A local two-CPU Ray, shut down after the module's tests."""
    ray.init(
        num_cpus=2,
        include_dashboard=False,
        log_to_driver=False,
        object_store_memory=LOCAL_OBJECT_STORE,
    )
    yield
    ray.shutdown()


def test_ray_gives_the_results_of_the_process_workers(
    reference_variants: list[Variant], reference_results: list[VariantResult]
) -> None:
    results = project_variants(reference_variants, backend="ray", workers=2).collect()
    assert [r.outcome() for r in results] == [r.outcome() for r in reference_results]
    assert len({r.worker for r in results}) == 2  # both actors did some of the work
    assert {r.worker for r in results}.isdisjoint({os.getpid()})
    assert ray.is_initialized()  # a Ray the caller started stays up


def _kill_when_written(path: Path, killed: list[int]) -> None:
    end = time.monotonic() + 120.0
    while not path.exists() or not path.read_text(encoding="utf-8"):
        if time.monotonic() > end:
            return
        time.sleep(0.02)
    pid = int(path.read_text(encoding="utf-8"))
    os.kill(pid, signal.SIGKILL)
    killed.append(pid)


def test_a_killed_actor_loses_only_its_variant(batch_plans: ModuleType, tmp_path: Path) -> None:
    pid_file = tmp_path / "blocked.pid"
    variants = [
        Variant("blocked", parameters={"block_in": str(pid_file)}),
        Variant("after-1", object_shifts={"mug-1": (0.0, 0.05, 0.0)}, look_at="mug-1"),
        Variant("after-2"),
    ]
    killed: list[int] = []
    killer = threading.Thread(target=_kill_when_written, args=(pid_file, killed))
    killer.start()
    run = project_variants(variants, plan=batch_plans.pick_or_block, backend="ray", workers=1)
    results = run.collect()
    killer.join()
    assert [r.status for r in results] == [
        VariantStatus.LOST,
        VariantStatus.SUCCEEDED,
        VariantStatus.SUCCEEDED,
    ]
    assert results[0].worker == killed[0] and results[0].failure_type == "WorkerDied"
    assert f"process {killed[0]} died" in results[0].message
    assert {results[1].worker, results[2].worker} - {killed[0]}  # the replacement ran them


def test_cancel_leaves_no_actor_process(batch_plans: ModuleType, tmp_path: Path) -> None:
    blocks = [tmp_path / "a.pid", tmp_path / "b.pid"]
    variants = [Variant(p.stem, parameters={"block_in": str(p)}) for p in blocks]
    run = project_variants(variants, plan=batch_plans.pick_or_block, backend="ray", workers=2)
    first: list[VariantResult] = []
    reader = threading.Thread(target=lambda: first.extend(run))  # blocks: nothing finishes
    reader.start()
    end = time.monotonic() + 120.0
    while not all(p.exists() for p in blocks) and time.monotonic() < end:
        time.sleep(0.02)
    actors = [int(p.read_text(encoding="utf-8")) for p in blocks]
    assert sorted(run.worker_pids()) == sorted(actors)
    run.cancel()
    reader.join(timeout=30.0)
    assert not reader.is_alive() and first == []
    assert not [pid for pid in actors if psutil.pid_exists(pid)]
