"""When a put-down object rests: how often it is looked at and how still it must be.

Looked at every step, an object let go a few mm above its support seems to rest in its
first step, before it starts falling; looked at every second step it lands within the
fifth look and rests by the sixth or seventh (12 to 14 steps at 240 Hz).
"""

from __future__ import annotations

from robocram.tf import Pose

LOOK = 1.0 / 120.0  # [s] simulated between two looks at the object (2 steps at 240 Hz)
AT_REST = 0.0002  # [m] an object moving less than this between two looks rests (2.4 cm/s)
AT_REST_TURN = 0.004  # [rad] ... and turning less than this (0.5 rad/s: a mug rocks a little)


def at_rest(before: Pose, now: Pose) -> bool:
    """Whether an object seen at ``before`` and one look later at ``now`` rests."""
    return now.distance_to(before) < AT_REST and now.angle_to(before) < AT_REST_TURN
