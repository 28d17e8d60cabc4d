"""Issue 37: a suction hand opens a drawer holding its handle's front face (MABI's mobile
arm, drafted with no edit: no gripper in its URDF, its tool frame on the wrist's flange)."""

from __future__ import annotations

import warnings
from pathlib import Path

import pybullet
import pytest

from robocram.plans.basic_actions import park_arms
from robocram.plans.container_access import open_from_front
from robocram.projection import simulated_robot
from robocram.robots import GripperDescription
from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase, audit_runs, trace_to
from tests.drafts import drafted

MABI = Path(__file__).resolve().parents[1] / "data" / "zoo" / "mabi_mobile" / "mabi_mobile.urdf"
DRAWER = "drawer_unit_drawer_3"

pytestmark = pytest.mark.filterwarnings("ignore::robocram.robots.DescriptionWarning")


def test_a_suction_hand_opens_a_drawer_by_its_handles_face(tmp_path: Path) -> None:
    module = tmp_path / "mabi_mobile.py"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        draft = drafted(MABI)
    assert draft.description.arms["arm"].gripper == GripperDescription.suction()
    module.write_text(draft.source(module), encoding="utf-8")
    scene = kitchen_scene(str(module))
    world = scene.world
    try:
        with trace_to(tmp_path / "open.db", world=world), simulated_robot(world, scene.robot):
            park_arms()
            opened = open_from_front(DRAWER)
        kitchen = world.object("kitchen")
        index = kitchen.joint_index[opened.container.joint]
        client = world.physics.client()
        travel = pybullet.getJointState(kitchen.body_id, index, physicsClientId=client)[0]
    finally:
        world.close()
    assert travel == pytest.approx(opened.container.opened, abs=1e-6)  # 0.4 m: fully open
    with TraceDatabase(tmp_path / "open.db") as db:
        report = audit_runs(db)
    assert not report.findings, report.summary_lines()
