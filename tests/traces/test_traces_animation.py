"""A run's animated GIF, rendered from its stored trajectories."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from robocram.projection import looking_orientation
from robocram.tf import Pose
from robocram.traces import TraceError, animate_run, run_trajectories

EYE, AT = (1.6, -1.6, 2.0), (-0.1, 0.1, 0.5)  # [m] in map: the PR2 and its drive in sight
CAMERA = Pose(EYE, looking_orientation(EYE, AT))
WIDTH, HEIGHT = 160, 120  # [px]
PERIOD = 0.5  # [s] of motion time between frames


def _motion_time(traced: Any) -> float:
    """[s] of motion in the run: the arm's, the torso's and the base's trajectories."""
    return sum(t.duration for t in run_trajectories(traced.db_path, traced.run))


def test_gif_has_a_frame_per_period_of_motion_and_every_state(
    trajectory_run: Any, tmp_path: Path
) -> None:
    out = tmp_path / "run.gif"
    gif = animate_run(
        trajectory_run.db_path, trajectory_run.run, out, CAMERA,
        width=WIDTH, height=HEIGHT, period=PERIOD,
    )  # fmt: skip
    span = _motion_time(trajectory_run)
    assert gif.period == pytest.approx(PERIOD)
    assert abs(gif.frames - (span / PERIOD + 1)) <= 1  # one every period, and the end
    assert gif.replay_duration == pytest.approx(span, abs=0.05)
    assert gif.size == out.stat().st_size
    with Image.open(out) as image:
        assert image.size == (WIDTH, HEIGHT)
        frames = []
        for index in range(image.n_frames):
            image.seek(index)
            frames.append(np.asarray(image.convert("RGB"), dtype=np.int16))
    assert 2 < len(frames) <= gif.frames  # identical neighbours may be merged by the encoder
    moved = np.abs(frames[0] - frames[-1]).max(axis=2) > 40
    assert moved.mean() > 0.01  # the robot drove off: a good part of the picture changed


def test_a_long_run_gets_a_wider_period(trajectory_run: Any, tmp_path: Path) -> None:
    gif = animate_run(
        trajectory_run.db_path, trajectory_run.run, tmp_path / "short.gif", CAMERA,
        width=WIDTH, height=HEIGHT, period=PERIOD, max_frames=5,
    )  # fmt: skip
    span = _motion_time(trajectory_run)
    assert gif.period == pytest.approx(span / 4, abs=0.05)
    assert gif.frames in (5, 6)


def test_animation_input_errors_say_what_to_do(trajectory_run: Any, tmp_path: Path) -> None:
    with pytest.raises(TraceError, match="positive period"):
        animate_run(
            trajectory_run.db_path, trajectory_run.run, tmp_path / "x.gif", CAMERA, period=0
        )


def test_with_no_camera_the_film_follows_the_robot(trajectory_run: Any, tmp_path: Path) -> None:
    fixed = animate_run(
        trajectory_run.db_path, trajectory_run.run, tmp_path / "fixed.gif", CAMERA,
        width=WIDTH, height=HEIGHT, period=PERIOD,
    )  # fmt: skip
    followed = animate_run(
        trajectory_run.db_path, trajectory_run.run, tmp_path / "followed.gif",
        width=WIDTH, height=HEIGHT, period=PERIOD,
    )  # fmt: skip
    assert followed.frames == fixed.frames  # the same moments, from another camera
    with Image.open(tmp_path / "fixed.gif") as a, Image.open(tmp_path / "followed.gif") as b:
        first_a = np.asarray(a.convert("RGB"), dtype=np.int16)
        first_b = np.asarray(b.convert("RGB"), dtype=np.int16)
    assert (np.abs(first_a - first_b).max(axis=2) > 40).mean() > 0.05
