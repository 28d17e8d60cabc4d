"""The browser viewer: the 3-D world and the task tree of a run in one page, live or replayed.

Built on viser (three.js in the browser, a Python server pushing scene updates over a
websocket), made for robotics: meshes, frames and GUI controls without our own JavaScript.
The viewer draws its own copy of the world, so scrubbing back never disturbs a running
plan; it binds 127.0.0.1 unless another host is asked for explicitly.
"""

from __future__ import annotations

import bisect
import errno
import queue
import socket
import threading
import time
from collections.abc import Iterable
from typing import Any

import viser

from robocram.execution import TaskSnapshot
from robocram.motion import JointTrajectory
from robocram.traces import (
    StoredCostmap,
    TraceDatabase,
    build_scene,
    require_run,
    robot_in,
    run_costmaps,
    set_robot_joints,
    task_tree,
)
from robocram.viewer.costmap_overlay import CostmapOverlay
from robocram.viewer.errors import NoWorld, PortInUse
from robocram.viewer.player import Player
from robocram.viewer.task_panel import TaskPanel
from robocram.viewer.timeline import REPLAY_PERIOD, Moment, Timeline
from robocram.viewer.world_view import WorldView
from robocram.world import RobotHandle, World
from robocram.world.view_framing import Bounds, frame_task

DEFAULT_HOST = "127.0.0.1"
DEFAULT_PORT = 8080
READY_PICTURE = 16  # [px] side of the picture asked of a page to know it has drawn
DRAW_TIMEOUT = 60.0  # [s] a paced live run waits at most this long for a page to draw


