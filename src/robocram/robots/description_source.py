"""Find the description a user names: a built-in robot, a ``.py`` file, or ``pkg.module:NAME``.

Wherever robocram takes a robot's name (``load_description``, the scenes, ``robocram demo
--robot``, batch specs, the examples) it takes a description file too: ``NAME`` (default
``description``) is a ``RobotDescription`` or a function returning one, so a file written
by ``robocram robot draft`` is used as written.
"""

from __future__ import annotations

import dataclasses
import importlib
import importlib.util
from pathlib import Path

from robocram.robots.builtin import builtin_description
from robocram.robots.description import RobotDescription
from robocram.robots.errors import DescriptionError

DEFAULT_NAME = "description"


class DescriptionSourceError(DescriptionError):
    """A named description cannot be found: no such built-in, file, module or attribute."""


def is_description_spec(spec: str) -> bool:
    """Whether ``spec`` names a file or module (``x.py``, ``x.py:NAME``, ``pkg.mod:NAME``)."""
    where = spec.partition(":")[0]
    return where.endswith(".py") or ":" in spec


def description_from(spec: str) -> RobotDescription:
    """The (unchecked) description ``spec`` names: a built-in robot, a file or a module.

    Raises:
        DescriptionSourceError: no such built-in robot, file, module or attribute; the
            message lists the ways to name a description.
    """
    where, _, name = spec.partition(":")
    name = name or DEFAULT_NAME
    if where.endswith(".py"):
        found = _described(_module_from_file(Path(where)), name, spec)
        return dataclasses.replace(found, source=f"{Path(where).resolve()}:{name}")
    if ":" in spec:
        try:
            module = importlib.import_module(where)
        except ImportError as err:
            raise DescriptionSourceError(f"cannot import {where!r} (from {spec!r}): {err}") from err
        return dataclasses.replace(_described(module, name, spec), source=f"{where}:{name}")
    try:
        return builtin_description(spec)
    except DescriptionError as err:  # its message names the built-ins and the other ways
        raise DescriptionSourceError(str(err)) from err


def _module_from_file(path: Path) -> object:
    if not path.is_file():
        raise DescriptionSourceError(
            f"no file {path}; give the .py file that defines description() "
            "(`robocram robot draft URDF -o FILE` writes one)"
        )
    loader = importlib.util.spec_from_file_location(f"robocram_checked_{path.stem}", path)
    if loader is None or loader.loader is None:
        raise DescriptionSourceError(f"cannot load {path} as a Python module")
    module = importlib.util.module_from_spec(loader)
    loader.loader.exec_module(module)
    return module


def _described(module: object, name: str, spec: str) -> RobotDescription:
    value = getattr(module, name, None)
    if callable(value):
        value = value()
    if not isinstance(value, RobotDescription):
        raise DescriptionSourceError(
            f"{spec!r}: {name!r} is {type(value).__name__}, not a RobotDescription or a "
            "function returning one; name it as module:NAME"
        )
    return value
