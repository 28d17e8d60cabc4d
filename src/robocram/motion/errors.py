"""The motion layer's root error: a motion asked for wrongly (not a plan failure).

A blocked path is a plan failure (``ManipulationPathBlocked``, ``NavigationPathBlocked``
in ``execution.failures``), which plans handle by retrying; a :class:`MotionError` is a
programming error: an unknown joint, a malformed path, a bad resolution.
"""

from __future__ import annotations


class MotionError(ValueError):
    """A motion, path or trajectory was asked for with bad input; the message says which."""
