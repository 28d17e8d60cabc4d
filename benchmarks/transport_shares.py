"""Where a cold PR2 transport's CPU goes, by purpose, sampled (issue 40's ~140 ms).

A CPU timer (``ITIMER_PROF``, every 0.5 ms of process CPU) samples the Python stack of
the timed transports, as ``prolog_share`` does; each sample goes to the first purpose of
:data:`PURPOSES` whose pattern some frame of its stack matches (so IK's own collision
tests count as IK, a corner blend's checks as path checks). Native work (PyBullet, coal,
numpy) counts for the Python frame that called it. A second table splits the same samples
by the folder of their innermost robocram frame: the kind of code that ran. Samples are
weighed by the CPU used since the one before (a long native call delivers one signal for
several timer periods: a plain count would tilt towards Python); the milliseconds are each
share times the mean CPU of the timed transports. Each run builds a fresh kitchen and times
one transport, as ``cold_transport`` does; the process's first transport is not sampled.
Usage: python benchmarks/transport_shares.py [RUNS]
"""

from __future__ import annotations

import re
import statistics
import sys
import time
from collections import Counter
from types import FrameType

from sampled_transports import sampled_transports

# (purpose, pattern over the stack's "folder/file.py:qualname" frames), first match wins
PURPOSES = (
    ("physics steps (settling)", r"world_tables\.py:WorldTables\.step\b"),
    (
        "IK (its collision tests included)",
        r"kinematics/(solve_ik|ik_solver|descent)\.py|:solve_at_stand\b",
    ),
    (
        "collision checks of arm paths",
        r"motion/(segment_check|self_path_check|coal_clearance|clearance_pairs|coal_self_distances)\.py"
        r"|:_blend_free\b|:_checked_path\b|cartesian_path\.py:follow_poses\b",
    ),
    ("trajectory timing", r"motion/(time_parameterization|corner_blend|jerk_profile)\.py"),
    ("Prolog", r"<robocram clause>|robocram/logic/"),
    ("looking and perceiving", r"projection/(perception|neck)\.py|world/(view|visibility)\.py"),
    (
        "base planning and driving",
        r"motion/(base_path|base_collision)\.py|projection/navigation\.py",
    ),
    ("stand search (costmaps)", r"robocram/costmaps/"),
    ("designators", r"robocram/designators/"),
    ("world queries and writes", r"robocram/world/"),
)
REST = "the rest (plans, execution, projection)"


class Sampler:
    """Counts the samples of each purpose and innermost folder while `on`."""

    def __init__(self) -> None:
        self.on = False
        self.purposes: Counter[str] = Counter()  # CPU seconds, as the folders
        self.folders: Counter[str] = Counter()
        self.last = 0.0  # process CPU at the last sample (or at `on`)
        self._patterns = [(name, re.compile(rx)) for name, rx in PURPOSES]

    def start(self) -> None:
        self.on, self.last = True, time.process_time()

    def stop(self) -> None:
        self.on = False

    def sample(self, signum: int, frame: FrameType | None) -> None:
        if not self.on:
            return
        now = time.process_time()  # a long native call merges its timer signals into one:
        weight, self.last = now - self.last, now  # weigh each sample by the CPU since the last
        frames: list[str] = []
        while frame is not None:
            code = frame.f_code
            frames.append(f"{code.co_filename}:{code.co_qualname}")
            frame = frame.f_back
        inner = next((f for f in frames if "/robocram/" in f or "<robocram" in f), "")
        self.folders[_folder(inner)] += weight
        stack = "\n".join(frames)
        purpose = next((name for name, rx in self._patterns if rx.search(stack)), REST)
        self.purposes[purpose] += weight


def _folder(frame: str) -> str:
    """The robocram folder of a ``file:qualname`` frame ('logic' for generated clauses)."""
    if frame.startswith("<robocram"):
        return "logic"
    path = frame.split("/robocram/", 1)[-1].split(":", 1)[0]
    return path.rsplit("/", 1)[0] if "/" in path else path or "outside robocram"


def _table(title: str, counts: Counter[str], mean: float) -> None:
    """``counts`` as shares and as milliseconds of the ``mean`` transport."""
    total = sum(counts.values())
    print(f"  {title}:")
    for name, count in counts.most_common():
        print(f"    {count / total * 100:5.1f} %  {count / total * mean:5.1f} ms  {name}")


def main(runs: int) -> None:
    sampler = Sampler()
    cpu = sampled_transports(sampler, runs)
    mean = statistics.mean(cpu)
    print(f"pr2 cold transport: CPU mean {mean:.1f} ms, median {statistics.median(cpu):.1f} ms")
    print(f"  {sum(sampler.purposes.values()):.2f} s of CPU sampled over {runs} transports")
    _table("by purpose (first match of the stack)", sampler.purposes, mean)
    _table("by the innermost robocram frame's folder", sampler.folders, mean)


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    main(int(args[0]) if args else 20)
