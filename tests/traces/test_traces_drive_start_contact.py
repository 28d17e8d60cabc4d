"""A drive that starts 3 mm inside a crate and backs away is audited clean: its trajectory
stores the start contact's bound (its depth and 0.5 mm), and the audit, on raw PyBullet,
holds the drive to it. Without the stored bound the same drive was a 3 mm finding. (The
robot put into the crate by the test is the stored start state's own finding.)"""

from __future__ import annotations

from pathlib import Path

import pytest

from robocram.motion.hand_contact import KEEP_DEPTH
from robocram.plans.basic_actions import navigate
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.tf import Pose
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.trajectory_audit import audit_runs
from robocram.traces.trajectory_record import run_trajectories
from robocram.world import World

START_DEPTH = 0.003  # [m] how far the base starts inside the crate


def _gap(world: World) -> float:
    """The PR2's distance [m] to the crate (negative: inside it), by PyBullet."""
    found = world.contacts.link_distances("pr2", distance=1.0)
    return min(d for _, other, _, d in found if other.name == "crate")


def test_a_drive_backing_out_of_a_start_contact_audits_clean(tmp_path: Path) -> None:
    scene = kitchen_scene("pr2")
    world = scene.world
    world.add_box("crate", (0.4, 0.8, 0.5), (0.0, 0.2, 0.25))
    world.set_pose("pr2", Pose((-1.0, 0.2, 0.0)))
    x = -1.0 + _gap(world) + START_DEPTH
    world.set_pose("pr2", Pose((x, 0.2, 0.0)))
    depth = -_gap(world)
    db_path = tmp_path / "drive.db"
    with trace_to(db_path, world=world), simulated_robot(world, "pr2"):
        navigate(Pose((x - 0.3, 0.2, 0.0)))
    world.close()
    with TraceDatabase(db_path, create=False) as db:
        base = [t for t in run_trajectories(db, 1) if t.kind == "base"]
        (stored,) = [a for t in base for a in t.allowed_contacts if a.other == "crate"]
        assert stored.depth == pytest.approx(depth + KEEP_DEPTH, abs=1e-6)
        assert depth > 0.002  # beyond the audit's general bound (1 mm)
        report = audit_runs(db)
    assert [f for f in report.findings if f.trajectory is not None] == []
    (placed,) = report.findings  # the start state, as the test set it
    assert placed.trajectory is None and placed.amount == pytest.approx(depth, abs=2e-4)
