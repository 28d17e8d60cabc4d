"""The viewer without a browser: live feed, replay timeline, task links, bad input."""

from __future__ import annotations

import socket
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from robocram.cli import EXIT_INPUT, main
from robocram.traces import TraceDatabase, world_state_times
from robocram.viewer import NoWorld, PortInUse, Viewer, replay_viewer
from robocram.viewer.world_view import ROOT


def _task(tree: Any, name: str) -> Any:
    return next(t for t in tree.walk() if t.name == name)


def test_live_feed_fills_tree_and_timeline(live_run: Any) -> None:
    viewer = live_run.viewer
    labels = viewer.tasks.labels()
    assert labels[0] == "✓ pick-mug succeeded"
    assert "✗ too-high failed" in labels and "✓ perform gripping succeeded" in labels
    assert len(labels) == len(list(live_run.tree.walk()))
    motions = [t for t in live_run.tree.walk() if t.name.startswith("perform ")]
    assert len(viewer.timeline) == 1 + len(motions)
    assert viewer.shown == len(viewer.timeline) - 1  # followed the run to its end
    assert viewer.server.get_host() == "127.0.0.1"


def test_task_links_to_the_world_when_it_ended(live_run: Any) -> None:
    viewer = live_run.viewer
    opening = _task(live_run.tree, "perform opening")
    viewer.show_task(opening)
    assert viewer.timeline[viewer.shown].task_path == opening.path
    assert viewer.display.bodies.attached_to("mug-1") is None  # not yet gripped
    ((_, link), frame) = next(kv for kv in viewer.view.frames.items() if kv[0][0] == "mug-1")
    mug = viewer.display.pose("mug-1") if link == ROOT else viewer.display.link_pose("mug-1", link)
    assert np.allclose(frame.position, mug.position, atol=1e-9)
    viewer.show_task(live_run.tree)  # the root ended last: the final world again
    assert viewer.shown == len(viewer.timeline) - 1
    assert viewer.display.bodies.attached_to("mug-1") is not None


def test_replay_shows_the_stored_run(live_run: Any) -> None:
    with TraceDatabase(live_run.db_path, create=False) as db:
        times = world_state_times(db, live_run.run)
        viewer = replay_viewer(db, live_run.run, port=_free_port())
    with viewer:
        moments = [viewer.timeline[i] for i in range(len(viewer.timeline))]
        assert len([m for m in moments if m.trajectory is None]) == len(times)
        assert viewer.tasks.labels() == live_run.viewer.tasks.labels()
        mug = viewer.display.pose("mug-1").position
        assert np.allclose(mug, live_run.world.pose("mug-1").position, atol=1e-9)
        ((stored, live),) = zip(viewer.costmaps, live_run.viewer.costmaps, strict=True)
        assert np.array_equal(stored.weights, live.weights)  # the traced costmap is the fed one
        assert stored.task_path == live.task_path == "pick-mug"
        assert viewer.overlay.shown is stored  # drawn with the last world state


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def test_port_in_use_names_the_port_and_the_flag(live_run: Any) -> None:
    port = live_run.viewer.server.get_port()
    with pytest.raises(PortInUse, match=f"port {port} on 127.0.0.1 is in use.*--port"):
        Viewer(live_run.world, port=port)


def test_viewer_without_a_world_says_how_to_start_one() -> None:
    with pytest.raises(NoWorld, match="robocram view"):
        Viewer(None)


def test_cli_replay_bad_input(
    live_run: Any, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    db = str(live_run.db_path)
    assert main(["replay", db, "--run", "5", "--port", str(_free_port())]) == EXIT_INPUT
    assert f"has no run 5; runs stored: {live_run.run}" in capsys.readouterr().err
    port = str(live_run.viewer.server.get_port())
    assert main(["replay", db, "--port", port, "--seconds", "0"]) == EXIT_INPUT
    assert f"port {port} on 127.0.0.1 is in use" in capsys.readouterr().err


def test_cli_replay_lit_without_the_environment_map_serves_the_run(
    live_run: Any, capsys: pytest.CaptureFixture[str]
) -> None:
    port = _free_port()
    argv = ["replay", str(live_run.db_path), "--no-environment-map", "--port", str(port)]
    assert main([*argv, "--seconds", "0"]) == 0
    assert f"run {live_run.run} at http://127.0.0.1:{port}" in capsys.readouterr().out
