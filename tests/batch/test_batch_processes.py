"""Batch projection on spawned processes: repeatable across worker counts, failures kept
as data, a killed worker loses only its variant, cancelling leaves no process behind."""

from __future__ import annotations

import os
import signal
import socket
import threading
from pathlib import Path
from types import ModuleType

import psutil
import pytest

from robocram.batch import (
    BadVariant,
    BatchError,
    UnknownBackend,
    Variant,
    VariantResult,
    VariantStatus,
    project_variants,
)
from robocram.batch.worker import VariantRunner, WorkerConfig
from robocram.plans import pick_up
from robocram.scenes import tabletop_scene
from robocram.traces import TraceDatabase, runs

HELPERS = ("forkserver", "resource_tracker")


def _children() -> set[int]:
    """Live descendants but multiprocessing's own helpers: the forkserver the workers come
    from (kept for the next batch) and its resource tracker."""
    return {
        p.pid
        for p in psutil.Process().children(recursive=True)
        if p.is_running() and not _multiprocessing_helper(p)
    }


def _multiprocessing_helper(process: psutil.Process) -> bool:
    """Whether ``process`` is a helper this process started (a worker forked by the server
    shows the server's command line too, but the server is its parent)."""
    try:
        command = " ".join(process.cmdline())
        if process.ppid() != os.getpid():
            return False
    except psutil.NoSuchProcess:
        return False
    return any(f"from multiprocessing.{m} import main" in command for m in HELPERS)


def test_one_and_two_workers_give_equal_results(
    reference_variants: list[Variant], reference_results: list[VariantResult]
) -> None:
    one = reference_results
    two = project_variants(reference_variants, robot="pr2", workers=2).collect()
    assert [r.outcome() for r in one] == [r.outcome() for r in two]
    assert len({r.worker for r in two}) == 2  # both workers did some of the work
    assert {r.node for r in two} == {socket.gethostname()}  # processes run on this host
    by_name = {r.name: r for r in one}
    assert by_name["toaster"].status is VariantStatus.FAILED
    assert by_name["toaster"].failure_type == "PerceptionObjectNotFound"
    assert by_name["typo"].failure_type == "TypeError" and "objec" in by_name["typo"].message
    picked = [r for r in one if r.succeeded]
    assert len(picked) >= 12 and all(r.arm in ("left", "right") for r in picked)
    # the grasp follows the mug: each variant's own placement, not the scene's
    ys = {round(r.grasp[1], 2) for r in picked if r.grasp is not None}
    assert len(ys) >= 6
    posed = [by_name[f"posed{i}"] for i in range(4)]
    for result, y in zip(posed, (-0.25, -0.1, 0.0, 0.12), strict=True):
        if result.succeeded and result.grasp is not None:  # grasped where the variant put it
            assert result.grasp[0:2] == pytest.approx((0.6, y), abs=0.02)


def test_a_killed_worker_loses_only_its_variant(batch_plans: ModuleType, tmp_path: Path) -> None:
    results, killed = batch_plans.run_killing_the_first("processes", tmp_path / "blocked.pid")
    assert results[0].failure_type == "WorkerDied" and results[0].name == "blocked"
    assert f"worker {killed} died (exit code {-signal.SIGKILL})" in results[0].message
    assert results[0].node == socket.gethostname() and not results[0].rerun  # not retried


def test_cancel_leaves_no_process(batch_plans: ModuleType, tmp_path: Path) -> None:
    before = _children()
    blocks = [tmp_path / "a.pid", tmp_path / "b.pid"]
    variants = [
        Variant("picked"),
        *(Variant(p.stem, parameters={"block_in": str(p)}) for p in blocks),
    ]
    run = project_variants(variants, plan=batch_plans.pick_or_block, workers=2)
    first = next(run)
    assert first.name == "picked" and first.succeeded
    batch_plans.wait_for(blocks)  # both workers are now busy in a variant that never ends
    workers = run.worker_pids()
    assert len(workers) == 2 and set(workers) <= _children()
    for pid in workers:  # one BLAS thread each: the workers share the cores
        assert psutil.Process(pid).environ().get("OPENBLAS_NUM_THREADS") == os.environ.get(
            "OPENBLAS_NUM_THREADS", "1"
        )
    run.cancel()
    assert _children() <= before
    assert list(run) == []


def test_ctrl_c_leaves_no_process(batch_plans: ModuleType, tmp_path: Path) -> None:
    before = _children()
    blocks = [tmp_path / "a.pid", tmp_path / "b.pid"]
    variants = [Variant(p.stem, parameters={"block_in": str(p)}) for p in blocks]

    def interrupt() -> None:
        batch_plans.wait_for(blocks)
        os.kill(os.getpid(), signal.SIGINT)

    interrupter = threading.Thread(target=interrupt)
    interrupter.start()
    with pytest.raises(KeyboardInterrupt):
        list(project_variants(variants, plan=batch_plans.pick_or_block, workers=2))
    interrupter.join()
    assert _children() <= before


def test_results_land_in_the_trace_store(tmp_path: Path) -> None:
    path = tmp_path / "batch.db"
    variants = [Variant("ok"), Variant("toaster", parameters={"object_type": "toaster"})]
    results = project_variants(variants, workers=2, traces=path).collect()
    assert [r.status for r in results] == [VariantStatus.SUCCEEDED, VariantStatus.FAILED]
    with TraceDatabase(path, create=False) as db:
        stored = {run.id: run for run in runs(db)}
    ok, toaster = (stored[r.run_id] for r in results if r.run_id is not None)
    assert (ok.status, toaster.status) == ("succeeded", "failed")
    assert ok.world_states > 3 and toaster.failed_tasks >= 1


def test_bad_input_names_the_culprit() -> None:
    with pytest.raises(UnknownBackend, match="'dask'.*processes"):
        project_variants([Variant("a")], backend="dask")
    with pytest.raises(BatchError, match="workers=0"):
        project_variants([Variant("a")], workers=0)
    with pytest.raises(BatchError, match="not a Variant"):
        project_variants([{"name": "a"}])  # type: ignore[list-item]
    with pytest.raises(BatchError, match="cannot be sent to a worker.*top level"):
        project_variants([Variant("a")], plan=lambda target: target)
    with pytest.raises(BadVariant, match="jitter=-0.1"):
        Variant("a", jitter=-0.1)
    with pytest.raises(BadVariant, match=r"object_shifts\['mug-1'\]"):
        Variant("a", object_shifts={"mug-1": (0.0, 1.0)})
    assert Variant("a", parameters={"b": 1, "a": 2}).parameters == (("a", 2), ("b", 1))


def test_a_worker_hides_what_it_keeps_from_the_collector_and_exits_cleanly(
    capfd: pytest.CaptureFixture[str],
) -> None:
    """A worker freezes what its first variant built (the collector's full passes walked it
    for nothing) and unfreezes it on the way out: its results are those of the same
    variants run in this process (no freeze here), and no binding reports leaked objects."""
    variants = [Variant("a"), Variant("b", seed=2), Variant("c", seed=3)]
    results = project_variants(variants, workers=1).collect()
    assert [r.status for r in results] == [VariantStatus.SUCCEEDED] * 3
    assert len({r.worker for r in results}) == 1
    runner = VariantRunner(WorkerConfig(pick_up, tabletop_scene, "pr2"))
    here = [runner.run(k, v) for k, v in enumerate(variants)]
    assert [r.outcome() for r in results] == [r.outcome() for r in here]
    assert "leaked" not in capfd.readouterr().err
