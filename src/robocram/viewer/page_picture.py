"""Pictures of the viewer page from headless Chromium, taken once the page has settled."""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from robocram.viewer.headless_browser import HeadlessChromium
from robocram.viewer.viewer import Viewer

CAMERA_FROM = (2.2, 1.4, 2.9)  # [m] in map: the initial camera, above the robot's table
CAMERA_AT = (0.35, -0.1, 0.65)  # [m] in map: what it looks at
SETTLE_TIMEOUT = 60.0  # [s] for the 3-D view to stop changing

DISMISS_NOTICES = """
document.querySelectorAll('.mantine-Notification-root, .mantine-Notifications-notification')
  .forEach(e => e.remove()); true
"""


def aim_camera(viewer: Viewer) -> None:
    """Point the page's initial camera at the table from the front corner."""
    viewer.server.initial_camera.position = CAMERA_FROM
    viewer.server.initial_camera.look_at = CAMERA_AT


def settled_screenshot(browser: HeadlessChromium, interval: float = 0.5) -> bytes:
    """Screenshots until two in a row are equal (the scene has drawn); the last one."""
    deadline = time.monotonic() + SETTLE_TIMEOUT
    last = browser.screenshot()
    while time.monotonic() < deadline:
        time.sleep(interval)
        browser.evaluate(DISMISS_NOTICES)
        shot = browser.screenshot()
        if shot == last:
            return shot
        last = shot
    return last


def open_viewer(browser: HeadlessChromium, viewer: Viewer, *texts: str) -> str:
    """Load the viewer's page and wait for its task tree (and ``texts``); the page text."""
    browser.open(viewer.url)
    return browser.wait_for_text("Task tree", *texts)


@contextmanager
def picture_page(viewer: Viewer, **size: Any) -> Iterator[HeadlessChromium]:
    """A headless browser showing the viewer's page, the camera aimed at the table.

    Open it before a live run starts: it is the browser a waiting ``robocram view`` serves.
    """
    aim_camera(viewer)
    with HeadlessChromium(**size) as browser:
        open_viewer(browser, viewer)
        yield browser


def save_picture(browser: HeadlessChromium, path: str | Path) -> Path:
    """Save a PNG of the page once it has settled."""
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_bytes(settled_screenshot(browser))
    return Path(path)


def take_picture(viewer: Viewer, path: str | Path, **size: Any) -> Path:
    """Save a PNG of the viewer's page as a browser shows it."""
    with picture_page(viewer, **size) as browser:
        return save_picture(browser, path)
