"""Whether two versions project the same kitchen transports, bit for bit.

``record`` traces kitchen transports into fresh SQLite stores with this checkout's code and
writes every stored trajectory (joint names, times, positions, velocities, accelerations,
allowed contacts, carried joints: the exact bytes) and every variant's result to a file:
``variants`` seeded variants of examples/batch_kitchen.yaml (the batch worker's runner, one
process), then the mug and the bowl transports of the PR2, HSR and Boxy. ``compare`` reads
two such files and names every trajectory or result that differs (exit 1 if any).

An optimisation of projection must leave them identical: run ``record`` on the old and the
new checkout (``PYTHONPATH=<checkout>/src``), then ``compare``.
Usage: python benchmarks/trajectory_identity.py record OUT.pkl [variants]   (default 20)
       python benchmarks/trajectory_identity.py compare OLD.pkl NEW.pkl
"""

from __future__ import annotations

import pickle
import sys
import tempfile
import warnings
from pathlib import Path

import numpy as np
from sqlalchemy import select

import robocram
from robocram.batch.batch_spec import load_spec
from robocram.batch.worker import VariantRunner, WorkerConfig
from robocram.designators import a
from robocram.plans.transport import transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.schema import TrajectoryRow

ROBOTS = ("pr2", "hsrb", "boxy")
ITEMS = ("mug", "bowl")
FIELDS = ("run", "sequence", "robot", "kind", "joints", "times", "positions", "velocities",
          "accelerations", "allowed contacts", "carried")  # fmt: skip
Row = tuple[object, ...]


def _rows(db: Path) -> list[Row]:
    """Every stored trajectory of ``db`` in store order, its fields as stored (no clock)."""
    with TraceDatabase(db, create=False) as opened, opened.read() as session:
        found = session.scalars(select(TrajectoryRow).order_by(TrajectoryRow.id)).all()
        return [(r.run_id, r.sequence, r.robot, r.kind, r.joint_names, r.times, r.positions,
                 r.velocities, r.accelerations, r.allowed_contacts, r.carried)
                for r in found]  # fmt: skip


def _batch(folder: Path, count: int) -> tuple[list[Row], list[Row]]:
    """The kitchen batch's variants, traced: their results and trajectories."""
    spec_file = Path(robocram.__file__).resolve().parents[2] / "examples" / "batch_kitchen.yaml"
    path = folder / "spec.yaml"
    path.write_text(spec_file.read_text().replace("variants: 4", f"variants: {count}"))
    spec = load_spec(path)
    db = folder / "batch.db"
    runner = VariantRunner(WorkerConfig(spec.plan, spec.scene, spec.robot, traces=db))
    results: list[Row] = []
    for k, variant in enumerate(spec.variants):
        r = runner.run(k, variant)
        results.append((r.name, r.status.name, r.failure_type, r.message, r.arm, r.grasp,
                        r.grasp_frame, r.grasp_name, r.locations))  # fmt: skip
    return results, _rows(db)


def _transport(folder: Path, robot: str, item: str) -> tuple[str, list[Row]]:
    """One kitchen transport of ``item`` by ``robot``, traced: its outcome, trajectories."""
    db = folder / f"{robot}-{item}.db"
    scene = kitchen_scene(robot)
    outcome = ""
    try:
        with trace_to(db, world=scene.world), simulated_robot(scene.world, scene.robot):
            transport(item, a.location(on=("kitchen", "table_top"), for_=f"{item}-1"))
    except Exception as err:  # a failure is part of the result
        outcome = f"{type(err).__name__}: {err}"
    finally:
        scene.world.close()
    return outcome, _rows(db)


def record(out: Path, count: int) -> None:
    warnings.simplefilter("ignore")
    data: dict[str, object] = {}
    with tempfile.TemporaryDirectory() as folder:
        data["batch"] = _batch(Path(folder), count)
        for robot in ROBOTS:
            for item in ITEMS:
                data[f"{robot}-{item}"] = _transport(Path(folder), robot, item)
    out.write_bytes(pickle.dumps(data))
    trajectories = sum(len(v[1]) for v in data.values())  # type: ignore[index, arg-type]
    print(f"trajectory_identity: {count} variants and {len(data) - 1} transports, "
          f"{trajectories} trajectories recorded to {out}")  # fmt: skip


def _differences(key: str, old: list[Row], new: list[Row]) -> list[str]:
    found = [f"{key}: {len(old)} trajectories, then {len(new)}"] if len(old) != len(new) else []
    for x, y in zip(old, new, strict=False):
        if x != y:
            fields = [name for name, u, v in zip(FIELDS, x, y, strict=True) if u != v]
            line = f"{key} run {x[0]} trajectory {x[1]} ({x[3]}): {', '.join(fields)} differ"
            if "positions" in fields and len(x[6]) == len(y[6]):  # type: ignore[arg-type]
                dq = np.frombuffer(x[6], "<f8") - np.frombuffer(y[6], "<f8")  # type: ignore[arg-type]
                line += f" (largest {np.abs(dq).max():.3g})"
            found.append(line)
    return found


def compare(old_file: Path, new_file: Path) -> int:
    old, new = pickle.loads(old_file.read_bytes()), pickle.loads(new_file.read_bytes())
    if old.keys() != new.keys():
        print(f"different runs: {sorted(old)} and {sorted(new)}")
        return 1
    found, count = [], 0
    for key in old:
        (x_result, x_rows), (y_result, y_rows) = old[key], new[key]
        if x_result != y_result:
            found.append(f"{key}: the results differ")
        found += _differences(key, x_rows, y_rows)
        count += len(x_rows)
    for line in found:
        print(line)
    print(f"trajectory_identity: {count} trajectories compared, {len(found)} difference(s)")
    return 1 if found else 0


if __name__ == "__main__":
    if sys.argv[1:2] == ["record"]:
        record(Path(sys.argv[2]), int(sys.argv[3]) if len(sys.argv) > 3 else 20)
    elif sys.argv[1:2] == ["compare"]:
        sys.exit(compare(Path(sys.argv[2]), Path(sys.argv[3])))
    else:
        sys.exit(__doc__)
