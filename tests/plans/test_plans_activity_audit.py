"""A traced breakfast on the PR2 passes the trace audit.

A spoon is fetched from the cutlery drawer (the other spoon and the knife ride out and in
with it), set at the seat, and cleared back into the drawer, which is opened and closed
twice. The audit replays every stored trajectory densely on raw PyBullet, the drawer moved
with the hand and what rests in it moved with the drawer, and finds nothing. The whole
breakfast's audit is not clean yet: one drive with the fingers round the fridge door's
handle (docs/activities.md, known limits; tests/traces/test_traces_door_audit.py).
"""

from __future__ import annotations

from pathlib import Path

import pybullet

from robocram.activity_demo import set_table_picture
from robocram.designators import an
from robocram.plans import perform
from robocram.plans.table_arrangement import Setting
from robocram.projection import simulated_robot
from robocram.scenes.breakfast_scene import breakfast_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.trajectory_audit import audit_runs

DRAWER = "cutlery_unit_drawer_3"


def test_a_traced_spoon_setting_and_clearing_is_clean(tmp_path: Path) -> None:
    scene = breakfast_scene("pr2")
    world = scene.world
    db_path = tmp_path / "breakfast.db"
    with trace_to(db_path, world=world), simulated_robot(world, scene.robot):
        setting = perform(
            an.action(type="setting-table", people=1, setting=(Setting("spoon", 0.2, 0.21),),
                      shared=())
        )  # fmt: skip
        cleared = perform(an.action(type="clearing-table"))
    assert list(setting.placed) == list(cleared.returned) == ["spoon-1"]
    kitchen = world.object("kitchen")
    drawer = kitchen.link_index[DRAWER]
    near = pybullet.getClosestPoints(
        world.object("spoon-1").body_id, kitchen.body_id, 0.005, linkIndexB=drawer,
        physicsClientId=world.physics.client(),
    )  # fmt: skip
    assert near  # back in its drawer
    world.close()
    with TraceDatabase(db_path, create=False) as db:
        report = audit_runs(db)
    assert report.trajectories > 100  # the drawer's steps, the arm's and base's motions
    assert report.clean, report.summary_lines()
    picture = set_table_picture(db_path, report.runs[0], tmp_path / "set.png")
    assert picture is not None and picture.stat().st_size > 4_000  # rendered from the trace
