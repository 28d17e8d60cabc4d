"""What a tool motion's process module answers: how far the path went, and what it did.

The ``tools`` motions (``moving-tool-path``, ``pouring``, ``cutting``) answer these frozen
values in every environment; what only a projection can count (the particles that landed,
the slices made) is filled in there and left empty (None) where nobody counts it.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Pose


@dataclass(frozen=True)
class ToolPathAnswer:
    """A tool path as executed: the fraction of it reached (0..1), why it stopped (empty
    when it reached the end) and the tool point's poses in ``map`` along the executed
    trajectory (one per trajectory point)."""

    fraction: float
    stopped_by: str = ""
    tool_poses: tuple[Pose, ...] = ()


@dataclass(frozen=True)
class PouringAnswer:
    """A pour: its tilt path, and of the ``particles`` that stood for the contents (in
    projection), how many ``landed`` in the target and how many ``spilled``."""

    path: ToolPathAnswer
    particles: int | None = None
    landed: int | None = None
    spilled: int | None = None


@dataclass(frozen=True)
class CuttingAnswer:
    """A cut: its sawing path, the cuts the knife went through (offsets [m] along the
    object's axis) and the names of the slices the object became (in projection)."""

    path: ToolPathAnswer
    cuts_made: tuple[float, ...] = ()
    slices: tuple[str, ...] = ()
