"""The kitchen's batch plan: transport one item to a supporting surface.

A batch plan is ``plan(look_target, **parameters)`` (see :mod:`robocram.batch.worker`);
transporting searches for the object itself, so the look target is not used. The item's
name fixes the object the placing location is sized for; its type is what the search
looks for.
"""

from __future__ import annotations

from robocram.designators import a
from robocram.plans.transport import TransportResult, transport
from robocram.tf import PoseStamped


def transport_item(
    look_target: PoseStamped,
    object_type: str = "mug",
    item: str = "mug-1",
    onto: str = "table_top",
    environment: str = "kitchen",
) -> TransportResult:
    """Search for an ``object_type``, fetch it and put it on ``onto`` of ``environment``."""
    del look_target  # the search finds the object
    return transport(object_type, a.location(on=(environment, onto), for_=item))
