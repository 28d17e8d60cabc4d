"""Forward kinematics of an arm chain for many configurations at once, in numpy.

IK's start table needs the tool pose of tens of thousands of sampled configurations; one
pinocchio call per sample would take a second per arm. The chain is a product of fixed
placements and one-axis motions, so all samples go through it together: a rotation
about the joint's axis (Rodrigues) for revolute and continuous joints, a shift along it
for prismatic ones. Poses are relative to the chain's base frame: the frame the first
IK variable's joint hangs from, so held joints before it (the torso) do not matter.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from robocram.kinematics.arm_chain import ArmChain, FloatArray
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")


def chain_base(chain: ArmChain) -> pin.SE3:
    """Pose of the chain's base frame in the root link, from the last FK of ``chain.data``."""
    # the reduced model holds the path only: path row r is joint r + 1, its parent joint r
    return chain.data.oMi[min(chain.first_row, len(chain.path))].copy()


def _rotations(axis: FloatArray, angles: FloatArray) -> FloatArray:
    """Rotation matrices about unit ``axis`` by each of ``angles`` [rad], shape (3, 3, n)."""
    k = np.array([[0.0, -axis[2], axis[1]], [axis[2], 0.0, -axis[0]], [-axis[1], axis[0], 0.0]])
    s, c = np.sin(angles), np.cos(angles)
    return np.eye(3)[:, :, None] + k[:, :, None] * s + (k @ k)[:, :, None] * (1.0 - c)


def _times(rot: FloatArray, other: FloatArray) -> FloatArray:
    """``rot @ other`` for stacks laid out (3, 3, n); ``other`` may be one (3, 3) matrix."""
    if other.ndim == 2:
        return np.einsum("ikn,kj->ijn", rot, other)
    return (rot[:, :, None, :] * other[None, :, :, :]).sum(axis=1)


def sweep_tip_poses(chain: ArmChain, values: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Tip positions (n, 3) and rotations (n, 3, 3) in the chain base for path values.

    ``values`` holds one row of path joint values (``A @ x + b``) per configuration.
    Stacks are laid out (3, 3, n) while sweeping, so each product is 27 vector operations.
    """
    n = values.shape[0]
    rot = np.repeat(np.eye(3)[:, :, None], n, axis=2)
    pos = np.zeros((3, n))
    for row in range(chain.first_row, len(chain.path)):
        placement = chain.model.jointPlacements[row + 1]
        pos = pos + np.einsum("ikn,k->in", rot, placement.translation)
        rot = _times(rot, placement.rotation)
        joint = chain.kin.robot_model.joints[chain.path[row]]
        axis = np.asarray(joint.axis, float)
        axis = axis / np.linalg.norm(axis)
        if joint.type == "prismatic":
            pos = pos + np.einsum("ikn,k->in", rot, axis) * values[:, row]
        else:
            rot = _times(rot, _rotations(axis, values[:, row]))
    tip = chain.model.frames[chain.frame_id].placement
    pos = pos + np.einsum("ikn,k->in", rot, tip.translation)
    return pos.T.copy(), np.moveaxis(_times(rot, tip.rotation), 2, 0).copy()
