"""How fast the trace audit (``audit_runs``) replays a fixed set of stored runs, and what
it finds there, so a change to the audit's speed can be timed and its report diffed.

The runs are traced once into SQLite stores under ``FOLDER`` (kept: later calls reuse
them): a PR2 kitchen mug transport, the PR2's breakfast spoon set and cleared (the
drawer carried by the hand), and the PR2 opening and closing the fridge's door. Each
store is audited ``REPEATS`` times with the default bounds and once with every depth
bound at zero (every touching pair a finding: depths to compare); the CPU time
(``time.process_time``: PyBullet runs in this process) of the default audit is the
median of the repeats. Every finding's line is printed with its depth in full.

Usage: python benchmarks/audit_speed_bench.py [FOLDER] [REPEATS]
(default /tmp/audit_speed_bench, 3)
"""

from __future__ import annotations

import statistics
import sys
import time
import warnings
from collections.abc import Callable
from pathlib import Path

from robocram.designators import a, an
from robocram.plans import perform
from robocram.plans.container_access import close_again, open_from_front
from robocram.plans.table_arrangement import Setting
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import AuditReport
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import World

STRICT = AuditBounds(penetration=0.0, held_depth=0.0)  # every contact a finding


def _kitchen_mug(db: Path) -> None:
    scene = kitchen_scene("pr2")
    with trace_to(db, world=scene.world), simulated_robot(scene.world, scene.robot):
        transport("mug", a.location(on=("kitchen", "table_top"), for_="mug-1"))
    scene.world.close()


def _breakfast_spoon(db: Path) -> None:
    scene = breakfast_scene("pr2")
    with trace_to(db, world=scene.world), simulated_robot(scene.world, scene.robot):
        perform(
            an.action(type="setting-table", people=1, setting=(Setting("spoon", 0.2, 0.21),),
                      shared=())
        )  # fmt: skip
        perform(an.action(type="clearing-table"))
    scene.world.close()


def _fridge_door(db: Path) -> None:
    scene = breakfast_scene("pr2")
    world: World = scene.world
    with trace_to(db, world=world), simulated_robot(world, scene.robot):
        close_again(open_from_front("fridge_body"))
    world.close()


RUNS: dict[str, Callable[[Path], None]] = {
    "pr2-kitchen-mug": _kitchen_mug,
    "pr2-breakfast-spoon": _breakfast_spoon,
    "pr2-fridge-door": _fridge_door,
}


def _audited(db: Path, bounds: AuditBounds | None) -> tuple[AuditReport, float]:
    with TraceDatabase(db, create=False) as opened:
        start = time.process_time()
        report = audit_runs(opened, bounds=bounds)
        return report, time.process_time() - start


def _print_report(label: str, report: AuditReport) -> None:
    print(f"  {label}: {report.trajectories} trajectories, {report.configurations} "
          f"configurations, {len(report.findings)} finding(s)")  # fmt: skip
    for f in report.findings:
        print(f"    {f.line()} amount={f.amount!r} time={f.time!r}")


def main(folder: Path, repeats: int) -> None:
    warnings.simplefilter("ignore")
    folder.mkdir(parents=True, exist_ok=True)
    total = 0.0
    for name, make in RUNS.items():
        db = folder / f"{name}.db"
        if not db.exists():
            traced = time.perf_counter()
            make(db)
            print(f"{name}: traced in {time.perf_counter() - traced:.0f} s")
        times = []
        for _ in range(repeats):
            report, cpu = _audited(db, None)
            times.append(cpu)
        strict, _ = _audited(db, STRICT)
        median = statistics.median(times)
        total += median
        print(f"{name}: audit CPU median {median:.2f} s of {', '.join(f'{t:.2f}' for t in times)}")
        _print_report("default bounds", report)
        _print_report("depths at zero", strict)
    print(f"audit_speed_bench: {total:.2f} s CPU in all (medians)")


if __name__ == "__main__":
    main(
        Path(sys.argv[1]) if len(sys.argv) > 1 else Path("/tmp/audit_speed_bench"),
        int(sys.argv[2]) if len(sys.argv) > 2 else 3,
    )
