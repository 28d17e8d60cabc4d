"""Putting a running driver back to the state it started in, so tests can share one.

Starting a driver costs seconds (the interpreter, the scene, the robot's geometry); a
reset costs milliseconds. A driver started by :class:`DriverProcess` reads its standard
input: each line ``reset <n> <settings as JSON>`` waits for its running goals to end,
puts the world back as it was built (objects, poses, joints, attachments, held handles),
takes the per-run settings (:class:`DriverSettings`) and publishes the state; then the
driver prints ``reset <n> done`` (or ``reset <n> failed: <why>``). What it serves after
is what a driver freshly started with those settings serves.
"""

from __future__ import annotations

import json
import sys
import threading
from collections.abc import Callable
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import TextIO

from robocram.ros_driver.errors import DriverArgumentError, DriverError

GOALS_END_TIMEOUT = 10.0  # [s] a reset waits this long for running goals to end


class DriverBusy(DriverError):
    """A reset found goals still running after ``GOALS_END_TIMEOUT``."""

    summary = "the driver's goals did not end, so it was not reset"
    hint = "cancel the goals first, or stop the driver and start a new one"


@dataclass(frozen=True)
class DriverSettings:
    """What a reset may change: what a driver is started with besides its robot, scene,
    controllers and ROS facts (those shape its servers and stay)."""

    goal_log: str | None = None  # a file each goal is appended to (None: no log)
    clock_offset: float = 0.0  # [s] on every stamp
    base_speed: float = 0.0  # [m/s]; 0 jumps
    time_scale: float = 0.0  # trajectory time x; 0 jumps
    fault: str = "none"  # ProjectionDriver's FAULTS
    tf_lag: float = 0.0  # [s] ROS 1's /tf sent this late

    def to_json(self) -> str:
        """One line of JSON (the reset command's tail)."""
        return json.dumps(asdict(self))

    @classmethod
    def from_json(cls, text: str) -> DriverSettings:
        """The settings a reset line carries; a typed error for anything else."""
        try:
            fields = json.loads(text)
            return cls(**fields)
        except (ValueError, TypeError) as err:
            raise DriverArgumentError(f"a reset's settings are not {cls.__name__}: {err}") from err

    @property
    def goal_log_path(self) -> Path | None:
        """``goal_log`` as a path."""
        return None if self.goal_log is None else Path(self.goal_log)


def serve_resets(
    reset: Callable[[DriverSettings], None], commands: TextIO | None = None
) -> threading.Thread:
    """Read reset commands from ``commands`` (default: standard input) in a daemon thread,
    run each with ``reset`` and print how it ended; the end of the input ends the thread."""
    stream = sys.stdin if commands is None else commands
    thread = threading.Thread(target=_read, args=(reset, stream), daemon=True)
    thread.start()
    return thread


def _read(reset: Callable[[DriverSettings], None], stream: TextIO) -> None:
    for line in stream:
        word, _, rest = line.strip().partition(" ")
        if word != "reset":
            continue
        number, _, settings = rest.partition(" ")
        try:
            reset(DriverSettings.from_json(settings))
        except DriverError as err:
            print(f"reset {number} failed: {type(err).__name__}: {err}", flush=True)
            continue
        print(f"reset {number} done", flush=True)
