"""Find the description a user names: ``pkg.module:NAME``, a ``.py`` file, or a built-in.

``NAME`` (default ``description``) is a ``RobotDescription`` or a function returning one,
so a drafted file (which defines ``description()``) is checked as written.
"""

from __future__ import annotations

import importlib
import importlib.util
from pathlib import Path

from robocram.robot_check.errors import RobotCheckError
from robocram.robots import DescriptionError, RobotDescription
from robocram.robots.builtin import builtin_description, builtin_names

DEFAULT_NAME = "description"


def description_from(spec: str) -> RobotDescription:
    """The description ``spec`` names.

    Raises:
        RobotCheckError: no such module, file, attribute or built-in robot.
    """
    where, _, name = spec.partition(":")
    name = name or DEFAULT_NAME
    if where.endswith(".py"):
        module = _module_from_file(Path(where))
    elif ":" in spec:
        try:
            module = importlib.import_module(where)
        except ImportError as err:
            raise RobotCheckError(f"cannot import {where!r} (from {spec!r}): {err}") from err
    else:
        try:
            return builtin_description(spec)
        except DescriptionError as err:
            raise RobotCheckError(
                f"{spec!r} is no built-in robot ({', '.join(builtin_names())}), no .py file and "
                "no pkg.module:NAME; name the description one of those ways"
            ) from err
    return _described(module, name, spec)


def _module_from_file(path: Path) -> object:
    if not path.is_file():
        raise RobotCheckError(f"no file {path}; give the .py file that defines description()")
    loader = importlib.util.spec_from_file_location(f"robocram_checked_{path.stem}", path)
    if loader is None or loader.loader is None:
        raise RobotCheckError(f"cannot load {path} as a Python module")
    module = importlib.util.module_from_spec(loader)
    loader.loader.exec_module(module)
    return module


def _described(module: object, name: str, spec: str) -> RobotDescription:
    value = getattr(module, name, None)
    if callable(value):
        value = value()
    if not isinstance(value, RobotDescription):
        raise RobotCheckError(
            f"{spec!r}: {name!r} is {type(value).__name__}, not a RobotDescription or a "
            "function returning one; name it as module:NAME"
        )
    return value
