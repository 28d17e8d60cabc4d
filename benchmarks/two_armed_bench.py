"""Breakfast for two, one-armed and two-armed, back to back: things set, drives, CPU time.

Run: ``.venv/bin/python benchmarks/two_armed_bench.py [rounds] [robots...]`` (defaults 1
and the PR2). Per robot and mode (``setting-table`` with ``two_arms`` off, then on, in
one process, alternating per round) it prints the things set of 7, the trips to the
table (the plan's ``trips``), the drives (base trajectories in the run's trace: every
drive, also to drawers and the fridge, and their path length) and the CPU time of
setting the table (median over the rounds, a fresh scene each, untraced; the drives come
from one more traced run). Figures on a loaded machine drift by 15-50 %; compare the
two modes of one run.
"""

from __future__ import annotations

import json
import statistics
import sys
import tempfile
import time
from contextlib import nullcontext
from pathlib import Path

import numpy as np
from sqlalchemy import select

from robocram.designators import an
from robocram.plans import perform
from robocram.plans.activity_failures import ActivityIncomplete
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.schema import TrajectoryRow


def _set(robot: str, two_arms: bool, trace: Path | None = None) -> tuple[int, int, float]:
    """Things set, trips to the table and CPU time [s] of one breakfast by ``robot``."""
    scene = breakfast_scene(robot)
    start = time.process_time()
    try:
        with (
            trace_to(trace, world=scene.world) if trace else nullcontext(),
            simulated_robot(scene.world, scene.robot),
        ):
            try:
                done = perform(an.action(type="setting-table", people=2, two_arms=two_arms))
                placed, trips = len(done.placed), len(done.trips)
            except ActivityIncomplete as failure:
                placed, trips = len(failure.done or ()), 0  # incomplete: not counted
        return placed, trips, time.process_time() - start
    finally:
        scene.world.close()


def _drives(robot: str, two_arms: bool) -> tuple[int, float]:
    """Base trajectories in the trace of one breakfast by ``robot``, and their length [m]
    (the base's x, y path)."""
    with tempfile.TemporaryDirectory() as folder:
        db = Path(folder) / "run.db"
        _set(robot, two_arms, db)
        with TraceDatabase(db, create=False) as opened, opened.read() as session:
            rows = session.scalars(select(TrajectoryRow).where(TrajectoryRow.kind == "base"))
            length = 0.0
            count = 0
            for row in rows:
                names = json.loads(row.joint_names)  # stored as JSON text
                points = np.frombuffer(row.positions, "<f8").reshape(-1, len(names))
                xy = points[:, [names.index("x"), names.index("y")]]
                length += float(np.linalg.norm(np.diff(xy, axis=0), axis=1).sum())
                count += 1
            return count, length


def main() -> None:
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 1
    robots = tuple(sys.argv[2:]) or ("pr2",)
    print(f"breakfast for two, one-armed vs two-armed, {rounds} round(s), CPU median")
    for robot in robots:
        runs: dict[bool, list[tuple[int, int, float]]] = {False: [], True: []}
        for _ in range(rounds):
            for two_arms in (False, True):
                runs[two_arms].append(_set(robot, two_arms))
        cpu = {mode: statistics.median(r[2] for r in runs[mode]) for mode in runs}
        for mode in (False, True):
            placed, trips, _ = runs[mode][-1]
            drives, metres = _drives(robot, mode)
            print(
                f"{robot:5s} {'two-armed' if mode else 'one-armed'}: set {placed}/7, "
                f"{f'{trips} trips to the table' if trips else 'incomplete'}, "
                f"{drives} drives ({metres:.1f} m), "
                f"CPU {cpu[mode]:.1f} s"
            )
        print(f"{robot:5s} CPU two-armed / one-armed: {cpu[True] / cpu[False]:.2f}")


if __name__ == "__main__":
    main()
