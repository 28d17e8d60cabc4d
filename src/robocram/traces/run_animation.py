"""An animated GIF of a stored run, rendered from its trajectories from one fixed camera.

The run's scene is rebuilt from the trace and put through its replay frames
(:func:`~robocram.traces.run_replay.replay_frames`). Rendered are: each trajectory every
``period`` of its motion time and at its end, and each stored world state but the one
right after a trajectory of its own motion (the trajectory's end showed it).
The period is widened so that about ``max_frames`` are rendered, which bounds both the
render time and the file size whatever the run's length. All frames share the first
frame's palette, so the GIF encoder stores only what changed between frames.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image

from robocram.tf import Pose
from robocram.traces.database import TraceDatabase
from robocram.traces.errors import TraceError
from robocram.traces.queries import require_run, world_state_times
from robocram.traces.run_replay import ReplayFrame, replay_frames
from robocram.traces.trajectory_record import run_trajectories
from robocram.traces.world_record import build_scene

GIF_PERIOD = 0.2  # [s] of motion time between two rendered frames of a trajectory
MAX_FRAMES = 120  # frames rendered, about; a run with more motion gets a wider period
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
    camera: Pose,
    *,
    width: int = 400,
    height: int = 300,
    period: float = GIF_PERIOD,
    max_frames: int = MAX_FRAMES,
) -> RunAnimation:
    """Render run ``run`` from ``camera`` (an optical-frame pose in map) into the GIF ``out``.

    Raises:
        UnknownRun: no run ``run`` in ``db``.
        TraceError: the run stored no scene (trace it with ``trace_to(db, world=world)``),
            or a non-positive period or frame count.
    """
    if not isinstance(db, TraceDatabase):
        with TraceDatabase(db, create=False) as opened:
            return animate_run(
                opened, run, out, camera, width=width, height=height,
                period=period, max_frames=max_frames,
            )  # fmt: skip
    if not (period > 0.0 and max_frames >= 2):
        raise TraceError(
            f"animate with a positive period and at least 2 frames, got {period} s, {max_frames}"
        )
    began = time.perf_counter()
    row = require_run(db, run)
    if row.scene is None:
        raise TraceError(f"run {run} stored no scene; trace it with trace_to(db, world=world)")
    step = _period(db, run, period, max_frames)
    images: list[np.ndarray] = []
    times: list[float] = []
    due = -np.inf  # [s] replay time of the next sample to render
    ended: str | None = None  # the task whose trajectory's end was just rendered
    with build_scene(row.scene) as world:
        for frame in replay_frames(db, run, world, period=step):
            end = frame.trajectory is not None and frame.sample_time >= frame.trajectory.duration
            if _rendered(frame, due, end, ended):
                images.append(world.render(camera, width, height))
                times.append(frame.time)
                due = frame.time + step * (1.0 - 1e-9)
            ended = frame.task_path if end else None
    if not images:
        raise TraceError(f"run {run} has no world states nor trajectories to animate")
    path = _write_gif(Path(out), images)
    return RunAnimation(
        path=path,
        frames=len(images),
        period=step,
        replay_duration=times[-1] - times[0],
        render_seconds=time.perf_counter() - began,
        size=path.stat().st_size,
    )


def _rendered(frame: ReplayFrame, due: float, end: bool, ended: str | None) -> bool:
    """A sample when due or at its trajectory's end; a state unless that end just showed it."""
    if frame.trajectory is not None:
        return frame.time >= due or end
    return ended is None or frame.task_path != ended


def _period(db: TraceDatabase, run: int, period: float, max_frames: int) -> float:
    """``period``, widened so that states, trajectory ends and samples make ``max_frames``."""
    trajectories = run_trajectories(db, run)
    fixed = len(world_state_times(db, run)) + len(trajectories)
    motion = sum(t.duration for t in trajectories)  # [s]
    return max(period, motion / max(max_frames - fixed, 1))


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
