"""Traced kitchen transports, each run and audited once for every test that judges it
(``test_traces_audit.py`` and ``test_traces_audit_hand.py`` judge the same PR2 and HSR
mug transports: the conftest's ``traced_transports`` keeps them for the session)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_findings import AuditReport
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import RawDistances, World

# the modules sharing these runs: one xdist worker runs them, so each run is made once
SHARED = pytest.mark.xdist_group("traces/traced_transports")


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


@dataclass(frozen=True)
class TracedTransport:
    """A kitchen transport traced to a store: its audit, its hand's ends, its result."""

    report: AuditReport
    ends: HandEnds
    done: TransportResult


def traced_transport(folder: Path, robot: str, kind: str) -> TracedTransport:
    """Transport ``kind-1`` to the table top on ``robot`` in the kitchen, traced into
    ``folder`` with the hand's ends watched, and audit the store."""
    scene = kitchen_scene(robot)
    ends = HandEnds(scene.world, scene.robot)
    db_path = folder / f"{Path(robot).stem}-{kind}.db"
    with (
        trace_to(db_path, world=scene.world),
        trajectory_listener(ends),
        simulated_robot(scene.world, scene.robot),
    ):
        done = transport(kind, a.location(on=("kitchen", "table_top"), for_=f"{kind}-1"))
    scene.world.close()
    with TraceDatabase(db_path, create=False) as db:
        return TracedTransport(audit_runs(db), ends, done)
