"""The viewer in a real browser: headless Chromium shows the task tree and draws the robot."""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

import numpy as np
from PIL import Image

from robocram.viewer.headless_browser import HeadlessChromium
from robocram.viewer.page_picture import (
    CAMERA_AT,
    CAMERA_FROM,
    aim_camera,
    open_viewer,
    settled_screenshot,
)

OUT = Path(__file__).resolve().parents[2] / "out"
WIDTH, HEIGHT = 1024, 640  # [px] of the page
FOV = math.radians(75.0)  # viser's default vertical field of view
CHANGED = 40  # a pixel changed if a channel moved by more than this (of 255)
MARGIN = 12  # [px] around the robot's projected box
OVERHEAD_FROM, OVERHEAD_AT = (0.6, -2.6, 3.4), (0.6, 0.0, 0.0)  # [m] in map: sees the floor


def _pixels(png: bytes) -> np.ndarray:
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def _project(
    points: np.ndarray,
    eye_at: tuple[float, float, float] = CAMERA_FROM,
    looking_at: tuple[float, float, float] = CAMERA_AT,
) -> np.ndarray:
    """Pixel (column, row) of map points seen by the page's initial camera."""
    eye, target = np.asarray(eye_at), np.asarray(looking_at)
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, (0.0, 0.0, 1.0))
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    rel = points - eye
    depth = rel @ forward
    half_h = math.tan(FOV / 2)
    ndc_x = (rel @ right) / (depth * half_h * WIDTH / HEIGHT)
    ndc_y = (rel @ up) / (depth * half_h)
    return np.stack([(ndc_x + 1) / 2 * WIDTH, (1 - ndc_y) / 2 * HEIGHT], axis=1)


def _robot_box_on_screen(world: Any) -> tuple[float, float, float, float]:
    low, high = (np.asarray(v) for v in world.aabb("pr2"))
    corners = np.array(
        [[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])]
    )
    px = _project(corners)
    return px[:, 0].min(), px[:, 1].min(), px[:, 0].max(), px[:, 1].max()


def test_browser_shows_tree_and_draws_the_robot(live_run: Any) -> None:
    viewer = live_run.viewer
    aim_camera(viewer)
    with HeadlessChromium(WIDTH, HEIGHT) as browser:
        text = open_viewer(browser, viewer, "perform moving-tcp#3")
        for task in live_run.tree.walk():
            assert f"{task.name} {task.status.value}" in text, task.path
        assert "too-high failed" in text and "pick-mug succeeded" in text
        with_robot = settled_screenshot(browser)
        with viewer.view.hidden("pr2"):
            without_robot = settled_screenshot(browser)
    OUT.mkdir(exist_ok=True)
    (OUT / "viewer.png").write_bytes(with_robot)
    (OUT / "viewer_without_robot.png").write_bytes(without_robot)
    changed = (np.abs(_pixels(with_robot) - _pixels(without_robot)) > CHANGED).any(axis=2)
    rows, cols = np.nonzero(changed)
    left, top, right, bottom = _robot_box_on_screen(live_run.world)
    inside = (
        (cols >= left - MARGIN)
        & (cols <= right + MARGIN)
        & (rows >= top - MARGIN)
        & (rows <= bottom + MARGIN)
    )
    box_area = (right - left) * (bottom - top)
    assert len(rows) > 0.1 * box_area  # the robot covers a good part of its box
    assert inside.mean() > 0.97  # and nothing changed elsewhere


def test_browser_draws_the_costmap_where_its_cells_are(live_run: Any) -> None:
    viewer = live_run.viewer
    (costmap,) = viewer.costmaps  # where to stand to reach the mug, from the live feed
    viewer.show(len(viewer.timeline) - 1)
    assert viewer.overlay.shown is costmap
    viewer.server.initial_camera.position = OVERHEAD_FROM
    viewer.server.initial_camera.look_at = OVERHEAD_AT
    try:
        with HeadlessChromium(WIDTH, HEIGHT) as browser:
            open_viewer(browser, viewer)
            with_overlay = settled_screenshot(browser)
            viewer.overlay.set_visible(False)
            without_overlay = settled_screenshot(browser)
    finally:
        viewer.overlay.set_visible(True)
        aim_camera(viewer)
    OUT.mkdir(exist_ok=True)
    (OUT / "viewer_costmap.png").write_bytes(with_overlay)
    changed = (np.abs(_pixels(with_overlay) - _pixels(without_overlay)) > CHANGED).any(axis=2)
    rows, cols = np.nonzero(changed)
    points, _ = costmap.cells()
    px = _project(points, OVERHEAD_FROM, OVERHEAD_AT)
    on_screen = (px[:, 0] >= 0) & (px[:, 0] < WIDTH) & (px[:, 1] >= 0) & (px[:, 1] < HEIGHT)
    assert on_screen.sum() > 50  # the camera sees a good part of the costmap
    left, top = px[on_screen].min(axis=0) - MARGIN
    right, bottom = px[on_screen].max(axis=0) + MARGIN
    inside = (cols >= left) & (cols <= right) & (rows >= top) & (rows <= bottom)
    assert len(rows) > 1500  # the cells the robot leaves in sight: ~60 px each from here
    assert inside.mean() > 0.97  # and nothing changed away from the cells
