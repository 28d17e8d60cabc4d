"""Where a link of the environment is now, asked of the world through the knowledge base."""

from __future__ import annotations

from robocram.knowledge.world_predicates import LINK_POSE
from robocram.logic import current_kb
from robocram.plans.errors import PlanSetupError
from robocram.tf import Pose


def environment_link_pose(environment: str, link: str, role: str) -> Pose:
    """The map pose of ``link`` of ``environment``, which the KB names as a ``role``.

    Raises:
        PlanSetupError: the world has no such link (facts from another scene).
    """
    row = LINK_POSE.first(current_kb(), object=environment, link=link)
    if row is None:
        raise PlanSetupError(
            f"the KB names {link!r} of {environment!r} as {role}, but the world has no such "
            "link; regenerate the scene's facts"
        )
    return row.pose
