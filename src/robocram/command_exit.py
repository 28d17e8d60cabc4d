"""How a ``robocram`` command ends: its exit codes, and which errors mean bad input (exit 3).

The command line imports each package only inside the commands that use it, so the root
errors of bad input are named here by module rather than imported: an error class whose
module was never loaded cannot have been raised.
"""

from __future__ import annotations

import sys

EXIT_OK, EXIT_FAILED, EXIT_USAGE, EXIT_INPUT = 0, 1, 2, 3

INPUT_ERRORS = (  # (module, class): the root errors of input a command cannot work with
    ("robocram.traces.errors", "TraceError"),
    ("robocram.robots.errors", "DescriptionError"),
    ("robocram.scenes.errors", "SceneError"),
    ("robocram.viewer.errors", "ViewerError"),
    ("robocram.world.errors", "BodyLoadError"),
)


class CliInputError(Exception):
    """Input the command cannot work with; the message says what to do instead."""


def is_input_error(err: BaseException) -> bool:
    """Whether ``err`` is bad input: a :class:`CliInputError` or a loaded package's root error."""
    if isinstance(err, CliInputError):
        return True
    for module_name, class_name in INPUT_ERRORS:
        module = sys.modules.get(module_name)
        root = getattr(module, class_name, None) if module is not None else None
        if isinstance(root, type) and isinstance(err, root):
            return True
    return False
