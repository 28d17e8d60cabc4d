"""The audit of a stored run: can its trajectories be executed as they were stored?

The run's world is rebuilt from its trace (its scene, then each stored world state), and
its stored trajectories are replayed in the order they ran, densely
(:mod:`~robocram.traces.dense_samples`). Found, independently of the planner:

- penetrations of the robot and what it holds with the world and with itself
  (:mod:`~robocram.traces.penetration_audit`, PyBullet's raw closest points);
- velocity, acceleration and jerk over the limits, from the stored positions, and stored
  velocities and accelerations that disagree with them (:mod:`~robocram.traces.limit_audit`);
- jumps of joints or the base with no trajectory (:mod:`~robocram.traces.teleport_audit`);
  a stored state the robot jumped to is checked for penetrations too.

``robocram runs audit runs.db [--run N]`` prints the findings; docs/motion.md, "Auditing a run".
"""

from __future__ import annotations

from collections.abc import Collection, Iterable, Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np

from robocram.motion import CarriedJoint, ContactAllowance, MotionError, joint_limits
from robocram.traces.audit_bounds import AuditBounds
from robocram.traces.audit_findings import (
    AuditFinding,
    AuditReport,
    FindingPlace,
    worst_per_culprit,
)
from robocram.traces.database import TraceDatabase
from robocram.traces.dense_samples import Levers, dense_configurations
from robocram.traces.errors import NoSceneStored, TraceError
from robocram.traces.limit_audit import limit_findings
from robocram.traces.penetration_audit import PenetrationProbe, robot_side_parts
from robocram.traces.queries import require_run, run_ids, world_state_times
from robocram.traces.relative_motion import moving_groups
from robocram.traces.replay_clock import ReplayClock
from robocram.traces.run_replay import robot_in, set_robot_joints
from robocram.traces.teleport_audit import TeleportWatch
from robocram.traces.trajectory_record import StoredTrajectory, run_trajectories
from robocram.traces.world_record import build_scene, load_world_state
from robocram.world import RawDistances, RobotHandle, RobotObject, World

RESTING = 0.005  # [m] a body this near a link a trajectory carries rides with it


def audit_runs(
    db: TraceDatabase,
    run: int | None = None,
    bounds: AuditBounds | None = None,
    robots: Mapping[str, str] | None = None,
) -> AuditReport:
    """The audit of run ``run``, or of every run of ``db`` (None); of every run, those
    traced without their world are listed as not audited.

    Raises:
        UnknownRun: no run ``run`` in ``db``.
        TraceError: run ``run`` has no stored scene, or a trajectory of a robot it lacks.
    """
    if run is not None:
        return audit_run(db, require_run(db, run).id, bounds, robots)
    reports = []
    for i in run_ids(db):
        try:
            reports.append(audit_run(db, i, bounds, robots))
        except NoSceneStored as err:
            reports.append(AuditReport((), (), 0, 0, ((i, str(err)),)))
    return AuditReport.merged(reports)


def audit_run(
    db: TraceDatabase,
    run: int,
    bounds: AuditBounds | None = None,
    robots: Mapping[str, str] | None = None,
) -> AuditReport:
    """Replay run ``run`` densely on its stored world and report what is wrong
    (``robots``: description files by robot name, see
    :func:`~robocram.traces.world_record.build_scene`)."""
    bounds = bounds if bounds is not None else AuditBounds()
    row = require_run(db, run)
    if row.scene is None:
        raise NoSceneStored(run)
    trajectories = run_trajectories(db, run)
    with build_scene(row.scene, robots=robots, db=db) as world:
        audit = _RunAudit(db, run, world, bounds, row.scene)
        for event in _events(db, run, trajectories):
            if isinstance(event, StoredTrajectory):
                audit.trajectory(event)
            else:
                audit.state(*event)
    findings = tuple(worst_per_culprit(audit.findings))
    return AuditReport((run,), findings, len(trajectories), audit.configurations)


def _hand_share(robot: RobotHandle, joint: CarriedJoint, by_time: float) -> float:
    """How far ``joint`` has gone: with the robot's holding link along its line (the
    link's position read from PyBullet as the robot is now), else ``by_time``."""
    if joint.line is None:
        return by_time
    return joint.share(robot.world.link_pose(robot.name, joint.link).position)


@contextmanager
def riding(world: World, carried: tuple[CarriedJoint, ...]) -> Iterator[None]:
    """Within the block, what rests on a link a carried joint moves rides with it (spoons
    in a drawer the hand closes), as projection attaches them (``articulation.resting_in``):
    free bodies within :data:`RESTING` of the link, held by nothing, at the start, by
    PyBullet's raw closest points."""
    riders: list[str] = []
    raw = RawDistances(world)
    for joint in carried:
        body = world.object(joint.obj)
        index = body.joint_index[joint.joint]
        link = next(name for name, i in body.link_index.items() if i == index)
        for obj in world.objects():
            if obj.is_static or obj.name == joint.obj or isinstance(obj, RobotObject):
                continue
            parts = raw.collision_links(obj)
            near = (raw.closest(obj, part, body, link, RESTING) for part in parts)
            if world.bodies.attached_to(obj) is None and any(gap is not None for gap in near):
                world.attach(obj, body, link)
                riders.append(obj.name)
    try:
        yield
    finally:
        for name in riders:
            world.detach(name)


