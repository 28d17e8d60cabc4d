"""Built-in robots by name, each in its own module exposing ``description()``.

Modules are imported only when their robot is asked for, so one robot's missing data
never stops another from loading.
"""

from __future__ import annotations

import importlib

from robocram.robots.description import RobotDescription
from robocram.robots.errors import DescriptionError, closest_names

_MODULES: dict[str, str] = {
    "boxy": "boxy",
    "hector_quadrotor": "quadrotor",
    "hsr": "hsrb",
    "hsrb": "hsrb",
    "pr2": "pr2",
    "quadrotor": "quadrotor",
}

__all__ = ["builtin_description", "builtin_names"]


def builtin_names() -> tuple[str, ...]:
    """Names (and aliases) ``builtin_description`` accepts, sorted."""
    return tuple(sorted(_MODULES))


def builtin_description(name: str) -> RobotDescription:
    """The unchecked description of the built-in robot ``name`` (``load_description`` checks)."""
    module_name = _MODULES.get(name.lower())
    if module_name is None:
        close = closest_names(name.lower(), _MODULES)
        hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
        raise DescriptionError(
            f"no built-in robot {name!r}{hint} (built-in: {', '.join(builtin_names())}); "
            "or give a .py file defining description() (as `robocram robot draft` writes), "
            "pkg.module:NAME, or a RobotDescription"
        )
    module = importlib.import_module(f"{__name__}.{module_name}")
    description: RobotDescription = module.description()
    return description
