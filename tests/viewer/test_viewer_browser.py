"""The viewer in a real browser: headless Chromium shows the task tree and draws the robot.

One Chromium for the module (starting it and loading the page's scripts take seconds of
both cores): each test starts from a blank page, so it sees only the page it opens.
"""

from __future__ import annotations

import io
import math
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from PIL import Image

from robocram.viewer.headless_browser import HeadlessChromium
from robocram.viewer.page_picture import (
    CAMERA_AT,
    CAMERA_FROM,
    aim_camera,
    open_viewer,
    settled_screenshot,
)
from tests.pinhole import view_axes

OUT = Path(__file__).resolve().parents[2] / "out"
WIDTH, HEIGHT = 1024, 640  # [px] of the page
FOV = math.radians(75.0)  # viser's default vertical field of view
CHANGED = 40  # a pixel changed if a channel moved by more than this (of 255)
MARGIN = 12  # [px] around the robot's projected box
OVERHEAD_FROM, OVERHEAD_AT = (0.6, -2.6, 3.4), (0.6, 0.0, 0.0)  # [m] in map: sees the floor
PAIRS = 4  # picture pairs taken until one shows the change alone
POLLS, POLL = 600, 0.1  # looks at the page for a new frame [s apart]: a guard against hanging
ONLY_THERE = 0.97  # share of the changed pixels that must lie in the expected box


@pytest.fixture(scope="module")
def chromium() -> Iterator[HeadlessChromium]:
    """The module's headless Chromium, the page size the projection assumes."""
    with HeadlessChromium(WIDTH, HEIGHT) as browser:
        yield browser


@pytest.fixture
def browser(chromium: HeadlessChromium) -> HeadlessChromium:
    """The module's Chromium on a blank page: no earlier test's page is left to be read."""
    chromium.open("about:blank")
    for _ in range(POLLS):
        if chromium.evaluate("location.href") == "about:blank":
            return chromium
        time.sleep(POLL)
    raise AssertionError(f"the browser did not leave the last page in {POLLS} looks")


def _pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def _project(
    points: np.ndarray,
    eye_at: tuple[float, float, float] = CAMERA_FROM,
    looking_at: tuple[float, float, float] = CAMERA_AT,
) -> np.ndarray:
    """Pixel (column, row) of map points seen by the page's initial camera."""
    forward, right, up = view_axes(eye_at, looking_at)
    rel = points - np.asarray(eye_at)
    depth = rel @ forward
    half_h = math.tan(FOV / 2)
    ndc_x = (rel @ right) / (depth * half_h * WIDTH / HEIGHT)
    ndc_y = (rel @ up) / (depth * half_h)
    return np.stack([(ndc_x + 1) / 2 * WIDTH, (1 - ndc_y) / 2 * HEIGHT], axis=1)


def _next_frame(browser: HeadlessChromium, before: bytes) -> bytes:
    """The settled picture once the page has drawn a frame other than ``before``.

    Waits for the change just made to reach the picture, however long a loaded machine
    takes; only a page that never draws it ends the wait.
    """
    for _ in range(POLLS):
        if browser.screenshot() != before:
            return settled_screenshot(browser)
        time.sleep(POLL)
    raise AssertionError(f"the page drew no new frame in {POLLS} looks")


def _with_and_without(
    browser: HeadlessChromium,
    show: Callable[[bool], None],
    box: Callable[[np.ndarray, np.ndarray], np.ndarray],
) -> tuple[bytes, bytes, np.ndarray, np.ndarray]:
    """Pictures with and without a part (``show(True)``/``show(False)``), the changed
    pixels' rows and columns, and which of them lie in ``box``.

    A pair taken while the page still loads (meshes arrive over the websocket) differs
    outside the part too; the next pair, of the loaded page, shows the part alone.
    """
    shown = settled_screenshot(browser)
    for _ in range(PAIRS):
        show(False)
        hidden = _next_frame(browser, shown)
        changed = (np.abs(_pixels(shown) - _pixels(hidden)) > CHANGED).any(axis=2)
        rows, cols = np.nonzero(changed)
        inside = box(rows, cols)
        show(True)
        if inside.mean() > ONLY_THERE:
            break
        shown = _next_frame(browser, hidden)
    return shown, hidden, rows, cols


def _robot_box_on_screen(world: Any) -> tuple[float, float, float, float]:
    low, high = (np.asarray(v) for v in world.aabb("pr2"))
    corners = np.array(
        [[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    )
    px = _project(corners)
    return px[:, 0].min(), px[:, 1].min(), px[:, 0].max(), px[:, 1].max()


def test_browser_shows_tree_and_draws_the_robot(live_run: Any, browser: HeadlessChromium) -> None:
    viewer = live_run.viewer
    aim_camera(viewer)
    shown = [f"{task.name} {task.status.value}" for task in live_run.tree.walk()]
    # the tree's rows are drawn one after another: wait for all of them, not the first
    text = open_viewer(browser, viewer, "perform moving-tcp#3", *shown)
    for task in live_run.tree.walk():
        assert f"{task.name} {task.status.value}" in text, task.path
    assert "too-high failed" in text and "pick-mug succeeded" in text
    left, top, right, bottom = _robot_box_on_screen(live_run.world)

    def in_box(rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        return (
            (cols >= left - MARGIN)
            & (cols <= right + MARGIN)
            & (rows >= top - MARGIN)
            & (rows <= bottom + MARGIN)
        )

    def show(visible: bool) -> None:
        viewer.view.set_visible("pr2", visible)

    with_robot, without_robot, rows, cols = _with_and_without(browser, show, in_box)
    OUT.mkdir(exist_ok=True)
    (OUT / "viewer.png").write_bytes(with_robot)
    (OUT / "viewer_without_robot.png").write_bytes(without_robot)
    box_area = (right - left) * (bottom - top)
    assert len(rows) > 0.1 * box_area  # the robot covers a good part of its box
    assert in_box(rows, cols).mean() > ONLY_THERE  # and nothing changed elsewhere


def test_browser_draws_the_costmap_where_its_cells_are(
    live_run: Any, browser: HeadlessChromium
) -> None:
    viewer = live_run.viewer
    (costmap,) = viewer.costmaps  # where to stand to reach the mug, from the live feed
    viewer.show(len(viewer.timeline) - 1)
    assert viewer.overlay.shown is costmap
    viewer.server.initial_camera.position = OVERHEAD_FROM
    viewer.server.initial_camera.look_at = OVERHEAD_AT
    points, _ = costmap.cells()
    px = _project(points, OVERHEAD_FROM, OVERHEAD_AT)
    on_screen = (px[:, 0] >= 0) & (px[:, 0] < WIDTH) & (px[:, 1] >= 0) & (px[:, 1] < HEIGHT)
    assert on_screen.sum() > 50  # the camera sees a good part of the costmap
    left, top = px[on_screen].min(axis=0) - MARGIN
    right, bottom = px[on_screen].max(axis=0) + MARGIN

    def in_box(rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
        return (cols >= left) & (cols <= right) & (rows >= top) & (rows <= bottom)

    try:
        open_viewer(browser, viewer)
        pictures = _with_and_without(browser, viewer.overlay.set_visible, in_box)
    finally:
        viewer.overlay.set_visible(True)
        aim_camera(viewer)
    with_overlay, _, rows, cols = pictures
    OUT.mkdir(exist_ok=True)
    (OUT / "viewer_costmap.png").write_bytes(with_overlay)
    assert len(rows) > 1500  # the cells the robot leaves in sight: ~60 px each from here
    assert in_box(rows, cols).mean() > ONLY_THERE  # and nothing changed away from the cells
