"""Objects attached to robot links follow the link kinematically."""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import Pose


@dataclass(frozen=True)
class Attachment:
    """``obj`` hangs from ``link`` of ``robot`` at the fixed pose ``link_T_obj``."""

    obj: str
    robot: str
    link: str
    link_T_obj: Pose  # noqa: N815  (frames in the name: the object's pose in the link frame)
