"""Frames and collision boxes a description adds to its robot's model in code.

The URDF text is never edited: :meth:`RobotModel.with_frame` and ``with_box`` make a new
model with the addition, and a :class:`RobotDescription` lists them in ``extra_frames`` and
``extra_boxes``.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Pose


@dataclass(frozen=True)
class FrameSpec:
    """A frame added to the model in code, as a child of ``parent`` by a fixed joint."""

    name: str
    parent: str
    pose: Pose  # of the new frame in ``parent``


@dataclass(frozen=True)
class BoxSpec:
    """A collision box added to the model in code, on a new link fixed to ``parent``."""

    name: str
    parent: str
    pose: Pose  # of the box centre in ``parent``
    size: tuple[float, float, float]  # [m] full extents along x, y, z
