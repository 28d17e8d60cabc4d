"""``robocram demo --activity breakfast``: a robot sets the breakfast table, then clears it.

Builds the breakfast kitchen, performs ``setting-table`` for two and ``clearing-table`` as
action designators inside ``simulated_robot``, traced to a database (``--db``, else
``out/breakfast.db``), and prints the task tree: each activity one ``perform`` task, its
places, things and motions below it, as a transport shows. The picture of the set table,
``out/breakfast_set.png``, is rendered from the trace: the world rebuilt from the run's
scene and put into the state stored when the last thing of the setting was put down.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from robocram.designators import an
from robocram.execution import PlanFailure
from robocram.plans import perform
from robocram.projection import looking_orientation, simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.tf import Pose
from robocram.traces import (
    NoSceneStored,
    TraceDatabase,
    build_scene,
    require_run,
    trace_to,
    world_state_times,
)
from robocram.traces.world_record import load_world_state

ACTIVITIES = ("breakfast",)  # what --activity takes
VIEW_FROM = (1.0, -0.4, 2.2)  # [m] in map: over the table, from its north-east
VIEW_AT = (0.0, -1.4, 0.75)  # [m] in map: the table's middle
CAMERA = Pose(VIEW_FROM, looking_orientation(VIEW_FROM, VIEW_AT))
SETTING = "perform setting-table"  # the setting's task, in the trace's task paths


@dataclass(frozen=True)
class ActivityRun:
    """What the activity demo wrote and the failures of its activities (one line each)."""

    db: Path
    run: int
    picture: Path | None  # the set table, rendered from the trace (None: nothing was set)
    failures: list[str]


def run_breakfast(robot: str, db: Path, out_dir: Path, verbose: bool = False) -> ActivityRun:
    """Set the table for two and clear it again, traced to ``db``; print the task tree and
    render the set table into ``out_dir/breakfast_set.png``."""
    scene = breakfast_scene(robot)
    failures: list[str] = []
    with trace_to(db, world=scene.world) as tracer, simulated_robot(
        scene.world, scene.robot, name="breakfast"
    ) as run:  # fmt: skip
        for action, keys in (("setting-table", {"people": 2}), ("clearing-table", {})):
            try:
                perform(an.action(type=action, **keys))
            except PlanFailure as failure:
                failures.append(f"{action}: {type(failure).__name__}: {failure}")
    scene.world.close()
    print(run.tree.render(verbose=verbose))
    for line in failures:
        print(line)
    run_id = tracer.runs[-1]
    out_dir.mkdir(parents=True, exist_ok=True)
    picture = set_table_picture(db, run_id, out_dir / "breakfast_set.png")
    return ActivityRun(db, run_id, picture, failures)


def set_table_picture(db_path: Path, run: int, path: Path) -> Path | None:
    """Render the table as the trace stored it after setting's last motion (None: the run
    has no such state), from :data:`VIEW_FROM`.

    Raises:
        NoSceneStored: the run was traced without its world.
    """
    with TraceDatabase(db_path, create=False) as db:
        scene = require_run(db, run).scene
        if scene is None:
            raise NoSceneStored(run)
        states = [i for i, _, task in world_state_times(db, run) if task and SETTING in task]
        if not states:
            return None
        with db.read() as session:
            state = load_world_state(session, states[-1])
    with build_scene(scene) as world:
        state.apply(world, scene)
        return world.view.save_png(path, CAMERA, width=800, height=600)
