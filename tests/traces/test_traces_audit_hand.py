"""Kitchen transports hold the hand to what it acts on, 5 mm deep at most, and say so.

Each ``allow_hand`` motion (approach, lift, put down, back off) stores its allowance:
the hand's links on the object moved, 5 mm. The audit replays every trajectory on raw
PyBullet and holds it to that bound (clean). Where each such motion ends, PyBullet's raw
closest points say how deep the hand is in the named object (within the bound) and that
it touches no other body.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import pytest

from robocram.costmaps.reach_reasoning import LIFT_MARGIN
from robocram.designators import a
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.motion.hand_contact import HAND_CONTACT_DEPTH
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_findings import AuditReport, FindingKind
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import RawDistances, World


@dataclass
class HandEnds:
    """At the end of each motion allowing the hand a contact: what it allowed, how deep
    the hand is in it, and what else the hand touches (PyBullet's raw closest points)."""

    world: World
    robot: str
    named: list[set[str]] = field(default_factory=list)  # per motion: the objects allowed
    depths: list[float] = field(default_factory=list)  # [m] per motion: deepest in them
    others: set[str] = field(default_factory=set)  # bodies touched that were not allowed

    def __call__(self, trajectory: JointTrajectory) -> None:
        if not trajectory.allowed_contacts:
            return
        raw = RawDistances(self.world)
        links = {c.robot_side for c in trajectory.allowed_contacts}
        named = {c.other for c in trajectory.allowed_contacts}
        shaped = [link for link in raw.collision_links(self.robot) if link in links]
        deepest = 0.0
        for obj in self.world.objects():
            if obj.name == self.robot or obj.type == "floor":
                continue
            for link in shaped:
                for other in raw.collision_links(obj):
                    gap = raw.closest(self.robot, link, obj, other)
                    if gap is None:
                        continue
                    if obj.name in named:
                        deepest = max(deepest, -gap.distance)
                    else:
                        self.others.add(f"{link} / {obj.name}/{other}")
        self.named.append(named)
        self.depths.append(deepest)


def _traced(tmp_path: Path, robot: str, kind: str) -> tuple[AuditReport, HandEnds, TransportResult]:
    scene = kitchen_scene(robot)
    ends = HandEnds(scene.world, scene.robot)
    db_path = tmp_path / f"{Path(robot).stem}-{kind}.db"
    with (
        trace_to(db_path, world=scene.world),
        trajectory_listener(ends),
        simulated_robot(scene.world, scene.robot),
    ):
        done = transport(kind, a.location(on=("kitchen", "table_top"), for_=f"{kind}-1"))
    scene.world.close()
    with TraceDatabase(db_path, create=False) as db:
        return audit_runs(db), ends, done


def _bottom_and_drawer_top(robot: str) -> tuple[float, float]:
    """[m] The bowl's bottom and its drawer's top, as the kitchen starts (the drawer
    slides level: both stay at these heights when it is open)."""
    scene = kitchen_scene(robot)
    boxes = scene.world.contacts
    bottom = min(low[2] for low, _ in boxes.link_aabbs("bowl-1").values())
    top = boxes.link_aabbs("kitchen")[DRAWER][1][2]
    scene.world.close()
    return bottom, top


DRAWER = "drawer_unit_drawer_3"
STRETCH = str(Path(__file__).resolve().parents[1] / "data" / "stretch" / "stretch.py")


@pytest.mark.parametrize(
    "robot",
    [
        "pr2",
        "hsrb",
        "boxy",
        # its grip centres the hand (curved finger hulls meet the mug 6 mm apart) and its
        # base backs the hand off the mug: a drive held to the bound, not a sweep through it
        pytest.param(STRETCH, id="stretch"),
    ],
)
def test_a_kitchen_mug_transport_is_clean_with_the_hand_bounded_on_the_mug(
    tmp_path: Path, robot: str
) -> None:
    report, ends, _ = _traced(tmp_path, robot, "mug")
    assert report.clean, report.summary_lines()
    assert len(ends.named) >= 3  # approach, lift, put down (and back off)
    assert all(named == {"mug-1"} for named in ends.named)  # only the mug, by name
    assert max(ends.depths) <= HAND_CONTACT_DEPTH
    assert ends.others == set()


@pytest.mark.parametrize("robot", ["pr2", "boxy"])
def test_the_bowl_comes_from_its_drawer_with_the_hand_bounded(tmp_path: Path, robot: str) -> None:
    """The drawer's handle and the bowl are named in turn. The audit moves the drawer
    with the hand (each step's trajectory carries its joint), and a grasp roll that did
    not hold goes back by trajectories: the whole run is clean, the drawer's opening and
    closing included. The pick lifts the bowl out over the drawer's top (Boxy's first
    stand could not: its delivery then failed, every table stand blocked by the bowl
    hanging in the drawer)."""
    bottom, top = _bottom_and_drawer_top(robot)
    report, ends, done = _traced(tmp_path, robot, "bowl")
    rise = done.held.lifted.position[2] - done.held.grasp_pose.position[2]  # [m]
    assert bottom + rise >= top + LIFT_MARGIN - 1e-6
    assert report.clean, [f.line() for f in report.findings]
    assert not [f for f in report.of(FindingKind.ALLOWED_CONTACT_TOO_DEEP) if "bowl" in f.what]
    handle = {"kitchen/drawer_unit_drawer_3_handle"}
    assert {frozenset(n) for n in ends.named} == {frozenset(handle), frozenset({"bowl-1"})}
    assert max(d for d, n in zip(ends.depths, ends.named, strict=True) if n == {"bowl-1"}) <= (
        HAND_CONTACT_DEPTH
    )
    assert max(ends.depths) <= HAND_CONTACT_DEPTH
    assert ends.others == set()
