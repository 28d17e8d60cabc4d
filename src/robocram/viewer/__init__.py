"""The browser viewer: a run's 3-D world and task tree in one page, live or replayed.

Needs the ``viewer`` extra (viser). ``Viewer(world)`` serves on 127.0.0.1:8080;
``with listening(LiveFeed(viewer, world)):`` feeds it from a running plan;
``replay_viewer(db, run)`` shows a stored run with a slider over its world states and the
samples of its trajectories between them, and a button that plays them.
"""

from robocram.viewer.errors import (
    NoWorld,
    PortInUse,
    ViewerArgumentError,
    ViewerError,
    ViewerUnavailable,
    ViewerUnknownKey,
)
from robocram.viewer.live_listener import LiveFeed
from robocram.viewer.player import Player
from robocram.viewer.timeline import Moment, Timeline
from robocram.viewer.viewer import DEFAULT_HOST, DEFAULT_PORT, Viewer, check_port, replay_viewer

__all__ = [
    "DEFAULT_HOST",
    "DEFAULT_PORT",
    "LiveFeed",
    "Moment",
    "NoWorld",
    "Player",
    "PortInUse",
    "Timeline",
    "Viewer",
    "ViewerArgumentError",
    "ViewerError",
    "ViewerUnavailable",
    "ViewerUnknownKey",
    "check_port",
    "replay_viewer",
]