def _events(
    db: TraceDatabase, run: int, trajectories: list[StoredTrajectory]
) -> Iterator[StoredTrajectory | tuple[int, float, str | None]]:
    """States (id, time on the replay clock, path) and trajectories in the order they ran."""
    start = require_run(db, run).start
    states = world_state_times(db, run)
    clock = ReplayClock(
        start, [(t.time, t.duration) for t in trajectories], [t for _, t, _ in states]
    )
    events: list[tuple[float, int, StoredTrajectory | tuple[int, float, str | None]]] = [
        (time, 1, (state_id, clock.since_start(time), path)) for state_id, time, path in states
    ]
    events += [(t.time, 0, t) for t in trajectories]
    events.sort(key=lambda e: (e[0], e[1]))  # a motion's trajectories before its end state
    for _, _, what in events:
        yield what


@dataclass
class _RunAudit:
    """The walk over one run: the world, where each robot is known to be, the findings."""

    db: TraceDatabase
    run: int
    world: World
    bounds: AuditBounds
    scene: str  # the run's scene (JSON): a body it removed and a later state has again

    def __post_init__(self) -> None:
        self.findings: list[AuditFinding] = []
        self.judged: set[str] = set()  # robots whose every pair was judged once
        self.skipped = {  # per robot: the pairs of its own links not judged
            r.name: frozenset(self.bounds.skipped_self_pairs(RobotHandle.of(self.world, r)))
            for r in self.world.robots()
        }
        self.configurations = 0
        self.watches = {
            r.name: TeleportWatch(r.name, r.description.model, self.bounds.teleport)
            for r in self.world.robots()
        }

    def state(self, state_id: int, time: float, path: str | None) -> None:
        """Apply a stored state; jumps to it are findings, and it is checked if any."""
        with self.db.read() as session:
            state = load_world_state(session, state_id)
        state.apply(self.world, self.scene)
        place = FindingPlace(self.run, None, path, time)
        for robot, watch in self.watches.items():
            jumps = list(watch.state(state.joints.get(robot, {}), state.poses[robot], place))
            self.findings += jumps
            if jumps or robot not in self.judged:
                handle = RobotHandle.of(self.world, robot)  # after the state: bodies may be new
                self._sweep_configurations(handle, watch.jumped, place, [(0.0, None)])

    def trajectory(self, trajectory: StoredTrajectory) -> None:
        """Limits, the jump to its start, and a dense sweep of its configurations."""
        if not trajectory.points:
            return
        handle = RobotHandle.of(self.world, robot_in(self.world, trajectory.robot))
        robot, description = handle.name, handle.description
        place = FindingPlace(self.run, trajectory.index, trajectory.task_path, trajectory.start)
        try:
            limits = joint_limits(description, trajectory.joint_names)
        except MotionError as err:
            raise TraceError(f"run {self.run}, trajectory {trajectory.index}: {err}") from err
        wrapping = {j.name for j in description.model.joints.values() if j.type == "continuous"}
        wrapping |= {"roll", "pitch", "yaw"}
        self.findings += limit_findings(trajectory, limits, self.bounds, place, wrapping)
        start = dict(zip(trajectory.joint_names, trajectory.points[0].positions, strict=True))
        end = dict(zip(trajectory.joint_names, trajectory.points[-1].positions, strict=True))
        self.findings += self.watches[robot].trajectory(start, end, place)
        times = np.array([p.time_from_start for p in trajectory.points])
        positions = np.array([p.positions for p in trajectory.points], dtype=float)
        held = self._held(robot)
        levers = Levers.of(handle, description.model, held)
        samples = (
            (t, dict(zip(trajectory.joint_names, q.tolist(), strict=True)))
            for t, q in dense_configurations(
                trajectory.joint_names, times, positions, levers,
                self.bounds.joint_step, self.bounds.point_step,
            )
        )  # fmt: skip
        with riding(self.world, trajectory.carried):
            self._sweep_configurations(
                handle, trajectory.joint_names, place, samples, trajectory.allowed_contacts,
                trajectory.carried, trajectory.duration,
            )  # fmt: skip

    def _held(self, robot_name: str) -> dict[str, str]:
        return {a.obj: a.link for a in self.world.bodies.all_attachments() if a.robot == robot_name}

    def _sweep_configurations(
        self,
        handle: RobotHandle,
        moved: Collection[str],
        place: FindingPlace,
        samples: Iterable[tuple[float, dict[str, float] | None]],
        allowances: tuple[ContactAllowance, ...] = (),
        carried: tuple[CarriedJoint, ...] = (),
        duration: float = 0.0,
    ) -> None:
        """Put the robot in each sample (None: as it is) and keep what penetrates.

        ``moved``: the joints moving; pairs of the robot's parts that they do not move
        relative to each other are not judged again; at the robot's first configuration in
        the run every pair is judged). ``carried``: other objects' joints the motion moves
        along: where the link holding the part is along its line, or at each sample's
        share of ``duration`` [s].
        """
        robot, description = handle.name, handle.description
        held = self._held(robot)
        groups = None
        if robot in self.judged:
            by_link = moving_groups(description.model, moved)
            parts = robot_side_parts(handle, held)
            groups = [by_link.get(held.get(p.body, p.link), "") for p in parts]
        self.judged.add(robot)
        probe = PenetrationProbe(
            handle, held, allowances, self.bounds, self.skipped[robot], groups
        )  # fmt: skip
        joints = {(c.obj, c.joint) for c in carried}
        for k, (t, positions) in enumerate(samples):
            if positions is not None:
                set_robot_joints(handle, positions)
            if carried:
                share = t / duration if duration > 0.0 else 1.0
                for joint in carried:
                    value = joint.at(_hand_share(handle, joint, share))
                    self.world.set_joint_states(joint.obj, {joint.joint: value})
                probe.others_moved(joints)
            self.configurations += 1
            for p in probe.check(first=k == 0):
                self.findings.append(place.finding(p.kind, t, p.what, p.depth, p.bound))
