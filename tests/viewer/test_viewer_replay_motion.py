"""Replaying trajectories in the viewer: the moments between states, and playing them."""

from __future__ import annotations

import importlib.util
import socket
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import numpy as np
import pytest

from robocram.traces import TraceDatabase, require_run, run_trajectories, world_state_times
from robocram.viewer import Viewer, replay_viewer

PERIOD = 0.1  # [s] between the viewer's moments along a trajectory
TOL = 1e-6  # [rad | m]


def _trajectory_run_module() -> ModuleType:
    """tests/traces/trajectory_run.py (tests are not a package: loaded by path)."""
    path = Path(__file__).resolve().parents[1] / "traces" / "trajectory_run.py"
    spec = importlib.util.spec_from_file_location("viewer_trajectory_run", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@pytest.fixture(scope="module")
def replayed(tmp_path_factory: pytest.TempPathFactory) -> Iterator[tuple[Any, Viewer]]:
    module = _trajectory_run_module()
    traced = module.traced_trajectory_run(tmp_path_factory.mktemp("replay") / "runs.db")
    with TraceDatabase(traced.db_path, create=False) as db:
        viewer = replay_viewer(db, traced.run, port=_free_port(), period=PERIOD)
    yield traced, viewer
    viewer.close()
    traced.world.close()


def test_the_slider_holds_the_states_and_the_samples_between(replayed: Any) -> None:
    traced, viewer = replayed
    with TraceDatabase(traced.db_path, create=False) as db:
        states = world_state_times(db, traced.run)
        stored = run_trajectories(db, traced.run)  # the arm's, the torso's, the base's
    moments = [viewer.timeline[i] for i in range(len(viewer.timeline))]
    assert [m.time for m in moments if m.trajectory is None] == [t for _, t, _ in states]
    assert [s.kind for s in stored] == ["arm", "torso", "base"]
    samples = sum(int(np.ceil(s.duration / PERIOD)) for s in stored)
    assert len(moments) == len(states) + samples + len(stored)  # each one's both ends
    assert viewer.shown == len(moments) - 1
    final = viewer.display.pose("mug-1").position
    assert final == pytest.approx(traced.world.pose("mug-1").position, abs=TOL)


@pytest.mark.parametrize("t", [0.0, 0.5, 1.3, 2.0, 4.0])
def test_the_arm_is_where_its_trajectory_was_at_each_time(replayed: Any, t: float) -> None:
    traced, viewer = replayed
    with TraceDatabase(traced.db_path, create=False) as db:
        arm = next(s for s in run_trajectories(db, traced.run) if s.kind == "arm")
        start = require_run(db, traced.run).start
    index = viewer.timeline.index_at_replay(start + arm.start + t + 1e-9)
    viewer.show(index)
    moment = viewer.timeline[index]
    assert moment.trajectory == arm.index
    assert moment.sample_time == pytest.approx(t, abs=1e-9)
    joints = viewer.display.joint_states("pr2")
    got = [joints[name] for name in arm.joint_names]
    assert np.allclose(got, traced.arm.at(t), atol=TOL)
    ((_, link), frame) = next(
        kv for kv in viewer.view.frames.items() if kv[0] == ("pr2", "r_forearm_link")
    )
    forearm = viewer.display.link_pose("pr2", link)
    assert np.allclose(frame.position, forearm.position, atol=1e-9)  # drawn where it is


def test_the_base_drives_its_path(replayed: Any) -> None:
    traced, viewer = replayed
    with TraceDatabase(traced.db_path, create=False) as db:
        base = next(s for s in run_trajectories(db, traced.run) if s.kind == "base")
        start = require_run(db, traced.run).start
    for t in (0.5, 1.5, base.duration):
        viewer.show(viewer.timeline.index_at_replay(start + base.start + t + 1e-9))
        x, y, _ = traced.base.at(t)
        assert viewer.display.pose("pr2").position[:2] == pytest.approx((x, y), abs=TOL)


def test_play_steps_at_the_replay_clock_to_the_end(replayed: Any) -> None:
    traced, viewer = replayed
    pauses = dict(viewer.player.pauses(0))
    along_arm = [
        pauses[i]
        for i in range(1, len(viewer.timeline))
        if viewer.timeline[i].trajectory == 0 and viewer.timeline[i].sample_time > 0
    ]
    assert along_arm[:-1] == pytest.approx([PERIOD] * (len(along_arm) - 1), abs=1e-6)
    assert 0 < along_arm[-1] <= PERIOD + 1e-9  # the last sample is the trajectory's end
    viewer.show(0)
    viewer.player.speed = 100.0  # the steps, not their pace, are under test
    viewer.toggle_play()
    viewer.player.wait()
    assert viewer.shown == len(viewer.timeline) - 1
    assert int(viewer.slider.value) == viewer.shown
