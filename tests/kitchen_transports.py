"""Kitchen transports, each run once for the session and judged by every test that asks.

The same transport (a robot, the mug or the bowl taken to the table top) was run by up to
four modules, each to judge it its own way: the trace audit and the hand's bounds
(``tests/traces``), the world it leaves (``tests/plans``, ``tests/robots``) and the stands
a ROS run must match (``tests/ros``). Now the conftest's ``kitchen_transports`` runs each
once, with the watchers its judges need, and keeps its world open for the session: the
modules asking for one carry ``SHARED`` (one xdist worker runs them all).

A traced run plans what a plain one does (the trace and the hand's watcher only read the
world; the attempts, final joints and poses compared bit for bit): the runs ``TRACED``
names are traced. The projection tests judge the same runs: the trajectory judge puts the
world back through a snapshot, to the bit, and the joint ledger only reads it (the HSR's
mug run, every watcher on, plans what a plain one does:
tests/projection/test_judged_transport_plans_as_plain.py). A watcher's failed assertion
is kept, not raised, so that the run goes on to its end; the test judging it asserts that
none was kept. Every run keeps the trajectories it executed.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from contextlib import ExitStack
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path

import pytest

from robocram.designators import a
from robocram.motion import JointTrajectory, trajectory_listener
from robocram.plans.transport import TransportResult, transport
from robocram.projection import simulated_robot
from robocram.robots import MissingMeshWarning, RobotDescription, load_description
from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase, trace_to
from robocram.traces.audit_findings import AuditReport
from robocram.traces.trajectory_audit import audit_runs
from robocram.world import RawDistances, World
from tests.projection.joint_ledger import Ledger
from tests.projection.raw_world import RawRecord
from tests.projection.trajectory_judge import Judge

SHARED = pytest.mark.xdist_group("kitchen_transports")
TABLE = ("kitchen", "table_top")
STRETCH = "stretch_description"  # the drafted Stretch's name (tests/data/stretch)
# (robot, kind) traced for the audit tests (their plain runs)
TRACED = frozenset(
    {("pr2", "mug"), ("hsrb", "mug"), ("boxy", "mug"), (STRETCH, "mug")}
    | {("pr2", "bowl"), ("boxy", "bowl")}
)
# (robot, kind) judged at each trajectory (tests/projection: transport_trajectories)
JUDGED = frozenset({("pr2", "mug"), ("hsrb", "mug"), ("boxy", "mug"), ("pr2", "bowl")})
# (robot, kind) whose joints are kept at each trajectory (tests/projection: no_teleports)
LEDGERED = frozenset({("pr2", "bowl"), ("hsrb", "mug")})
# (robot, kind) whose raw world is recorded at each trajectory, to be compared with a plain
# run's (tests/projection/test_judged_transport_plans_as_plain.py): every watcher is on it
RECORDED = frozenset({("hsrb", "mug")})


@dataclass
class Kept:
    """A watcher whose failed assertions are kept, not raised: the shared run goes on to
    its end, and each test judging it asserts that none was kept."""

    watcher: Callable[[JointTrajectory], object]
    failures: list[str] = field(default_factory=list)

    def __call__(self, trajectory: JointTrajectory) -> None:
        try:
            self.watcher(trajectory)
        except AssertionError as failure:
            named = f"{trajectory.kind} trajectory {trajectory.joint_names}"
            self.failures.append(f"{named}: {failure}")

    def finally_(self, check: Callable[[], object]) -> None:
        """Run ``check`` (the watcher's own at the run's end), keeping its failure."""
        try:
            check()
        except AssertionError as failure:
            self.failures.append(f"at the end: {failure}")

    def found_nothing(self) -> Callable[[JointTrajectory], object]:
        """The watcher, asserting first that none of its assertions failed."""
        assert not self.failures, "\n".join(self.failures)
        return self.watcher


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


@dataclass
class KitchenTransport:
    """A kitchen transport as it ran: its result, the world it left (open for the
    session: do not change it), and what its watchers saw."""

    world: World
    robot: str
    done: TransportResult
    store: Path | None  # the trace (TRACED runs)
    hand_ends: HandEnds | None  # (TRACED runs)
    executed: list[JointTrajectory] = field(default_factory=list)  # every run
    judged: Kept | None = None  # the judge, its failures kept (JUDGED runs)
    ledger: Kept | None = None  # the joint ledger, its failures kept (LEDGERED runs)
    raw: RawRecord | None = None  # the raw world at each trajectory (RECORDED runs)

    @property
    def ends(self) -> HandEnds:
        assert self.hand_ends is not None, f"{self.robot}'s run is not in TRACED"
        return self.hand_ends

    @property
    def judge(self) -> Judge:
        """The judge (its ``judged``: kind and configurations checked per trajectory),
        asserting first that it found nothing."""
        assert self.judged is not None, f"{self.robot}'s run is not in JUDGED"
        judge = self.judged.found_nothing()
        assert isinstance(judge, Judge)
        return judge

    @property
    def ledgered(self) -> Ledger:
        """The joint ledger (its ``seen`` trajectories), asserting first that it found
        nothing: no joint or base moved off a trajectory, nothing after the last."""
        assert self.ledger is not None, f"{self.robot}'s run is not in LEDGERED"
        ledger = self.ledger.found_nothing()
        assert isinstance(ledger, Ledger)
        return ledger

    @cached_property
    def report(self) -> AuditReport:
        """The trace's audit (every trajectory replayed densely), made when first asked."""
        assert self.store is not None, f"{self.robot}'s run is not in TRACED"
        with TraceDatabase(self.store, create=False) as db:
            return audit_runs(db)