def check_port(host: str, port: int) -> None:
    """Raise PortInUse if ``host:port`` cannot be bound now."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        try:
            probe.bind((host, port))
        except OSError as err:
            if err.errno in (errno.EADDRINUSE, errno.EACCES):
                raise PortInUse(host, port) from err
            raise


class Viewer:
    """A viser server showing ``world`` (drawn from a private copy) and a task tree.

    ``environment_map=False`` lights the scene with viser's default lights only, without its
    environment map (image-based lighting): software WebGL (no GPU: headless, Docker) spends
    seconds of CPU building that map on each page load.
    """

    def __init__(
        self,
        world: World | None,
        host: str = DEFAULT_HOST,
        port: int = DEFAULT_PORT,
        title: str = "robocram",
        *,
        environment_map: bool = True,
    ) -> None:
        if world is None:
            raise NoWorld()
        check_port(host, port)
        self.server = viser.ViserServer(host=host, port=port, label=title, verbose=False)
        self.server.scene.set_up_direction("+z")
        if not environment_map:
            self.server.scene.configure_environment_map(None)
        self.display = world.copy()
        self.view = WorldView(self.server, self.display)
        self.timeline = Timeline()
        self._lock = threading.Lock()
        self.frame(world)
        gui = self.server.gui
        gui.add_markdown(f"**{title}**")
        self.follow = gui.add_checkbox("Follow live", initial_value=True)
        self.slider = gui.add_slider("World state", min=0, max=1, step=1, initial_value=0)
        self.slider.on_update(lambda _event: self._slider_moved())
        self.player = Player(self.timeline, self._play_step)
        self.play_button = gui.add_button("Play / stop")
        self.play_button.on_click(lambda _event: self.toggle_play())
        # below the controls: a caption of two lines or one never moves the slider
        self.caption = gui.add_markdown("waiting for a run")
        self.costmaps: list[StoredCostmap] = []  # in time order
        self.overlay = CostmapOverlay(self.server)
        toggle = gui.add_checkbox("Costmaps", initial_value=True)
        toggle.on_update(lambda _event: self.overlay.set_visible(bool(toggle.value)))
        self.tasks = TaskPanel(gui, self.show_task)
        self.shown = -1  # index of the moment on screen
        self._browsers: queue.Queue[viser.ClientHandle] = queue.Queue()
        self.server.on_client_connect(self._browsers.put)

    def frame(self, world: World, more: Iterable[Bounds] = ()) -> None:
        """Aim the page's first camera over the shoulder of ``world``'s first robot, with
        the items near it and ``more`` bounds in view (none: viser's default view)."""
        robots = world.robots()
        if not robots:
            return
        camera = self.server.initial_camera
        framing = frame_task(world, robots[0], float(camera.fov), more)
        camera.position, camera.look_at = framing.eye, framing.target

    @property
    def url(self) -> str:
        """Where a browser finds the page."""
        return f"http://{self.server.get_host()}:{self.server.get_port()}"

    def wait_for_browser(self, timeout: float | None = None) -> bool:
        """Wait until a browser has opened the page and drawn the world (``timeout`` [s]
        for each, None: for ever); return whether one has.

        A page connects long before it has built the scene (software WebGL takes seconds);
        asking it for a small picture returns once it has drawn everything sent before,
        so a live run started after this is seen from its start.
        """
        try:
            browser = self._browsers.get(timeout=timeout)
        except queue.Empty:
            return False
        return _drawn(browser, timeout)

    def wait_until_drawn(self, timeout: float = DRAW_TIMEOUT) -> None:
        """Wait until every open page has drawn what was sent to it (or ``timeout`` [s])."""
        for browser in list(self.server.get_clients().values()):
            _drawn(browser, timeout)

    def play(
        self, trajectory: JointTrajectory, speed: float = 1.0, period: float = REPLAY_PERIOD
    ) -> None:
        """Move the robot along ``trajectory`` on screen, at ``speed`` times its own pace,
        one frame every ``period`` [s] of the trajectory's time.

        Starts from the moment shown (the state the motion started from, when following a
        live run); scrubbed back (not following), nothing is played.
        """
        if not self.follow.value or not trajectory.points:
            return
        with self._lock:
            robot = robot_in(self.display, trajectory.robot)
        where = f"**state {self.shown}**, then moving ({trajectory.kind})"
        for t, positions in trajectory.sampled(period):
            with self._lock:
                set_robot_joints(RobotHandle.of(self.display, robot), positions)
                self.view.show(self.display)
            self.caption.content = f"{where}: {t:.1f} of {trajectory.duration:.1f} s"
            time.sleep(period / speed)

    def add_moments(self, moments: list[Moment]) -> None:
        """Add world states; when following, show the newest at once."""
        index = max(self.timeline.add(moment) for moment in moments)
        self.slider.max = max(len(self.timeline) - 1, 1)
        if self.follow.value:
            _set_value(self.slider, index)
            self.show(index)

    def show(self, index: int) -> None:
        """Draw the world of moment ``index``."""
        with self._lock:
            if not 0 <= index < len(self.timeline):
                return
            moment = self.timeline[index]
            moment.state.apply(self.display)
            self.view.show(self.display)
            self.overlay.show(self.costmap_at(moment.time))
            self.shown = index
        self.tasks.highlight(moment.task_path)
        where = moment.task_path or "the start"
        if moment.trajectory is None:
            self.caption.content = f"**state {index}**: after {where}"
        else:
            self.caption.content = (
                f"**moment {index}**: trajectory {moment.trajectory} of {where} "
                f"at {moment.sample_time:.2f} s"
            )

    def add_costmap(self, costmap: StoredCostmap) -> None:
        """Add a costmap; it is drawn with the world states after it was built."""
        with self._lock:
            times = [c.time for c in self.costmaps]
            self.costmaps.insert(bisect.bisect_right(times, costmap.time), costmap)
        if self.shown >= 0:
            self.show(self.shown)

    def costmap_at(self, time: float) -> StoredCostmap | None:
        """The last costmap built at or before ``time`` [s since the epoch], if any."""
        times = [c.time for c in self.costmaps]
        index = bisect.bisect_right(times, time) - 1
        return self.costmaps[index] if index >= 0 else None

    def toggle_play(self) -> None:
        """Play the moments from the one shown (from the first at the end), or stop playing."""
        if self.player.playing:
            self.player.stop()
            return
        _set_value(self.follow, False)
        start = self.shown if 0 <= self.shown < len(self.timeline) - 1 else 0
        if start == 0:
            self._play_step(0)
        self.player.play(start)

    def _play_step(self, index: int) -> None:
        _set_value(self.slider, index)
        self.show(index)

    def _slider_moved(self) -> None:
        index = int(self.slider.value)
        if index != self.shown:
            self.show(index)

    def show_task(self, task: TaskSnapshot) -> None:
        """Show the world when ``task`` ended (the latest state if it is still running)."""
        time = task.end_time if task.end_time is not None else float("inf")
        _set_value(self.follow, False)
        index = self.timeline.index_at(time)
        _set_value(self.slider, index)
        self.show(index)

    def set_tree(self, tree: TaskSnapshot) -> None:
        """Show (or update) the task tree."""
        self.tasks.update(tree)

    def load_run(self, db: TraceDatabase, run: int, period: float = REPLAY_PERIOD) -> None:
        """Show stored run ``run`` of ``db``: its tree, its world states and, between them,
        its trajectories sampled every ``period`` [s]."""
        _set_value(self.follow, False)
        self.set_tree(task_tree(db, run))
        for costmap in run_costmaps(db, run):
            self.add_costmap(costmap)
        with self._lock:  # the display world plays the run through once
            stored = Timeline.of_replay(db, run, self.display, period)
            self.frame(self.display, _robot_bounds(self.display, stored))
        self.add_moments([stored[index] for index in range(len(stored))])
        _set_value(self.slider, len(self.timeline) - 1)
        self.show(len(self.timeline) - 1)

    def close(self) -> None:
        """Stop playing and serving, and free the display world."""
        self.player.stop()
        self.server.stop()
        self.display.close()

    def __enter__(self) -> Viewer:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def _robot_bounds(world: World, timeline: Timeline) -> list[Bounds]:
    """The first robot's bounds in each stored world state of ``timeline`` (applied to
    ``world``, which is left in the last): everywhere the run took it."""
    robots = world.robots()
    found = []
    for index in range(len(timeline)):
        moment = timeline[index]
        if robots and moment.trajectory is None:
            moment.state.apply(world)
            found.append(world.aabb(robots[0]))
    return found


def _drawn(browser: viser.ClientHandle, timeout: float | None) -> bool:
    """Whether the page drew a tiny picture in time: it has drawn all sent before it."""
    try:
        browser.get_render(READY_PICTURE, READY_PICTURE, timeout=timeout)
    except TimeoutError:
        return False
    return True


def _set_value(handle: Any, value: Any) -> None:
    """Set a GUI input's value (viser's stubs call it read-only; it is a synced property)."""
    setattr(handle, "value", value)  # noqa: B010


def replay_viewer(
    db: TraceDatabase,
    run: int,
    host: str = DEFAULT_HOST,
    port: int = DEFAULT_PORT,
    period: float = REPLAY_PERIOD,
    *,
    environment_map: bool = True,
) -> Viewer:
    """A viewer showing stored run ``run``, its world rebuilt from the stored scene.

    Its slider runs over the stored states and the trajectories' samples every ``period``
    [s] between them; the play button steps through them at the replay clock's pace.
    ``environment_map`` as for :class:`Viewer`.
    """
    row = require_run(db, run)
    if row.scene is None:
        raise NoWorld()
    with build_scene(row.scene, db=db) as world:
        viewer = Viewer(
            world, host, port, title=f"run {run}: {row.name}", environment_map=environment_map
        )
    viewer.load_run(db, run, period)
    return viewer
