"""Batch projection on a real local Ray (``ray.init(num_cpus=2)``): the same results as the
spawned processes, a killed actor loses only its variant, cancelling leaves no actor process.

One Ray for the whole module: starting one takes seconds. Ray is held to the processes'
results on one reference variant of each kind (:data:`OF_EACH_KIND`), not all twenty: Ray
carries the variants and their results, and how the plan fares with each placement is the
processes' test (``test_batch_processes.py`` runs all twenty on one and on two workers).
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from types import ModuleType

import psutil
import pytest
import ray

from robocram.batch import BackendMissing, Variant, VariantResult, project_variants
from robocram.batch.ray_pool import LOCAL_OBJECT_STORE

# of the reference variants: shifted, jittered and seeded, put at a pose, failing in the
# plan (no toaster), failing on a misspelt parameter (a TypeError crossing Ray)
OF_EACH_KIND = ("mug0", "mug1", "posed0", "toaster", "typo")


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
    variants = [v for v in reference_variants if v.name in OF_EACH_KIND]
    expected = [r for r in reference_results if r.name in OF_EACH_KIND]
    assert len(variants) == len(expected) == len(OF_EACH_KIND)
    results = project_variants(variants, backend="ray", workers=2).collect()
    assert [r.index for r in results] == list(range(len(variants)))  # in the batch's order
    in_reference = [
        replace(r.outcome(), index=e.index) for r, e in zip(results, expected, strict=True)
    ]
    assert in_reference == [e.outcome() for e in expected]
    assert len({r.worker for r in results}) == 2  # both actors did some of the work
    assert {r.worker for r in results}.isdisjoint({os.getpid()})
    assert {r.node for r in results} == {ray.get_runtime_context().get_node_id()}
    assert ray.is_initialized()  # a Ray the caller started stays up


def test_a_killed_actor_loses_only_its_variant(batch_plans: ModuleType, tmp_path: Path) -> None:
    results, killed = batch_plans.run_killing_the_first("ray", tmp_path / "blocked.pid")
    assert results[0].failure_type == "WorkerDied" and results[0].name == "blocked"
    assert f"Ray actor in process {killed} died" in results[0].message
    # its node lives on: the variant may be what killed it, so it does not run again
    assert results[0].node == ray.get_runtime_context().get_node_id() and not results[0].rerun


def test_cancel_leaves_no_actor_process(batch_plans: ModuleType, tmp_path: Path) -> None:
    blocks = [tmp_path / "a.pid", tmp_path / "b.pid"]
    variants = [Variant(p.stem, parameters={"block_in": str(p)}) for p in blocks]
    run = project_variants(variants, plan=batch_plans.pick_or_block, backend="ray", workers=2)
    first: list[VariantResult] = []
    reader = threading.Thread(target=lambda: first.extend(run))  # blocks: nothing finishes
    reader.start()
    batch_plans.wait_for(blocks)
    actors = [int(p.read_text(encoding="utf-8")) for p in blocks]
    assert sorted(run.worker_pids()) == sorted(actors)
    run.cancel()
    reader.join(timeout=30.0)
    assert not reader.is_alive() and first == []
    assert not [pid for pid in actors if psutil.pid_exists(pid)]


def test_without_ray_installed_the_error_says_how(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "ray", None)  # what `import ray` meets when it is missing
    with pytest.raises(BackendMissing, match=r"needs 'ray': pip install 'robocram\[ray\]'"):
        project_variants([Variant("a")], backend="ray")
