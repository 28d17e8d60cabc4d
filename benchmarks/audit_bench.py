"""What the independent audit finds in the runs issue 35 names: kitchen transports (the
mug from the counter, the bowl from its drawer) of the PR2, HSR and Boxy and of the
drafted Fetch and Stretch, and seeded cluttered-counter transports of the PR2 (2 to 4
boxes round the mug, none within 12 cm of it, nor within 1 cm of
the mug or another box: a box drawn into the mug's handle is drawn again).

Each run is traced into a fresh SQLite store and replayed by ``robocram runs audit``'s
code (raw PyBullet queries, none of the planner's checks). A failed transport is listed
with its error; its trajectories up to the failure are audited too.
Usage: python benchmarks/audit_bench.py [cluttered variants]   (default 30)
"""

from __future__ import annotations

import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from robocram.designators import a
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import KitchenScene, kitchen_scene
from robocram.tf import Pose
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_findings import AuditReport
from robocram.traces.trajectory_audit import audit_runs

DATA = Path(__file__).resolve().parents[1] / "tests" / "data"
ROBOTS = (
    "pr2",
    "hsrb",
    "boxy",
    str(DATA / "fetch" / "fetch.py"),
    str(DATA / "stretch" / "stretch.py"),
)
ITEMS = ("mug", "bowl")
MUG = (-1.25, 2.11, 0.85)  # [m] where the kitchen puts mug-1 (its base, on the counter)


def _cluttered(seed: int) -> KitchenScene:
    """The PR2 kitchen with 2 to 4 seeded boxes on the counter round the mug."""
    scene = kitchen_scene("pr2")
    rng = np.random.default_rng(seed)
    for k in range(int(rng.integers(2, 5))):
        while True:
            dx, dy = rng.uniform(-0.45, 0.45), rng.uniform(-0.2, 0.15)
            size = (rng.uniform(0.04, 0.12), rng.uniform(0.04, 0.12), rng.uniform(0.05, 0.25))
            where = (MUG[0] + dx, MUG[1] + dy, MUG[2] + size[2] / 2 + 0.002)
            if abs(dx) > 0.12 or abs(dy) > 0.12:
                scene.world.add_box(f"clutter-{k}", size, Pose(where))
                near = ["mug-1", *(f"clutter-{j}" for j in range(k))]
                if not any(scene.world.contacts.contact_points(f"clutter-{k}", o, distance=0.01)
                           for o in near):  # fmt: skip
                    break  # a box clear of the mug and of the boxes before it
                scene.world.remove(f"clutter-{k}")
    return scene


def _run(scene: KitchenScene, item: str, db: Path) -> str:
    """Transport ``item`` to the table, traced into ``db``; '' or the error's name."""
    try:
        with trace_to(db, world=scene.world), simulated_robot(scene.world, scene.robot):
            transport(item, a.location(on=("kitchen", "table_top"), for_=f"{item}-1"))
        return ""
    except Exception as err:  # the run is audited whatever ended it
        return type(err).__name__
    finally:
        scene.world.close()


def _audit(label: str, db: Path, outcomes: list[str]) -> AuditReport:
    with TraceDatabase(db, create=False) as opened:
        report = audit_runs(opened)
    failed = [o for o in outcomes if o]
    print(f"{label}: {len(outcomes) - len(failed)}/{len(outcomes)} transports succeed"
          f"{' (' + ', '.join(failed) + ')' if failed else ''}; "
          f"{report.trajectories} trajectories, {report.configurations} configurations, "
          f"{len(report.findings)} finding(s)")  # fmt: skip
    for line in report.summary_lines()[1:]:
        print(f"  {line.strip()}")
    return report


def main(cluttered: int = 30) -> None:
    warnings.simplefilter("ignore")  # the drafted robots' missing meshes
    start = time.perf_counter()
    total = 0
    with tempfile.TemporaryDirectory() as folder:
        for robot in ROBOTS:
            db = Path(folder) / f"{Path(robot).stem}.db"
            outcomes = [_run(kitchen_scene(robot), item, db) for item in ITEMS]
            total += len(_audit(f"{Path(robot).stem} kitchen", db, outcomes).findings)
        db = Path(folder) / "cluttered.db"
        outcomes = [_run(_cluttered(seed), "mug", db) for seed in range(cluttered)]
        total += len(_audit(f"pr2 cluttered x{cluttered}", db, outcomes).findings)
    print(f"audit_bench: {total} finding(s) in all, {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 30)
