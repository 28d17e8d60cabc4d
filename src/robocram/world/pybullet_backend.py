"""PyBullet, loaded once for the whole world package, without its build-time banner.

The C extension prints ``pybullet build time: ...`` when it is loaded (to standard error in
the wheels we use, to standard output in some builds): into every command's output and a
test's captured text. Every module of ``robocram.world`` imports ``pybullet`` from here,
so the banner is silenced in one place: file descriptors 1 and 2 point at the null device
while the extension loads, C's output buffers are flushed there, and both are restored.
It loads at the first use of ``pybullet``, not at import (issue 40).
"""

from __future__ import annotations

import contextlib
import ctypes
import importlib
import os
import sys
from collections.abc import Iterator
from types import ModuleType
from typing import TYPE_CHECKING

from robocram.robots.lazy_library import LazyLibrary

__all__ = ["pybullet", "silenced"]


@contextlib.contextmanager
def silenced(descriptors: tuple[int, ...] = (1, 2)) -> Iterator[None]:
    """Send what C code writes to ``descriptors`` to the null device, then restore them."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved: dict[int, int] = {}
    null = os.open(os.devnull, os.O_WRONLY)
    try:
        for fd in descriptors:
            with contextlib.suppress(OSError):  # a closed descriptor has nothing to hide
                saved[fd] = os.dup(fd)
                os.dup2(null, fd)
        yield
    finally:
        with contextlib.suppress(OSError, AttributeError):
            ctypes.CDLL(None).fflush(None)  # the banner may wait in C's buffer of a pipe
        for fd, copy in saved.items():
            os.dup2(copy, fd)
            os.close(copy)
        os.close(null)


def _silenced_import(name: str) -> ModuleType:
    """Import ``name`` with its banner sent to the null device."""
    with silenced():
        return importlib.import_module(name)


if TYPE_CHECKING:
    import pybullet
else:
    pybullet = LazyLibrary("pybullet", _silenced_import)
