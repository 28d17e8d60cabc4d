"""Bodies a run adds or removes after its start (grains poured, a loaf cut) are traced.

Each world state keeps the recipe of every body its run's scene lacks, and lacks the bodies
removed; applying it to the world rebuilt from the scene adds and removes them. A file
written before (schema 7) opens and reads no added bodies.
"""

from __future__ import annotations

import sqlite3
from pathlib import Path

import pybullet
import pytest

from robocram.execution import top_level
from robocram.traces import SCHEMA_VERSION, TraceDatabase, run_ids, trace_to
from robocram.traces.errors import TraceError
from robocram.traces.queries import world_state_times
from robocram.traces.world_record import (
    StoredWorldState,
    build_scene,
    load_world_state,
    scene_names,
    scene_of,
)
from robocram.world import World


def _world() -> World:
    world = World()
    world.bodies.add_floor()
    world.add_box("loaf", (0.24, 0.1, 0.1), pose=(0.0, 0.0, 0.05))
    return world


def _position(world: World, name: str) -> tuple[float, ...]:
    position, _ = pybullet.getBasePositionAndOrientation(
        world.object(name).body_id, physicsClientId=world.physics.client()
    )
    return tuple(position)


def test_a_state_adds_what_the_run_added_and_removes_what_it_removed() -> None:
    with _world() as ran:
        scene = scene_of(ran)
        before = StoredWorldState.capture(ran, 0.0, scene_names(scene))
        ran.remove("loaf")
        ran.bodies.add_sphere("grain-1", 0.005, pose=(0.1, 0.2, 0.3))
        state = StoredWorldState.capture(ran, 1.0, scene_names(scene))
    assert set(state.added) == {"grain-1"} and before.added == {}
    with build_scene(scene) as replay:
        state.apply(replay)
        assert {o.name for o in replay.objects()} == {"floor", "grain-1"}
        assert _position(replay, "grain-1") == pytest.approx((0.1, 0.2, 0.3), abs=1e-9)
        low, high = pybullet.getAABB(
            replay.object("grain-1").body_id, physicsClientId=replay.physics.client()
        )
        assert high[0] - low[0] == pytest.approx(0.01, abs=0.002)  # its recipe's size
        before.apply(replay, scene)  # going back: the loaf from the scene again
        assert {o.name for o in replay.objects()} == {"floor", "loaf"}
        with pytest.raises(TraceError, match="grain-1"):
            state_without_recipe = StoredWorldState(
                state.time, state.sim_time, state.poses, state.joints, state.attachments
            )
            state_without_recipe.apply(replay)


def test_a_schema_7_file_opens_and_reads_no_added_bodies(tmp_path: Path) -> None:
    db_path = tmp_path / "runs.db"
    with _world() as world, trace_to(db_path, world=world), top_level(name="pour"):
        pass
    with TraceDatabase(db_path, create=False) as db:
        (run,) = run_ids(db)
        ids = [state_id for state_id, _, _ in world_state_times(db, run)]
        with db.read() as session:
            states = [load_world_state(session, i) for i in ids]
    assert states and states[0].added == {}
    with sqlite3.connect(db_path) as con:  # what robocram wrote before added bodies
        con.execute("ALTER TABLE world_states DROP COLUMN added")
        con.execute("UPDATE schema_info SET version = 7")
    with TraceDatabase(db_path, create=False) as db, db.read() as session:
        assert all(load_world_state(session, i).added == {} for i in ids)
    with sqlite3.connect(db_path) as con:
        assert con.execute("SELECT version FROM schema_info").fetchone() == (SCHEMA_VERSION,)
