"""Start-up of the ``robocram`` command: what a user waits for before anything happens.

Run: ``.venv/bin/python benchmarks/cli_bench.py [DB]``. Prints the median wall and CPU time
(user + system, of the child process) of 10 fresh processes each for ``robocram --help`` and
``robocram runs list DB``. Without DB, a small trace database is recorded first with
``robocram demo --db`` (not timed). Goal (issue 27): ``--help`` <= 0.3 s.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPEATS = 10
COMMAND = [sys.executable, "-m", "robocram.cli"]


def timed(args: list[str]) -> tuple[float, float]:
    """Wall and CPU time [s] of one fresh ``robocram ARGS`` process."""
    before = os.times()
    start = time.perf_counter()
    subprocess.run([*COMMAND, *args], check=True, capture_output=True)
    wall = time.perf_counter() - start
    after = os.times()
    cpu = (after.children_user - before.children_user) + (
        after.children_system - before.children_system
    )
    return wall, cpu


def report(label: str, args: list[str]) -> None:
    """Print the medians over :data:`REPEATS` fresh processes."""
    samples = [timed(args) for _ in range(REPEATS)]
    wall = statistics.median(s[0] for s in samples)
    cpu = statistics.median(s[1] for s in samples)
    print(f"{label:<24} wall {wall * 1e3:7.0f} ms   cpu {cpu * 1e3:7.0f} ms  (median of {REPEATS})")


def small_database(directory: Path) -> Path:
    """A trace database holding one run of the tabletop demo."""
    db = directory / "runs.db"
    subprocess.run([*COMMAND, "demo", "--db", str(db)], check=True, capture_output=True)
    return db


def main(argv: list[str]) -> None:
    """Time ``--help`` and ``runs list``; print load so figures can be compared."""
    print(f"load average {os.getloadavg()[0]:.2f}, {os.cpu_count()} cores")
    report("robocram --help", ["--help"])
    with tempfile.TemporaryDirectory() as tmp:
        db = Path(argv[0]) if argv else small_database(Path(tmp))
        report("robocram runs list DB", ["runs", "list", str(db)])


if __name__ == "__main__":
    main(sys.argv[1:])
