"""What rides in a drawer the hand carries is judged where it rides to (issue 40).

A spoon standing in a drawer that a trajectory pulls toward the PR2's parked right hand
rides into the fingers only because it rides: the hand itself barely moves. The audit
attaches it to the drawer (``trajectory_audit.riding``) and must read its bounds again as
it goes, not where it stood when the trajectory began; the depth it reports is the one
raw PyBullet gives for the spoon put where the drawer took it.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pybullet
import pytest

from robocram.execution import sub_task, top_level
from robocram.motion import CarriedJoint, joint_limits, report_executed, time_parameterize
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import FindingKind
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import World

PULL = 0.38  # [m] how far the drawer comes out toward the robot
SPOON_AT = (0.73, -0.47, 0.72)  # [m] the spoon's centre, standing on the closed drawer
SPOON_SIZE = (0.04, 0.04, 0.4)  # [m] tall: its top reaches the parked hand's height
LIFT = 0.01  # [m] the torso's move the drawer is carried along
DEPTH_TOLERANCE = 0.001  # [m]


def _box_link(name: str, size: str, xyz: str = "0 0 0") -> str:
    return (
        f'<link name="{name}"><collision><origin xyz="{xyz}"/>'
        f'<geometry><box size="{size}"/></geometry></collision>'
        '<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/>'
        "</inertial></link>"
    )


# a low cabinet in front of the PR2's right side; its drawer, a tray on top, slides to -x
CABINET = (
    '<robot name="cabinet">'
    + _box_link("body", "0.4 0.4 0.5")
    + _box_link("drawer", "0.2 0.2 0.02")
    + '<joint name="drawer_joint" type="prismatic"><parent link="body"/><child link="drawer"/>'
    '<origin xyz="-0.05 0 0.26"/><axis xyz="-1 0 0"/><limit lower="0" upper="0.4"/></joint>'
    "</robot>"
)


def _raw_depths(world: World, a: str, b: str) -> dict[str, float]:
    """Per link of ``b`` in ``a`` [m]: its deepest penetration, by PyBullet's own closest
    points (nothing of the audit's)."""
    cid = world.physics.client()
    target = world.object(b)
    names = {index: name for name, index in target.link_index.items()}
    points = pybullet.getClosestPoints(
        world.object(a).body_id, target.body_id, 0.0, physicsClientId=cid
    )
    depths: dict[str, float] = {}
    for p in points:
        link = names.get(p[4], "base") if p[4] >= 0 else "base"
        depths[link] = max(depths.get(link, 0.0), -p[8])
    return depths


def test_a_spoon_riding_into_the_hand_is_found_where_it_rode_to(tmp_path: Path) -> None:
    urdf = tmp_path / "cabinet.urdf"
    urdf.write_text(CABINET, encoding="utf-8")
    db_path = tmp_path / "runs.db"
    world = World()
    world.add_robot("pr2")
    description = world.robot("pr2").description
    for arm in description.arms.values():
        world.set_joint_states("pr2", dict(arm.parking))
    world.add_urdf("cabinet", urdf, (0.85, -0.47, 0.25))
    world.add_box("spoon", SPOON_SIZE, SPOON_AT, mass=0.05)
    assert _raw_depths(world, "spoon", "pr2") == {}  # nothing touches before the pull
    names = ("torso_lift_joint",)
    lift = time_parameterize("pr2", names, [[0.0], [LIFT]], joint_limits(description, names))
    lift = replace(lift, carried=(CarriedJoint("cabinet", "drawer_joint", 0.0, PULL),))
    with trace_to(db_path, world=world), top_level(name="pull"), sub_task("pull-drawer"):
        world.set_joint_states("pr2", {"torso_lift_joint": LIFT})
        world.attach("spoon", "cabinet", "drawer")  # it rides, as projection has it
        world.set_joint_states("cabinet", {"drawer_joint": PULL})
        world.detach("spoon")
        report_executed(lift)
    bound = AuditBounds().penetration
    in_hand = {k: v for k, v in _raw_depths(world, "spoon", "pr2").items() if v > bound}
    drawer = _raw_depths(world, "cabinet", "pr2")
    world.close()
    assert drawer == {}  # the drawer itself passes under the hand
    assert max(in_hand.values()) > 0.02  # the spoon is 3 cm in the fingers at the end
    with TraceDatabase(db_path, create=False) as db:
        report = audit_runs(db)
    found = {f.what: f for f in report.findings}
    assert {f.kind for f in found.values()} == {FindingKind.WORLD_PENETRATION}
    assert set(found) == {f"pr2:{link} / spoon" for link in in_hand}  # was none: clean
    for link, depth in in_hand.items():
        assert found[f"pr2:{link} / spoon"].amount == pytest.approx(depth, abs=DEPTH_TOLERANCE)
