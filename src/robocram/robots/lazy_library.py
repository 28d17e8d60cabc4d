"""A heavy library (pinocchio, coal, OMPL, ruckig, PyBullet) imported where first used.

Importing them all costs about 150 ms of a script's start (issue 40), paid even by a
script that only plans or reads a description. A module binds the library's usual name
to a :class:`LazyLibrary` and keeps the real import for the type checker::

    if TYPE_CHECKING:
        import pinocchio as pin
    else:
        pin = LazyLibrary("pinocchio")

The first attribute read imports the library and copies its attributes in, so later
reads cost what a module's do and ``pin.SE3`` is the library's own class.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from types import ModuleType

__all__ = ["LazyLibrary"]


class LazyLibrary(ModuleType):
    """Stands for the module ``name``; imports it (with ``load``) at the first attribute read."""

    def __init__(self, name: str, load: Callable[[str], ModuleType] | None = None) -> None:
        super().__init__(name)
        self.__dict__["_lazy_load"] = load or importlib.import_module

    def __getattr__(self, attribute: str) -> object:
        """Only reached for an attribute not copied in yet: import, copy, answer."""
        library = self.__dict__["_lazy_load"](self.__name__)
        self.__dict__.update(library.__dict__)
        return getattr(library, attribute)
