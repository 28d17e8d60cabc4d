"""What perception attaches to an object designator it made effective.

Every perception backend (projection's camera, a robot's perception server behind ROS)
answers with the object's name, type and pose; plans read them from the designator.
"""

from __future__ import annotations

from dataclasses import dataclass

from robocram.tf import PoseStamped


@dataclass(frozen=True)
class PerceivedObject:
    """What perception attaches to a designator: the object and its pose in the base frame."""

    name: str
    type: str
    pose: PoseStamped
