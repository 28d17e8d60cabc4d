"""The viewer's first camera frames the robot at its task, the task whose world is shown is
marked, and a caption that grows never moves the slider (issue 41, the viewer items)."""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from robocram.scenes import kitchen_scene
from robocram.traces import TraceDatabase
from robocram.viewer import Viewer, replay_viewer
from robocram.viewer.headless_browser import HeadlessChromium
from robocram.viewer.page_picture import DISMISS_NOTICES, open_viewer
from robocram.viewer.task_panel import CURRENT
from tests.pinhole import box_corners, view_offsets
from tests.viewer.conftest import free_port

SLIDER_TOP = """(() => {
  const label = [...document.querySelectorAll('label, p, span, div')]
    .find(e => e.childElementCount === 0 && e.textContent.trim() === 'World state');
  return label ? label.getBoundingClientRect().top : -1;
})()"""
SETTLE_LOOKS = 150  # 0.2 s apart: a guard against a page that never settles
LONG = "a caption long enough to wrap onto several lines " * 6


def test_the_first_camera_frames_the_robot_from_behind_at_a_useful_size() -> None:
    scene = kitchen_scene("pr2")
    with scene.world as world, Viewer(world, port=free_port()) as viewer:
        camera = viewer.server.initial_camera
        eye, target = np.asarray(camera.position), np.asarray(camera.look_at)
        fov = float(camera.fov)
        robot = box_corners(*world.aabb("pr2"))
        offsets = view_offsets(robot, eye, target, fov)
        assert np.abs(offsets).max() <= 1.0  # the whole robot is in view
        height = offsets[:, 1].max() - offsets[:, 1].min()
        assert height > 0.35  # and more than a sixth of the picture high (0.35 of 2)
        mug = box_corners(*world.aabb("mug-1"))  # the item its task is about, 2 m away
        assert np.abs(view_offsets(mug, eye, target, fov)).max() <= 1.0
        base = np.asarray(world.pose("pr2").position)
        x, y, z, w = world.pose("pr2").orientation
        facing = np.array([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 0.0])
        assert float((eye - base) @ facing) < 0.0  # seen from behind: the counter is beyond


def test_replay_marks_the_task_whose_world_is_shown(live_run: Any) -> None:
    with TraceDatabase(live_run.db_path, create=False) as db:
        viewer = replay_viewer(db, live_run.run, port=free_port())
    with viewer:
        panel = viewer.tasks
        first_motion = next(i for i in range(len(viewer.timeline)) if viewer.timeline[i].task_path)
        moment = viewer.timeline[first_motion]
        viewer.show(first_motion)
        assert panel.current == moment.task_path
        marked = [b.label for b in panel._buttons.values() if b.label.startswith(CURRENT)]
        assert len(marked) == 1 and panel._buttons[moment.task_path].label == marked[0]
        viewer.show(len(viewer.timeline) - 1)
        last = viewer.timeline[len(viewer.timeline) - 1].task_path
        assert panel.current == (last or None)
        assert not panel._buttons[moment.task_path].label.startswith(CURRENT) or (
            moment.task_path == last
        )
        assert panel.labels() == live_run.viewer.tasks.labels()  # the mark is not a label


def _settled_top(browser: HeadlessChromium) -> float:
    """The slider label's top [px] once the page stops moving (notices dismissed): a page
    still loading, or showing a connection notice, moves everything below."""
    last = -1.0
    for _ in range(SETTLE_LOOKS):
        browser.evaluate(DISMISS_NOTICES)
        top = float(browser.evaluate(SLIDER_TOP))
        if top > 0 and top == last:
            return top
        last = top
        time.sleep(0.2)
    raise AssertionError(f"the slider did not settle in {SETTLE_LOOKS} looks")


def test_a_long_caption_leaves_the_slider_where_it_was(live_run: Any) -> None:
    viewer = live_run.viewer
    caption = viewer.caption.content  # put back: the other viewer tests share the viewer
    try:
        with HeadlessChromium(1024, 640) as browser:
            open_viewer(browser, viewer, "World state")
            viewer.caption.content = "one line"
            browser.wait_for_text("one line")
            before = _settled_top(browser)
            viewer.caption.content = LONG
            browser.wait_for_text("several lines")
            after = _settled_top(browser)
    finally:
        viewer.caption.content = caption
    assert after == before
