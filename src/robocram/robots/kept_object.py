"""A value built once per machine from robocram's own data classes, kept on disk.

Some one-time builds give a tree of frozen dataclasses rather than arrays (the kitchen's
drafted description: ~70 ms, each process the same). :func:`kept_object` keeps its
pickle as one array of :func:`~robocram.robots.disk_cache.kept_arrays`, so it is keyed,
checked and written as those are. It is read back with an unpickler that makes only
robocram's classes and paths: any other global in a file (a function to call, a class
of another library) refuses it, and it is rebuilt and replaced like a damaged one.
"""

from __future__ import annotations

import io
import pickle
from collections.abc import Callable, Sequence
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

from robocram.robots.disk_cache import Arrays, kept_arrays

__all__ = ["kept_object"]

T = TypeVar("T")
_PICKLE = "pickle"
_PATHS = frozenset({"Path", "PosixPath", "WindowsPath", "PurePath", "PurePosixPath"})


class _OwnClasses(pickle.Unpickler):
    """Makes robocram's classes (and paths) only; :meth:`find_class` refuses the rest."""

    def find_class(self, module: str, name: str) -> type:
        if module.startswith("robocram.") or (module == "pathlib" and name in _PATHS):
            found = super().find_class(module, name)
            if isinstance(found, type):
                return found
        raise pickle.UnpicklingError(f"{module}.{name} is not kept")


def kept_object(
    kind: str,
    key: str,
    built_by: Sequence[str],
    build: Callable[[], T],
    of: type[T],
    accept: Callable[[T], bool] | None = None,
) -> T:
    """The ``of`` that ``build()`` returns for ``key``: read from disk, else built and
    written (``kind``, ``key``, ``built_by`` as :func:`kept_arrays` takes them).

    ``accept``: whether a value read is still right (one it refuses is rebuilt and
    replaced), for values that depend on more than ``key`` can say.
    """
    made: list[T] = []

    def pickled() -> Arrays:
        made.append(build())
        data = pickle.dumps(made[0], protocol=pickle.HIGHEST_PROTOCOL)
        return {_PICKLE: np.frombuffer(data, dtype=np.uint8)}

    def readable(arrays: Arrays) -> bool:
        value = _unpickled(arrays, of)
        if value is None or (accept is not None and not accept(value)):
            return False
        made.append(value)
        return True

    kept_arrays(kind, key, (__name__, *built_by), pickled, accept=readable)
    return made[-1]


def _unpickled(arrays: Arrays, of: type[T]) -> T | None:
    """The value pickled in ``arrays``, if it is an ``of`` made of allowed classes."""
    data: NDArray[np.generic] | None = arrays.get(_PICKLE)
    if data is None or data.dtype != np.uint8:
        return None
    try:
        value = _OwnClasses(io.BytesIO(data.tobytes())).load()
    except (pickle.UnpicklingError, AttributeError, EOFError, ImportError, TypeError, ValueError):
        return None
    return value if isinstance(value, of) else None
