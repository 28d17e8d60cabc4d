"""One projection driver kept running across a test module's tests, reset between them.

A driver takes seconds to start (a fresh interpreter, the scene, the robot's geometry) and
milliseconds to reset (``robocram/ros_driver/driver_reset.py``). ``with pool(robot,
scene=..., goal_log=...) as driver:`` gives a driver serving that robot and scene: the one
already running when it was started with the same robot, scene, controllers and ROS
facts, reset to the per-test settings (goal log, clock offset, speeds, fault, tf lag); else a
new one, the old one stopped first (two drivers would serve the same names). A driver a
test killed, or one whose goals ignore cancels (they never end), is not reused.

ROS 2: each driver the pool starts gets a domain of its own (``free_domain``), set as
``ROS_DOMAIN_ID`` inside the block, so a client started there finds it.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from robocram.ros_driver.driver_process import DriverProcess

NOT_REUSED = ("ignore_cancel",)  # faults whose goals never end: a reset would wait in vain


@dataclass(frozen=True)
class Shape:
    """What a driver is started with that a reset does not change."""

    robot: str
    scene: str
    controllers: str
    ros_facts: str  # the facts file's text ("" for the packaged facts)


class DriverPool:
    """The running driver of one ROS master (ROS 1) or of a module's ROS 2 tests."""

    def __init__(self, master_uri: str = "", ros: int = 1) -> None:
        self.master_uri = master_uri
        self.ros = ros
        self.started = 0  # drivers started (for tests of the pool)
        self._driver: DriverProcess | None = None
        self._shape: Shape | None = None
        self._domain: contextlib.ExitStack | None = None
        self._domain_id = 0

    @contextlib.contextmanager
    def __call__(
        self,
        robot: str = "pr2",
        *,
        scene: str = "tabletop",
        controllers: str = "projection",
        ros_facts: Path | None = None,
        tf_lag: float = 0.0,
        goal_log: Path | None = None,
        clock_offset: float = 0.0,
        base_speed: float = 0.0,
        time_scale: float = 0.0,
        fault: str = "none",
    ) -> Iterator[DriverProcess]:
        """A driver of this shape, as fresh, with these settings, for the block."""
        facts = "" if ros_facts is None else ros_facts.read_text(encoding="utf-8")
        shape = Shape(robot, scene, controllers, facts)
        settings = {
            "goal_log": goal_log,
            "clock_offset": clock_offset,
            "base_speed": base_speed,
            "time_scale": time_scale,
            "fault": fault,
            "tf_lag": tf_lag,
        }
        driver = self._driver
        if driver is not None and self._shape == shape and driver.running:
            driver.reset(**settings)
        else:
            self.close()
            if self.ros == 2:
                from robocram.ros.ros2_domain import free_domain

                self._domain = contextlib.ExitStack()
                self._domain_id = self._domain.enter_context(free_domain())
            with self._in_domain():
                driver = self._start(shape, ros_facts, settings)
        try:
            with self._in_domain():
                yield driver
        finally:
            if fault in NOT_REUSED or not driver.running:
                self.close()

    def _start(
        self, shape: Shape, ros_facts: Path | None, settings: dict[str, object]
    ) -> DriverProcess:
        driver = DriverProcess(
            self.master_uri,
            shape.robot,
            scene=shape.scene,
            controllers=shape.controllers,
            ros_facts=ros_facts,
            ros=self.ros,
            domain_id=self._domain_id,
            **settings,
        )
        try:
            driver.start()
        except BaseException:
            self.close()
            raise
        self._driver, self._shape = driver, shape
        self.started += 1
        return driver

    @property
    def domain_id(self) -> int:
        """ROS 2: the domain of the running driver."""
        return self._domain_id

    @contextlib.contextmanager
    def _in_domain(self) -> Iterator[None]:
        """ROS 2: the driver's domain in the environment, its traffic kept on this machine."""
        if self.ros != 2:
            yield
            return
        saved = {k: os.environ.get(k) for k in ("ROS_DOMAIN_ID", "ROS_AUTOMATIC_DISCOVERY_RANGE")}
        os.environ["ROS_DOMAIN_ID"] = str(self._domain_id)
        os.environ["ROS_AUTOMATIC_DISCOVERY_RANGE"] = "LOCALHOST"
        try:
            yield
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value

    def close(self) -> None:
        """Stop the running driver, if any, and give its ROS 2 domain back."""
        if self._driver is not None:
            self._driver.stop()
        if self._domain is not None:
            self._domain.close()
        self._driver, self._shape, self._domain = None, None, None
