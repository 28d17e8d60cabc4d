"""An animated GIF of a stored run, rendered from its trajectories from one fixed camera.

The run's scene is rebuilt from the trace and put through its replay frames
(:func:`~robocram.traces.run_replay.replay_frames`); the first frame at or after every
``period`` of replay time is rendered, and the last one. The period is widened so that
about ``max_frames`` are rendered (at most one more), which bounds both the render time
and the file size whatever the run's length; a motion shorter than the period (a grip)
shows in the next frame. All frames share the first frame's palette, so the GIF encoder
stores only what changed between frames.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from robocram.tf import Pose
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.queries import require_run, world_state_times
from robocram.traces.run_replay import replay_frames
from robocram.traces.trajectory_record import replay_clock, run_trajectories
from robocram.traces.world_record import build_scene
from robocram.world import Camera, World
from robocram.world.view_framing import Follower

GIF_PERIOD = 0.2  # [s] of replay time between two rendered frames
MAX_FRAMES = 100  # frames rendered (at most one more); a longer run gets a wider period
FRAME_SHOWN = 0.1  # [s] each frame is shown: the GIF plays period / FRAME_SHOWN times faster
COLORS = 128  # palette size shared by all frames


@dataclass(frozen=True)
class RunAnimation:
    """What :func:`animate_run` wrote: the file, its frames and the replay time they span."""

    path: Path
    frames: int
    period: float  # [s] of replay time between frames
    replay_duration: float  # [s] from the first to the last frame, replay clock
    render_seconds: float  # [s] of wall time spent rendering and encoding
    size: int  # [bytes] of the file


def animate_run(
    db: TraceDatabase | str | Path,
    run: int,
    out: str | Path,
    camera: Pose | None = None,
    *,
    width: int = 400,
    height: int = 300,
    period: float = GIF_PERIOD,
    max_frames: int = MAX_FRAMES,
    robots: Mapping[str, str] | None = None,
) -> RunAnimation:
    """Render run ``run`` from ``camera`` (an optical-frame pose in map) into the GIF ``out``;
    with no camera, from over the robot's shoulder, following it as it drives
    (:class:`~robocram.world.view_framing.Follower`).

    Raises:
        UnknownRun: no run ``run`` in ``db``.
        TraceError: the run stored no scene (trace it with ``trace_to(db, world=world)``),
            or a non-positive period or frame count.
    """
    if not isinstance(db, TraceDatabase):
        with TraceDatabase(db, create=False) as opened:
            return animate_run(
                opened, run, out, camera, width=width, height=height,
                period=period, max_frames=max_frames, robots=robots,
            )  # fmt: skip
    if not (period > 0.0 and max_frames >= 2):
        raise TraceError(
            f"animate with a positive period and at least 2 frames, got {period} s, {max_frames}"
        )
    began = time.perf_counter()
    row = require_run(db, run)
    if row.scene is None:
        raise TraceError(f"run {run} stored no scene; trace it with trace_to(db, world=world)")
    step = max(period, _replay_span(db, run) / (max_frames - 1))
    images: list[np.ndarray] = []
    first, due, last, shown = None, -np.inf, 0.0, False
    with build_scene(row.scene, robots=robots, db=db) as world:
        aim = _aim(world, run, camera)
        for frame in replay_frames(db, run, world, period=min(step, period)):
            first = frame.time if first is None else first
            last, shown = frame.time, frame.time >= due
            if shown:
                images.append(world.view.render(aim(), width, height))
                due = frame.time + step * (1.0 - 1e-9)
        if first is not None and not shown:  # the run's end is always in the picture
            images.append(world.view.render(aim(), width, height))
    if not images:
        raise TraceError(f"run {run} has no world states nor trajectories to animate")
    path = _write_gif(Path(out), images)
    return RunAnimation(
        path=path,
        frames=len(images),
        period=step,
        replay_duration=last - (first or 0.0),
        render_seconds=time.perf_counter() - began,
        size=path.stat().st_size,
    )


def _aim(world: World, run: int, camera: Pose | None) -> Callable[[], Pose]:
    """The camera pose for the world as it is now: ``camera``, or following the run's first
    robot from over its shoulder as it started (the scene's state before the run)."""
    if camera is not None:
        return lambda: camera
    robots = world.robots()
    if not robots:
        raise TraceError(f"run {run}'s scene holds no robot to follow; give a camera")
    follower: list[Follower] = []  # aimed at the first frame: the scene's robot as it started

    def aim() -> Pose:
        if not follower:
            follower.append(Follower.of(world, robots[0], Camera(Pose()).vertical_fov))
        return follower[0].framing(world, robots[0]).pose()

    return aim


def _replay_span(db: TraceDatabase, run: int) -> float:
    """[s] of replay time from the run's start to its last state or trajectory end."""
    start = require_run(db, run).start
    clock = replay_clock(db, run)
    ends = [clock.at(t) for _, t, _ in world_state_times(db, run)]
    ends += [start + t.end for t in run_trajectories(db, run)]
    return max(ends, default=start) - start


def _write_gif(out: Path, images: list[np.ndarray]) -> Path:
    out.parent.mkdir(parents=True, exist_ok=True)
    first = Image.fromarray(images[0]).quantize(COLORS, method=Image.Quantize.MEDIANCUT)
    frames = [
        Image.fromarray(image).quantize(palette=first, dither=Image.Dither.NONE) for image in images
    ]
    frames[0].save(
        out,
        save_all=True,
        append_images=frames[1:],
        duration=round(FRAME_SHOWN * 1000),
        loop=0,
        optimize=False,
    )
    return out
