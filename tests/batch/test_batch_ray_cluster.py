"""Batch projection on a real Ray cluster on this machine (``ray start --head`` plus ``ray
start --address``, separate raylets of one CPU each), losing a node mid-batch: its variant
runs again on the node that remains and the batch finishes; with no node left, the command
prints what finished and exits 1.

The doomed node's raylet is SIGKILLed while one of its actors runs a variant. The module's
tests share one head, which runs no actor (starting one takes seconds); each test adds its
worker nodes, and the next test starts once the head has declared them dead.
"""

from __future__ import annotations

import importlib
import json
import sys
import threading
from collections import Counter
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import TYPE_CHECKING

import pytest
import ray

from robocram.batch import BackendMissing, Variant, VariantStatus, project_variants
from robocram.cli import EXIT_FAILED, main

if TYPE_CHECKING:
    from ray_cluster import LocalCluster


@pytest.fixture(scope="module")
def head() -> Iterator[LocalCluster]:
    """The module's cluster: a head with no CPU for actors; every node killed after."""
    if ray.is_initialized():  # a Ray left running would be used instead of RAY_ADDRESS's
        ray.shutdown()
    sys.path.insert(0, str(Path(__file__).resolve().parent))  # ray_cluster.py, beside this
    try:
        made: LocalCluster = importlib.import_module("ray_cluster").LocalCluster()
    finally:
        sys.path.pop(0)
    try:
        made.start_head(cpus=0)
        yield made
    finally:
        if ray.is_initialized():
            ray.shutdown()
        made.stop()


@pytest.fixture
def cluster(
    head: LocalCluster, batch_plans: ModuleType, monkeypatch: pytest.MonkeyPatch
) -> Iterator[LocalCluster]:
    """The head with no worker node (an earlier test's removed, and declared dead by the
    head), its address in ``RAY_ADDRESS``."""
    if head.has_nodes:
        ray.init(address=head.address, log_to_driver=False)
        try:
            head.remove_nodes(lambda: sum(bool(node["Alive"]) for node in ray.nodes()))
        finally:
            ray.shutdown()
    monkeypatch.setenv("RAY_ADDRESS", head.address)
    try:
        yield head
    finally:
        if ray.is_initialized():
            ray.shutdown()


def _kill_when_blocked(cluster: LocalCluster, node: str, block_dir: Path) -> threading.Thread:
    """Start a thread that kills ``node`` once a variant blocked on it."""
    plans = sys.modules["batch_plans"]

    def kill() -> None:
        pid_file = block_dir / plans.BLOCKED
        plans.wait_for([pid_file])
        if pid_file.exists():
            cluster.kill_node(node)

    killer = threading.Thread(target=kill)
    killer.start()
    return killer


def test_a_lost_node_s_variant_runs_again_and_the_batch_finishes(
    cluster: LocalCluster, batch_plans: ModuleType, tmp_path: Path
) -> None:
    _, doomed = cluster.add_nodes([{}, {batch_plans.DOOMED_ENV: "doomed"}])  # one survives
    variants = [
        Variant(
            f"mug{i}",
            object_shifts={"mug-1": (0.0, 0.02 * (i % 4), 0.0)},
            look_at="mug-1",
            parameters={"block_dir": str(tmp_path), "runs_before": 1},
        )
        for i in range(10)
    ]
    killer = _kill_when_blocked(cluster, doomed, tmp_path)
    run = project_variants(variants, batch_plans.pick_unless_doomed, backend="ray", workers=2)
    results = run.collect()
    killer.join()
    assert [r.name for r in results] == [v.name for v in variants]  # one result each
    assert [r.status for r in results] == [VariantStatus.SUCCEEDED] * 10
    (rerun,) = [r for r in results if r.rerun]  # the one in flight on the lost node
    per_node = Counter(r.node for r in results)
    assert sorted(per_node.values()) == [1, 9]  # one ran on the doomed node before it died
    (survivor,) = [node for node, count in per_node.items() if count == 9]
    assert rerun.node == survivor and len(survivor) == 56  # a Ray node id, in hex


def test_a_lost_cluster_ends_the_command_with_what_finished(
    cluster: LocalCluster,
    batch_plans: ModuleType,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    doomed = cluster.add_node(  # the head runs no actor: the doomed node is the only one
        **{batch_plans.DOOMED_ENV: "doomed"}
    )
    block_dir = tmp_path / "blocks"
    block_dir.mkdir()
    spec = tmp_path / "spec.json"
    parameters = {"block_dir": str(block_dir), "runs_before": 1}
    variants = [{"name": f"v{i}", "parameters": parameters} for i in range(4)]
    plan = "batch_plans:pick_unless_doomed"
    spec.write_text(json.dumps({"plan": plan, "variants": variants}), encoding="utf-8")
    killer = _kill_when_blocked(cluster, doomed, block_dir)
    code = main(["batch", str(spec), "--backend", "ray", "--workers", "1"])
    killer.join()
    out = capsys.readouterr().out
    assert code == EXIT_FAILED
    counts = {line[:26].strip(): line[26:].split()[:1] for line in out.splitlines()}
    assert counts["variants"] == ["4"] and counts["succeeded"] == ["1"]
    assert counts["lost"] == ["3"]  # the one lost with the node, and the two not run
    causes = out.split("variants that did not succeed, by cause:\n")[1].splitlines()
    assert causes[0].split()[:4] == ["2", "NoWorkerLeft:", "not", "run:"]
    assert causes[1].split() == ["v2", "v3"]
    assert causes[2].split()[:2] == ["1", "NoWorkerLeft:"] and "lost with" in causes[2]
    assert causes[3].split() == ["v1"]  # the one its actor held when the node was killed


def test_a_ray_client_address_without_the_client_says_how(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    if ray.is_initialized():
        ray.shutdown()
    monkeypatch.setenv("RAY_ADDRESS", "ray://head-node:10001")
    monkeypatch.setitem(sys.modules, "grpc", None)  # what `import grpc` meets when missing
    with pytest.raises(BackendMissing, match=r"needs 'ray\[client\]'.*robocram\[ray\]"):
        project_variants([Variant("a")], backend="ray").collect()
