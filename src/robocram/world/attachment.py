"""Objects attached to robot links follow the link kinematically."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from robocram.tf import Pose
from robocram.world.errors import AttachmentCycleError


@dataclass(frozen=True)
class Attachment:
    """``obj`` hangs from ``link`` of ``robot`` at the fixed pose ``link_T_obj``."""

    obj: str
    robot: str
    link: str
    link_T_obj: Pose  # noqa: N815  (frames in the name: the object's pose in the link frame)


def check_acyclic(attachments: Mapping[str, Attachment], obj: str, carrier: str) -> None:
    """Refuse hanging ``obj`` from ``carrier`` when ``carrier`` already hangs from ``obj``."""
    chain = [carrier]
    while chain[-1] in attachments and chain[-1] != obj:
        chain.append(attachments[chain[-1]].robot)
    if chain[-1] == obj:
        raise AttachmentCycleError(obj, carrier, [obj, *chain[:-1]])
