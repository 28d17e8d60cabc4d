"""Bodies asleep while one object settles: Bullet leaves a sleeping body as it is.

A step of the kitchen costs ~0.7 ms, nearly all of it for what does not move: the robot
and the kitchen (~160 links, their joint limits and motors) and the objects resting on
the counter (their contacts). While a put-down object settles, they sleep: PyBullet does
not integrate them nor solve their contacts, unless something moving touches them (then
Bullet wakes them as usual). Bullet solves apart what does not touch, so the settling
object moves exactly as it would among awake bodies (~0.15 ms a step).

Waking puts the bodies back as PyBullet makes them (no sleeping of their own, awake), but
Bullet marks their shapes awake only at the end of their next step: in that step they
stay as they are. A caller takes that step before anything else may move them.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator, Sequence

from robocram.world.pybullet_backend import pybullet


def _asleep() -> int:
    """PyBullet's activation state of a body that may sleep and sleeps now."""
    return int(pybullet.ACTIVATION_STATE_ENABLE_SLEEPING | pybullet.ACTIVATION_STATE_SLEEP)


def _awake() -> int:
    """PyBullet's activation state of a body awake that never sleeps."""
    return int(pybullet.ACTIVATION_STATE_WAKE_UP | pybullet.ACTIVATION_STATE_DISABLE_SLEEPING)


@contextlib.contextmanager
def asleep(bodies: Sequence[int], cid: int) -> Iterator[None]:
    """``bodies`` (ids) sleep within the block; afterwards they are awake and never sleep."""
    for body in bodies:
        pybullet.changeDynamics(body, -1, activationState=_asleep(), physicsClientId=cid)
    try:
        yield
    finally:
        for body in bodies:
            pybullet.changeDynamics(body, -1, activationState=_awake(), physicsClientId=cid)
