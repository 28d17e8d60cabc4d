"""A body moved only by its carrier for a while: static to physics, so nothing pushes it.

A held object follows its hand by being put where the hand is at every step; as a
dynamic body, whatever it touches also pushes it, and Bullet shares each contact's
correction between the two: grains resting in a held cup crept through its wall a few
tenths of a millimetre per step. Inside :func:`kinematic` the body has no mass (Bullet's
static body), so contacts push only the others; its mass comes back after.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import TYPE_CHECKING

from robocram.world.pybullet_backend import pybullet
from robocram.world.world_tables import ObjectRef

if TYPE_CHECKING:
    from robocram.world.world_facade import WorldFacade


@contextlib.contextmanager
def kinematic(world: WorldFacade, obj: ObjectRef) -> Iterator[None]:
    """Inside the block ``obj`` is moved only by whoever sets its pose (its carrier)."""
    handle = world.object(obj)
    cid = world.physics.client()
    mass = float(pybullet.getDynamicsInfo(handle.body_id, -1, physicsClientId=cid)[0])
    pybullet.changeDynamics(handle.body_id, -1, mass=0.0, physicsClientId=cid)
    try:
        yield
    finally:
        pybullet.changeDynamics(handle.body_id, -1, mass=mass, physicsClientId=cid)
