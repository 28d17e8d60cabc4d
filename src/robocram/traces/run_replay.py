"""Replaying a stored run: its world states, and its trajectories sampled in between.

:func:`replay_frames` walks a run's stored world states and executed trajectories in the
order they happened and puts a world (rebuilt from the run's scene) into each frame in
turn: a stored state exactly, a trajectory sample by setting its joints (a base
trajectory's ``x``, ``y``, ``yaw`` as the robot's pose in map) on the world left by what
came before, so held objects ride along. The MCAP export, the viewer's timeline and the
demo's animation are all made from these frames.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from robocram.motion import BODY_JOINTS
from robocram.tf import Pose
from robocram.tf.quaternion import from_euler, to_euler
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.queries import require_run, world_state_times
from robocram.traces.replay_clock import ReplayClock
from robocram.traces.trajectory_record import StoredTrajectory, run_trajectories
from robocram.traces.world_record import StoredWorldState, load_world_state
from robocram.world import RobotHandle, World

SAMPLE_PERIOD = 0.05  # [s] of motion time between two frames of a trajectory


@dataclass(frozen=True)
class ReplayFrame:
    """One moment of a replayed run: a stored world state or a sample of a trajectory."""

    time: float  # [s] since the epoch, on the run's replay clock
    wall_time: float  # [s] since the epoch: a state's own; samples spread up to the report
    task_path: str | None  # the motion that ended (a state) or that ran (a sample)
    state: StoredWorldState | None  # the stored state; None for a trajectory sample
    trajectory: StoredTrajectory | None  # the trajectory sampled; None for a state
    sample_time: float = 0.0  # [s] from the trajectory's start


def replay_frames(
    db: TraceDatabase, run: int, world: World, period: float = SAMPLE_PERIOD
) -> Iterator[ReplayFrame]:
    """Put ``world`` (holding the run's scene) into each frame of run ``run`` and yield it.

    Trajectories are sampled every ``period`` [s] of their own time, both ends included.
    Lazy: the world is in a frame's configuration while the caller holds that frame.

    Raises:
        UnknownRun: no run ``run`` in ``db``.
        TraceError: a non-positive period, or a trajectory of a robot ``world`` lacks.

    Warns:
        DamagedTrajectoryWarning: a damaged trajectory row was skipped (named).
    """
    if not period > 0.0:
        raise TraceError(f"the replay sampling period must be positive, got {period} s")
    row = require_run(db, run)
    start = row.start
    trajectories = run_trajectories(db, run, skip_damaged=True)  # the rest still replays
    states = world_state_times(db, run)
    clock = ReplayClock(
        start, [(t.time, t.duration) for t in trajectories], [t for _, t, _ in states]
    )
    events: list[tuple[float, int, int | StoredTrajectory, str | None]] = [
        (time, 1, state_id, path) for state_id, time, path in states
    ]
    events += [(t.time, 0, t, t.task_path) for t in trajectories]
    events.sort(key=lambda e: (e[0], e[1]))  # a motion's trajectories before its end state
    last_wall = start
    for wall, _, what, path in events:
        if isinstance(what, StoredTrajectory):
            yield from _samples(world, what, period, start, last_wall)
        else:
            with db.read() as session:
                state = load_world_state(session, what)
            state.apply(world, row.scene)
            yield ReplayFrame(clock.at(wall), wall, path, state, None)
        last_wall = wall


def _samples(
    world: World, trajectory: StoredTrajectory, period: float, run_start: float, after: float
) -> Iterator[ReplayFrame]:
    """Frames along ``trajectory``; wall times spread over (``after``, its report]."""
    if not trajectory.points:  # stopped before its first point: nothing moved
        return
    robot = RobotHandle.of(world, robot_in(world, trajectory.robot))
    span = trajectory.time - after
    for t, positions in trajectory.trajectory().sampled(period):
        set_robot_joints(robot, positions)
        share = t / trajectory.duration if trajectory.duration > 0.0 else 1.0
        wall = after + span * share
        time = run_start + trajectory.start + t
        yield ReplayFrame(time, wall, trajectory.task_path, None, trajectory, sample_time=t)


def robot_in(world: World, name: str) -> str:
    """The world's object name of robot ``name`` (an object name or a description name)."""
    robots = world.robots()
    for robot in robots:
        if name == robot.name:
            return robot.name
    for robot in robots:
        if name == robot.description.name:
            return robot.name
    raise TraceError(
        f"the replay world has no robot {name!r} (robots: {sorted(r.name for r in robots)}); "
        "replay into the run's scene (build_scene(scene_of(run)))"
    )


def set_robot_joints(robot: RobotHandle, positions: dict[str, float]) -> None:
    """Set ``robot``'s joints; the base joints ``x``, ``y``, ``yaw`` (and a flight's ``z``,
    ``roll``, ``pitch``) move its pose in map. What it holds is placed once, after both
    (where the joints and the base put its links: the order of the two writes does not
    change that)."""
    world = robot.world
    base = {name: positions[name] for name in BODY_JOINTS if name in positions}
    joints = {name: value for name, value in positions.items() if name not in base}
    if joints:
        world.set_joint_states(robot.name, joints, carry=not base)
    if base:
        world.set_pose(robot.name, _moved_base(world.pose(robot.name), base))


def _moved_base(pose: Pose, base: dict[str, float]) -> Pose:
    """``pose`` with the given base joints replaced (the others kept)."""
    x, y, z = pose.position
    roll, pitch, yaw = to_euler(pose.orientation)
    position = (base.get("x", x), base.get("y", y), base.get("z", z))
    turn = from_euler(base.get("roll", roll), base.get("pitch", pitch), base.get("yaw", yaw))
    return Pose(position, turn)
