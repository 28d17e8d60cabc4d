"""Plans for the batch fault tests, imported by name in the spawned workers, and the
helpers that kill a blocked worker or wait for blocked workers."""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Callable
from pathlib import Path

from robocram.batch import Variant, VariantResult, VariantStatus, project_variants
from robocram.plans import pick_up
from robocram.tf import PoseStamped

BLOCK_LIMIT = 120.0  # [s] a blocked plan gives up after this, should a test not end it
DOOMED_ENV = "ROBOCRAM_TEST_NODE"  # "doomed" in the processes of a Ray node a test kills
BLOCKED = "blocked.pid"  # what a plan blocked on the doomed node writes its pid to


def pick_or_block(look_target: PoseStamped, block_in: str = "") -> object:
    """Pick up the mug, or (with ``block_in``) write this pid there and wait to be killed."""
    if block_in:
        _block(Path(block_in))
    return pick_up(look_target)


def pick_unless_doomed(look_target: PoseStamped, block_dir: str, runs_before: int = 1) -> object:
    """Pick up the mug; on the doomed node, the variant after ``runs_before`` others blocks
    (its pid in ``block_dir/blocked.pid``) until the node is killed, so it is lost with the
    node, and picks the mug up when run again on another node. Elsewhere a variant first
    waits until the doomed node has run one (a loaded machine could otherwise run them all
    elsewhere before the doomed node's actor starts, and nothing would be lost)."""
    if os.environ.get(DOOMED_ENV) == "doomed":
        ran = len(list(Path(block_dir).glob("ran-*")))
        if ran >= runs_before:
            _block(Path(block_dir) / BLOCKED)
        (Path(block_dir) / f"ran-{ran}").touch()
    else:
        _wait_until(lambda: any(Path(block_dir).glob("ran-*")))
    return pick_up(look_target)


def _wait_until(done: Callable[[], bool]) -> None:
    """Wait until ``done()`` (or :data:`BLOCK_LIMIT` passed)."""
    end = time.monotonic() + BLOCK_LIMIT
    while not done() and time.monotonic() < end:
        time.sleep(0.02)


def _block(pid_file: Path) -> None:
    """Write this pid to ``pid_file`` and wait to be killed (until BLOCK_LIMIT)."""
    pid_file.write_text(str(os.getpid()), encoding="utf-8")
    end = time.monotonic() + BLOCK_LIMIT
    while time.monotonic() < end:
        time.sleep(0.05)
    raise TimeoutError(f"nobody killed worker {os.getpid()} within {BLOCK_LIMIT} s")


def kill_when_written(path: Path, killed: list[int]) -> None:
    """SIGKILL the process whose pid a blocked plan writes to ``path``; note its pid."""
    wait_for([path])
    if path.exists():
        pid = int(path.read_text(encoding="utf-8"))
        os.kill(pid, signal.SIGKILL)
        killed.append(pid)


def wait_for(paths: list[Path]) -> None:
    """Wait until blocked plans wrote every file of ``paths`` (or the limit passed)."""
    end = time.monotonic() + BLOCK_LIMIT
    while not all(p.exists() and p.read_text(encoding="utf-8") for p in paths):
        if time.monotonic() > end:
            return
        time.sleep(0.02)


def run_killing_the_first(backend: str, pid_file: Path) -> tuple[list[VariantResult], int]:
    """Three variants on one worker; the first blocks and its worker is SIGKILLed.

    Checks what both backends must do: only that variant is lost, a new worker runs the
    others. Returns the results and the killed pid.
    """
    variants = [
        Variant("blocked", parameters={"block_in": str(pid_file)}),
        Variant("after-1", object_shifts={"mug-1": (0.0, 0.05, 0.0)}, look_at="mug-1"),
        Variant("after-2"),
    ]
    killed: list[int] = []
    killer = threading.Thread(target=kill_when_written, args=(pid_file, killed))
    killer.start()
    results = project_variants(variants, plan=pick_or_block, workers=1, backend=backend).collect()
    killer.join()
    statuses = [r.status for r in results]
    lost, done = VariantStatus.LOST, VariantStatus.SUCCEEDED
    if statuses != [lost, done, done] or results[0].worker != killed[0]:
        raise AssertionError(f"expected only 'blocked' lost, by worker {killed}: {results}")
    if killed[0] in (results[1].worker, results[2].worker):
        raise AssertionError(f"the killed worker {killed[0]} answered later: {results}")
    return results, killed[0]


class Unprintable(RuntimeError):
    """An error that cannot be turned into text."""

    def __str__(self) -> str:
        raise ValueError("no text")


def misbehave(look_target: PoseStamped, how: str = "") -> object:
    """Raise what ``how`` names (``exit``, ``interrupt``, ``unprintable``), else pick up."""
    if how == "exit":
        raise SystemExit(3)
    if how == "interrupt":
        raise KeyboardInterrupt
    if how == "unprintable":
        raise Unprintable
    return pick_up(look_target)
