"""Start the projection driver node as a process and stop it by its PID (tests, demos, benchmarks).

``with DriverProcess(master_uri, robot="pr2", time_scale=0.0) as driver:`` waits until
the node printed ``ready``; ``driver.kill()`` ends it at once (a robot dying mid-goal);
leaving the block stops it if it still runs. Its output goes to a log file, never a pipe
that could fill up and block it. ``driver.reset(...)`` puts the running driver back to the
state it started in, with new per-run settings (``driver_reset.py``): tests share one.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from types import TracebackType
from typing import Any

from robocram.ros.errors import RosNodeError
from robocram.ros_driver.driver_reset import GOALS_END_TIMEOUT, DriverSettings

START_TIMEOUT = 60.0  # [s]
RESET_TIMEOUT = GOALS_END_TIMEOUT + 10.0  # [s] for the driver to answer a reset
STOP_TIMEOUT = 10.0  # [s]


class DriverProcess:
    """``python -m robocram.ros_driver`` with the given options, as a context manager."""

    def __init__(
        self,
        master_uri: str,
        robot_name: str = "pr2",
        base_speed: float = 0.0,
        time_scale: float = 0.0,
        fault: str = "none",
        ros_facts: Path | None = None,
        goal_log: Path | None = None,
        controllers: str = "projection",
        clock_offset: float = 0.0,
        scene: str = "tabletop",
        ros: int = 1,
        domain_id: int = 0,
        tf_lag: float = 0.0,
    ) -> None:
        """``goal_log``: the driver appends each goal it receives there (``received_goals``);
        ``controllers="pr2"``: the real PR2's controllers; ``clock_offset`` [s] on stamps;
        ``scene``: ``"tabletop"`` or ``"kitchen"`` (``kitchen_scene``); ``ros=2``: a ROS 2
        robot on ``domain_id`` (``master_uri`` is then not used); ``tf_lag`` [s]: ROS 1's
        transforms sent that late, as a loaded client's tf thread handles them."""
        self.args = [
            sys.executable, "-m", "robocram.ros_driver", "--robot", robot_name,
            "--master-uri", master_uri, "--base-speed", str(base_speed),
            "--time-scale", str(time_scale), "--fault", fault,
            "--controllers", controllers, "--clock-offset", str(clock_offset), "--scene", scene,
            "--ros", str(ros), "--domain-id", str(domain_id), "--tf-lag", str(tf_lag),
        ]  # fmt: skip
        if ros_facts is not None:
            self.args += ["--ros-facts", str(ros_facts)]
        self.goal_log = goal_log
        if goal_log is not None:
            self.args += ["--goal-log", str(goal_log)]
        self.master_uri = master_uri
        self.settings = _settings(goal_log, clock_offset, base_speed, time_scale, fault, tf_lag)
        self._resets = 0
        self.process: subprocess.Popen[bytes] | None = None
        self._log = tempfile.NamedTemporaryFile(  # noqa: SIM115 - closed by stop()
            prefix="robocram-driver-", suffix=".log"
        )

    @property
    def log(self) -> str:
        """What the driver printed so far."""
        return Path(self._log.name).read_text(errors="replace")

    def received_goals(self, server: str | None = None) -> list[dict[str, Any]]:
        """The goals the driver received so far (of ``server``, or all), oldest first."""
        return [e["goal"] for e in self._log_entries(server) if "goal" in e]

    def cancels_seen(self, server: str | None = None) -> list[float]:
        """When cancels reached the driver's servers (``time.monotonic()``), oldest first."""
        return [e["cancel_seen"] for e in self._log_entries(server) if "cancel_seen" in e]

    def _log_entries(self, server: str | None) -> list[dict[str, Any]]:
        if self.goal_log is None:
            raise RosNodeError("the driver keeps no goal log; start it with goal_log=PATH")
        if not self.goal_log.exists():
            return []
        entries = [json.loads(line) for line in self.goal_log.read_text().splitlines() if line]
        return [e for e in entries if server is None or e["server"] == server]

    def start(self) -> DriverProcess:
        """Start the node and wait for its ``ready`` line."""
        env = dict(os.environ, ROS_MASTER_URI=self.master_uri) if self.master_uri else None
        self.process = subprocess.Popen(
            self.args, stdin=subprocess.PIPE, stdout=self._log, stderr=subprocess.STDOUT, env=env
        )
        deadline = time.monotonic() + START_TIMEOUT
        while "ready" not in self.log:
            if self.process.poll() is not None or time.monotonic() > deadline:
                printed = self.log  # before stop() removes the log file
                self.stop()
                raise RosNodeError(f"the driver did not start ({' '.join(self.args)}):\n{printed}")
            time.sleep(0.05)
        return self

    def reset(
        self,
        goal_log: Path | None = None,
        clock_offset: float = 0.0,
        base_speed: float = 0.0,
        time_scale: float = 0.0,
        fault: str = "none",
        tf_lag: float = 0.0,
    ) -> DriverProcess:
        """Put the running driver back to the world it started in, taking these settings
        (as the constructor's) once its goals ended; return when it says it is done."""
        process = self.process
        if process is None or process.stdin is None or process.poll() is not None:
            raise RosNodeError("the driver does not run: start it before resetting it")
        settings = _settings(goal_log, clock_offset, base_speed, time_scale, fault, tf_lag)
        self._resets += 1
        number = self._resets
        try:
            process.stdin.write(f"reset {number} {settings.to_json()}\n".encode())
            process.stdin.flush()
        except OSError as err:  # it died just now
            raise RosNodeError(f"the driver was not reset: {err}") from err
        deadline = time.monotonic() + RESET_TIMEOUT
        done, failed = f"reset {number} done", f"reset {number} failed"
        while done not in (log := self.log):
            if failed in log or process.poll() is not None or time.monotonic() > deadline:
                raise RosNodeError(f"the driver was not reset:\n{log[-2000:]}")
            time.sleep(0.01)
        self.settings = settings
        self.goal_log = goal_log
        return self

    @property
    def running(self) -> bool:
        """Whether the driver's process runs."""
        return self.process is not None and self.process.poll() is None

    def kill(self) -> None:
        """End the driver at once (SIGKILL), as a crash would."""
        if self.process is not None and self.process.poll() is None:
            self.process.kill()
            self.process.wait()

    def stop(self) -> None:
        """Ask the driver to end (SIGTERM), kill it if it does not, and wait for it."""
        process = self.process
        if process is not None and process.stdin is not None:
            process.stdin.close()
        if process is not None and process.poll() is None:
            process.terminate()
            try:
                process.wait(STOP_TIMEOUT)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
        self._log.close()

    def __enter__(self) -> DriverProcess:
        return self.start()

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.stop()


def _settings(
    goal_log: Path | None,
    clock_offset: float,
    base_speed: float,
    time_scale: float,
    fault: str,
    tf_lag: float,
) -> DriverSettings:
    """The per-run settings a driver starts with or is reset to."""
    log = None if goal_log is None else str(goal_log)
    return DriverSettings(log, clock_offset, base_speed, time_scale, fault, tf_lag)
