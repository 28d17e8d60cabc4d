"""Batch projection throughput: a tabletop pick-up and 0.5 s of simulation per variant, over
N mug placements, on 1 and 2 spawned processes and on 1 and 2 Ray actors.

Prints variants/s over the whole batch (worker start and scene build included) and after
the first result (steady state), the speed-up of 2 workers over 1 (issue 14's goal: >= 1.8x
on a 2-core machine), the time to the first result and each worker's memory (RSS, peak seen
while sampling), and the CPU load average: on a machine others are using the speed-up is
lower; rerun on an idle one. Ray's own start-up is timed apart (it is started once, as a
user would). No reference system: CRAM and PyCRAM project one world in one process.
Each figure is the fastest of ``--rounds`` runs, alternating which worker count goes first,
so load from other processes biases neither. Workers run one BLAS thread each.
Usage: python benchmarks/batch_bench.py [--variants 40] [--rounds 2] [--robot pr2] [--no-ray]
"""

from __future__ import annotations

import argparse
import os
import time
from dataclasses import dataclass

import psutil
from settle_plan import pick_and_settle

from robocram.batch import Variant, project_variants


@dataclass(frozen=True)
class Figures:
    backend: str
    workers: int
    total: float  # [s]
    first: float  # [s] until the first result
    last_minus_first: float  # [s]
    count: int
    succeeded: int
    rss: dict[int, float]  # worker pid -> peak resident memory seen [MB]

    @property
    def steady(self) -> float:
        """Variants/s after the first result (the workers' start-up left out)."""
        done = self.count - self.workers
        return done / self.last_minus_first if self.last_minus_first > 0 and done > 0 else 0.0


def variants(count: int) -> list[Variant]:
    """Mug placements on a grid around the scene's, each with its own seed."""
    return [
        Variant(
            f"mug{i}",
            object_shifts={"mug-1": (0.03 * (i % 3) - 0.03, 0.02 * (i // 3 % 10) - 0.1, 0.0)},
            look_at="mug-1",
            seed=i,
        )
        for i in range(count)
    ]


def _sample_rss(pids: list[int], rss: dict[int, float]) -> None:
    for pid in pids:
        try:
            mb = psutil.Process(pid).memory_info().rss / 2**20
        except psutil.NoSuchProcess:
            continue
        rss[pid] = max(rss.get(pid, 0.0), mb)


def measure(batch: list[Variant], backend: str, workers: int, robot: str) -> Figures:
    """Run the batch once, sampling the workers' memory at every result."""
    rss: dict[int, float] = {}
    stamps: list[float] = []
    succeeded = 0
    start = time.perf_counter()
    run = project_variants(
        batch, plan=pick_and_settle, robot=robot, workers=workers, backend=backend
    )
    for result in run:
        stamps.append(time.perf_counter() - start)
        succeeded += result.succeeded
        _sample_rss(run.worker_pids(), rss)
    total = time.perf_counter() - start
    return Figures(
        backend, workers, total, stamps[0], stamps[-1] - stamps[0], len(stamps), succeeded, rss
    )


def report(f: Figures) -> None:
    memory = ", ".join(f"{mb:.0f}" for mb in f.rss.values())
    print(
        f"{f.backend:>9} x{f.workers}: {f.count / f.total:5.2f} variants/s overall "
        f"({f.total:5.1f} s, {f.succeeded}/{f.count} picked), {f.steady:5.2f} variants/s "
        f"after the first result, first result after {f.first:4.1f} s, "
        f"worker RSS [MB]: {memory}  (load {os.getloadavg()[0]:.1f})",
        flush=True,
    )


def compare(backend: str, batch: list[Variant], robot: str, rounds: int) -> None:
    """1 and 2 workers, alternating which runs first each round; the fastest run of each."""
    runs: dict[int, list[Figures]] = {1: [], 2: []}
    for r in range(rounds):
        for workers in (1, 2) if r % 2 == 0 else (2, 1):
            runs[workers].append(measure(batch, backend, workers, robot))
    one, two = (min(runs[w], key=lambda f: f.total) for w in (1, 2))
    report(one)
    report(two)
    print(
        f"{backend:>9}: speed-up 2 vs 1 workers {one.total / two.total:.2f}x overall, "
        f"{two.steady / one.steady if one.steady else 0.0:.2f}x after the first result "
        f"(best of {rounds} rounds; goal >= 1.8x on an idle 2-core machine)",
        flush=True,
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", type=int, default=40)
    parser.add_argument("--robot", default="pr2")
    parser.add_argument("--rounds", type=int, default=2, help="runs of each, fastest kept")
    parser.add_argument("--no-ray", action="store_true", help="only the process backend")
    args = parser.parse_args()
    batch = variants(args.variants)
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(
        f"batch projection: {args.variants} variants (pick-up + 0.5 s simulated), {args.robot}, "
        f"{psutil.cpu_count()} cores, load average {load} (1, 5, 15 min); the lead reruns "
        "this on an idle machine",
        flush=True,
    )
    compare("processes", batch, args.robot, args.rounds)
    if args.no_ray:
        return
    import ray

    start = time.perf_counter()
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    print(f"ray: local start-up {time.perf_counter() - start:.1f} s (not counted below)")
    try:
        compare("ray", batch, args.robot, args.rounds)
    finally:
        ray.shutdown()


if __name__ == "__main__":
    main()
