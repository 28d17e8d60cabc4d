"""Raw PyBullet lookups the tests judge with, apart from the code under test."""

from __future__ import annotations

import pybullet


def link_indices(body: int, client: int) -> dict[str, int]:
    """Each link's index in PyBullet's ``body`` by the link's name (the root is -1, absent)."""
    count = pybullet.getNumJoints(body, physicsClientId=client)
    return {
        pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i for i in range(count)
    }
