"""Trace and viewer figures: tracing overhead on the PR2 pick-up (traced against untraced,
interleaved in one run and one world) and the browser viewer's update rate.

Prints medians over ``runs`` plans; no reference system is installable here (PyCRAM's
ORM logging needs PyCRAM and ROS). Usage: ``python benchmarks/trace_bench.py [runs]``.
"""

from __future__ import annotations

import contextlib
import socket
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from robocram.execution import listening
from robocram.plans import pick_up
from robocram.projection import simulated_robot
from robocram.scenes import TabletopScene, tabletop_scene
from robocram.traces import TraceDatabase, Tracer, runs


def _plan_time(scene: TabletopScene, around: Callable[[], Any]) -> float:
    """Seconds [s] for one pick-up inside the context ``around()``, world restored after."""
    return _plan_times(scene, around)[0]


def _plan_times(scene: TabletopScene, around: Callable[[], Any]) -> tuple[float, float]:
    """Wall and process CPU seconds [s] of one pick-up inside ``around()``, world restored.

    CPU time is the steadier figure on a loaded machine (other processes' work is not in
    it); the tracer runs in the plan's thread, so it counts all the tracer's work.
    """
    with scene.world.snapshots.stored_state():
        start, cpu = time.perf_counter(), time.process_time()
        with around(), simulated_robot(scene.world, scene.robot, name="pick-mug"):
            pick_up(scene.look_target)
        return time.perf_counter() - start, time.process_time() - cpu


def _print_medians(times: dict[str, list[tuple[float, float]]], base_name: str) -> None:
    """One line per mode: median wall and CPU time [ms] and the change from ``base_name``."""
    base = [statistics.median(t[i] for t in times[base_name]) for i in (0, 1)]
    for name, values in times.items():
        wall, cpu = (statistics.median(t[i] for t in values) for i in (0, 1))
        print(
            f"  {name:30} {wall * 1e3:7.1f} ms {100 * (wall / base[0] - 1):+6.1f} %"
            f"  | {cpu * 1e3:7.1f} ms {100 * (cpu / base[1] - 1):+6.1f} %"
        )


def tracing_overhead(count: int, db: Path) -> None:
    """Untraced, traced (tree only) and traced with world states, interleaved.

    The database is opened once, as a batch of projections would; each traced plan writes
    its tasks (one transaction per motion) and, with a world, a state after every motion.
    """
    scene = tabletop_scene("pr2")
    store = TraceDatabase(db)
    tree_only, with_world = Tracer(store), Tracer(store, scene.world)
    modes: dict[str, Callable[[], Any]] = {
        "untraced": contextlib.nullcontext,
        "traced, task tree": lambda: listening(tree_only),
        "traced, tree + world states": lambda: listening(with_world),
    }
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in modes}
    _plan_time(scene, contextlib.nullcontext)  # warm caches (IK, meshes, KB)
    order = list(modes)
    for round_ in range(count):
        shift = round_ % len(order)  # rotate who goes first: no mode always pays a warm-up
        for name in order[shift:] + order[:shift]:
            times[name].append(_plan_times(scene, modes[name]))
    print(f"pick-up plan on the PR2, median of {count} interleaved runs each (wall | CPU):")
    _print_medians(times, "untraced")
    stored = runs(store)
    store.close()
    tasks = statistics.median(r.tasks for r in stored)
    print(f"  ({len(stored)} runs stored, {tasks:.0f} tasks per run; goal: overhead < 10 %)")
    scene.world.close()


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


def viewer_rates(count: int) -> None:
    """Live plan time with the viewer fed (pushes bounded or not), and scrubbing speed."""
    try:
        from robocram.viewer import LiveFeed, Viewer, live_listener
    except ImportError as err:
        print(f"viewer: skipped, {err.name} missing (pip install 'robocram[viewer]')")
        return
    scene = tabletop_scene("pr2")
    viewer = Viewer(scene.world, port=_free_port())
    bounded = live_listener.MAX_PUSH_RATE
    rates = {"unfed": 0.0, "fed, pushes unbounded": 1e9, f"fed, <= {bounded:.0f} pushes/s": bounded}
    times: dict[str, list[tuple[float, float]]] = {name: [] for name in rates}
    for _ in range(count):
        times["unfed"].append(_plan_times(scene, contextlib.nullcontext))
        for name, rate in list(rates.items())[1:]:
            live_listener.MAX_PUSH_RATE = rate  # read when the feeder starts
            with LiveFeed(viewer, scene.world) as feed:
                times[name].append(_plan_times(scene, lambda: listening(feed)))
                feed.flush()
    live_listener.MAX_PUSH_RATE = bounded
    states = len(viewer.timeline) // (2 * count)
    print(f"viewer, live pick-up ({states} world states per run), median of {count} (wall | CPU):")
    _print_medians(times, "unfed")
    frames = len(viewer.view.frames)
    shows = 5 * len(viewer.timeline)
    start = time.perf_counter()
    for i in range(shows):
        viewer.show(i % len(viewer.timeline))
    elapsed = time.perf_counter() - start
    print(
        f"viewer, scrubbing: {shows / elapsed:.1f} world states/s pushed "
        f"({frames} link frames each, {1e3 * elapsed / shows:.2f} ms per state)"
    )
    viewer.close()
    scene.world.close()


if __name__ == "__main__":
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    with tempfile.TemporaryDirectory() as tmp:
        tracing_overhead(count, Path(tmp) / "bench.db")
    viewer_rates(max(count // 2, 2))