# what the conftest's ``kitchen_transports`` gives: (robot, kind) -> its run
Transports = Callable[[str | RobotDescription, str], KitchenTransport]


def transport_key(robot: str | RobotDescription, kind: str) -> tuple[str, str]:
    """``(robot's name, kind)``: a robot given by name, file or description is one robot
    (loaded again quietly: its scene has warned of what its meshes miss)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MissingMeshWarning)
        return load_description(robot).name, kind


def kitchen_transport(folder: Path, robot: str | RobotDescription, kind: str) -> KitchenTransport:
    """``kind-1`` taken to the kitchen's table top on ``robot``, projected, with the
    watchers ``TRACED``, ``JUDGED``, ``LEDGERED`` and ``RECORDED`` name for it (traced
    into ``folder``)."""
    key = transport_key(robot, kind)
    scene = kitchen_scene(robot)
    world = scene.world
    traced = key in TRACED
    store = folder / f"{key[0]}-{kind}.db" if traced else None
    ends = HandEnds(world, scene.robot) if traced else None
    raw = RawRecord(world) if key in RECORDED else None
    judged = Kept(Judge(world, scene.robot)) if key in JUDGED else None
    ledger = Ledger(world, scene.robot) if key in LEDGERED else None
    kept_ledger = Kept(ledger) if ledger is not None else None
    executed: list[JointTrajectory] = []
    # the trace and the watchers that only read the world first; the judge, which sets it
    # and puts it back, last
    listeners = [raw, ends, executed.append, kept_ledger, judged]
    with ExitStack() as watching:
        if store is not None:
            watching.enter_context(trace_to(store, world=world))
        for listener in listeners:
            if listener is not None:
                watching.enter_context(trajectory_listener(listener))
        watching.enter_context(simulated_robot(world, scene.robot))
        done = transport(kind, a.location(on=TABLE, for_=f"{kind}-1"))
    if ledger is not None and kept_ledger is not None:
        kept_ledger.finally_(ledger.assert_still)  # nothing moved after the last trajectory
    if raw is not None:
        raw.end()
    return KitchenTransport(
        world, scene.robot, done, store, ends, executed, judged, kept_ledger, raw
    )
