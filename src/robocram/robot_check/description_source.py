"""Find the description a user names: ``pkg.module:NAME``, a ``.py`` file, or a built-in.

The robots layer's :func:`robocram.robots.description_source.description_from`, with its
errors raised as :class:`RobotCheckError` for the report card's callers.
"""

from __future__ import annotations

from robocram.robot_check.errors import RobotCheckError
from robocram.robots import RobotDescription
from robocram.robots.description_source import DescriptionSourceError
from robocram.robots.description_source import description_from as _description_from


def description_from(spec: str) -> RobotDescription:
    """The description ``spec`` names.

    Raises:
        RobotCheckError: no such module, file, attribute or built-in robot.
    """
    try:
        return _description_from(spec)
    except DescriptionSourceError as err:
        raise RobotCheckError(str(err)) from err
