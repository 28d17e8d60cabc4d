"""Errors of robocram.ros: set-up and configuration errors, and the lost-connection failure.

``RosError`` is the root of what goes wrong before or around a plan (the extra is not
installed, facts are missing, the ROS node cannot start). What goes wrong while a plan
runs is a plan failure: a resource's own failure class for ABORTED and REJECTED goals,
``ActionlibActionTimedOut`` for goals that exceed their time, ``RosConnectionLost`` when
the action server or our ROS node goes away mid-goal.
"""

from __future__ import annotations

from robocram.execution.failures import LowLevelFailure, SetupFailure

INSTALL_HINT = (
    "install it with `make setup` (or `bash tools/setup_ros.sh .venv` as root): it "
    "apt-get installs ROS 1 from Debian, generates control_msgs and puts both on the venv's path"
)


class RosError(Exception):
    """Root of robocram.ros's set-up and configuration errors."""


class RosExtraMissing(RosError, ImportError):
    """The ROS 1 Python packages robocram.ros needs are not importable."""


class RosConfigError(RosError):
    """A robot's ROS facts (action servers, topics, timeouts) are missing or wrong."""


class RosNodeError(RosError):
    """Our ROS node could not start or answer (no master, node process died)."""


class RosConnectionLost(LowLevelFailure):
    """The action server (or our ROS node) went away while a goal was running."""

    fields = ("server", "reason")
    summary = "the connection to the ROS action server was lost"
    hint = "check that the robot's driver and the ROS master are running, then retry"


class RosJointStateInvalid(LowLevelFailure):
    """The robot reported a joint position that is not a finite number."""

    topic: str | None = None
    joint: str | None = None
    value: float | None = None
    summary = "the robot reported a joint state that is not a number"
    hint = "check the robot's driver and the joint's encoder; nothing was sent"


class RosMasterUnreachable(RosNodeError):
    """No ROS master answered at the URI within the master timeout."""


class RosCancelIgnored(LowLevelFailure):
    """A cancelled goal's server did not confirm the cancel in time: the robot may still move."""

    server: str | None = None
    timeout: float | None = None  # [s] waited for the confirmation
    stopping: bool | None = None  # the cancel came from a stopped task (not a timeout)
    summary = "the action server ignored a cancel; the robot may still be moving"
    hint = (
        "stop the robot by its own means (run-stop), check its controller, then retry; "
        "ros_cancel_timeout/2 sets how long to wait for a confirmation"
    )


class RosCommandError(SetupFailure):
    """A command names what the robot's ROS side does not have (an arm, a joint, a motion)."""

    summary = "the command does not fit the robot behind ROS"
    hint = "fix the name or value in the motion designator"


class RosArgumentError(RosError, ValueError):
    """A value given to the ROS layer is outside what it accepts."""

    summary = "a value given to the ROS layer is outside what it accepts"
    hint = "fix the value the message names: it says the range or the choices"


class RosUsageError(RosError, TypeError):
    """The ROS layer was handed the wrong kind of thing: the caller's mistake."""

    summary = "the ROS layer was handed the wrong kind of thing"
    hint = "pass what the message asks for"


class RosUnknownKey(RosError, KeyError):
    """A name that the ROS layer does not know; the message lists the known ones."""

    summary = "a name that the ROS layer does not know"
    hint = "use one of the names the message lists"
