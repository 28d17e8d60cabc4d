"""Raw PyBullet lookups the tests judge with, apart from the code under test."""

from __future__ import annotations

import numpy as np
import pybullet


def link_indices(body: int, client: int) -> dict[str, int]:
    """Each link's index in PyBullet's ``body`` by the link's name (the root is -1, absent)."""
    count = pybullet.getNumJoints(body, physicsClientId=client)
    return {
        pybullet.getJointInfo(body, i, physicsClientId=client)[12].decode(): i for i in range(count)
    }


def link_frame(body: int, client: int, link: str) -> tuple[np.ndarray, np.ndarray]:
    """The position and 3x3 rotation of link ``link``'s frame in the map, as PyBullet's own
    forward kinematics has it."""
    state = pybullet.getLinkState(
        body,
        link_indices(body, client)[link],
        computeForwardKinematics=True,
        physicsClientId=client,
    )
    rotation = np.array(pybullet.getMatrixFromQuaternion(state[5])).reshape(3, 3)
    return np.asarray(state[4]), rotation
