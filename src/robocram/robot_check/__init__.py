"""Check a robot description by driving each part once: ``check_robot(desc)`` -> report card."""

from robocram.robot_check.check_robot import check_robot
from robocram.robot_check.description_source import description_from
from robocram.robot_check.errors import (
    CheckUnknownKey,
    RobotCheckError,
)
from robocram.robot_check.report_card import CheckResult, ReportCard

__all__ = [
    "CheckResult",
    "CheckUnknownKey",
    "ReportCard",
    "RobotCheckError",
    "check_robot",
    "description_from",
]
