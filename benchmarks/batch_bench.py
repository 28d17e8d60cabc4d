"""Batch projection throughput: the tabletop pick-up over N mug placements, 1 and 2 workers.

Prints variants/s over the whole batch (worker start and scene build included) and after
the first result (steady state), the speed-up of 2 workers over 1 (issue 14's goal: >= 1.8x
on this 2-core machine), the time to the first result and each worker's memory (RSS, peak
seen while sampling). No reference system: CRAM and PyCRAM project one world in one process.
Usage: python benchmarks/batch_bench.py [--variants 40] [--robot pr2]
"""

from __future__ import annotations

import argparse
import time
from dataclasses import dataclass

import psutil

from robocram.batch import Variant, project_variants


@dataclass(frozen=True)
class Figures:
    workers: int
    total: float  # [s]
    first: float  # [s] until the first result
    last_minus_first: float  # [s]
    count: int
    succeeded: int
    rss: dict[int, float]  # worker pid -> peak resident memory seen [MB]


def variants(count: int) -> list[Variant]:
    """Mug placements on a 5 cm grid around the scene's, each with its own seed."""
    return [
        Variant(
            f"mug{i}",
            object_shifts={"mug-1": (0.03 * (i % 3) - 0.03, 0.02 * (i // 3 % 10) - 0.1, 0.0)},
            look_at="mug-1",
            seed=i,
        )
        for i in range(count)
    ]


def measure(batch: list[Variant], workers: int, robot: str) -> Figures:
    """Run the batch once, sampling the workers' memory at every result."""
    rss: dict[int, float] = {}
    start = time.perf_counter()
    stamps: list[float] = []
    succeeded = 0
    run = project_variants(batch, robot=robot, workers=workers)
    for result in run:
        stamps.append(time.perf_counter() - start)
        succeeded += result.succeeded
        for pid in run.worker_pids():
            try:
                mb = psutil.Process(pid).memory_info().rss / 2**20
            except psutil.NoSuchProcess:
                continue
            rss[pid] = max(rss.get(pid, 0.0), mb)
    total = time.perf_counter() - start
    return Figures(workers, total, stamps[0], stamps[-1] - stamps[0], len(stamps), succeeded, rss)


def report(f: Figures) -> None:
    steady = (f.count - f.workers) / f.last_minus_first if f.last_minus_first > 0 else 0.0
    memory = ", ".join(f"{mb:.0f}" for mb in f.rss.values())
    print(
        f"{f.workers} worker(s): {f.count / f.total:6.2f} variants/s overall "
        f"({f.total:.1f} s, {f.succeeded}/{f.count} picked), {steady:6.2f} variants/s after "
        f"the first result, first result after {f.first:.1f} s, worker RSS [MB]: {memory}"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--variants", type=int, default=40)
    parser.add_argument("--robot", default="pr2")
    args = parser.parse_args()
    batch = variants(args.variants)
    print(f"batch projection: {args.variants} tabletop pick-up variants, {args.robot}, "
          f"{psutil.cpu_count()} cores, load {psutil.getloadavg()[0]:.1f}")  # fmt: skip
    one = measure(batch, 1, args.robot)
    report(one)
    two = measure(batch, 2, args.robot)
    report(two)
    steady_one = (one.count - 1) / one.last_minus_first
    steady_two = (two.count - 2) / two.last_minus_first
    print(
        f"speed-up 2 vs 1 workers: {one.total / two.total:.2f}x overall, "
        f"{steady_two / steady_one:.2f}x after the first result (goal >= 1.8x)"
    )


if __name__ == "__main__":
    main()
