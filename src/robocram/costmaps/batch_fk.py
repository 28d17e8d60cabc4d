"""Forward kinematics of one frame for many configurations at once, in numpy.

Reachability maps need hundreds of thousands of FK samples; one pinocchio call per sample
spends its time in Python. Here the chain from the root to the frame is walked once, each
joint applied to all samples together. Joints off the sampled set keep their defaults.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from robocram.costmaps.errors import CostmapError
from robocram.kinematics.robot_kinematics import RobotKinematics
from robocram.robots.lazy_library import LazyLibrary

if TYPE_CHECKING:
    import pinocchio as pin
else:
    pin = LazyLibrary("pinocchio")

_AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


def _joint_motion(joint: pin.JointModel) -> tuple[str, NDArray[np.float64]]:
    """``("revolute" | "prismatic", axis)`` of a one-degree-of-freedom pinocchio joint."""
    kind = joint.shortname().removeprefix("JointModel")
    if kind in ("RevoluteUnaligned", "RevoluteUnboundedUnaligned"):
        return "revolute", np.asarray(joint.extract().axis, dtype=float)
    if kind == "PrismaticUnaligned":
        return "prismatic", np.asarray(joint.extract().axis, dtype=float)
    if kind[:-1] in ("R", "RUB") and kind[-1] in _AXES:
        return "revolute", np.array(_AXES[kind[-1]])
    if kind[:-1] == "P" and kind[-1] in _AXES:
        return "prismatic", np.array(_AXES[kind[-1]])
    raise CostmapError(f"batch FK does not know pinocchio joint type {kind!r}")


def _times(rotation: NDArray[np.float64], matrix: NDArray[np.float64]) -> NDArray[np.float64]:
    """``rotation[i] @ matrix`` for all i."""
    return np.einsum("nij,jk->nik", rotation, matrix)


def _turned(
    rotation: NDArray[np.float64], axis: NDArray[np.float64], angles: NDArray[np.float64]
) -> NDArray[np.float64]:
    """``rotation[i] @ Rot(axis, angles[i])`` by Rodrigues: R + sin R K + (1 - cos) R K^2."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    s = np.sin(angles)[:, None, None]
    c = np.cos(angles)[:, None, None]
    return rotation + s * _times(rotation, k) + (1 - c) * _times(rotation, k @ k)


def _with_followers(
    kin: RobotKinematics, values: Mapping[str, NDArray[np.float64]]
) -> dict[str, NDArray[np.float64]]:
    """``values`` plus every mimic joint following one of them, transitively."""
    found = dict(values)
    changed = True
    while changed:
        changed = False
        for joint in kin.robot_model.joints.values():
            mimic = joint.mimic
            if mimic is not None and mimic.joint in found and joint.name not in found:
                found[joint.name] = mimic.multiplier * found[mimic.joint] + mimic.offset
                changed = True
    return found


def batch_frame_poses(
    kin: RobotKinematics, frame: str, values: Mapping[str, NDArray[np.float64]]
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Rotations (N x 3 x 3) and positions (N x 3) of ``frame`` in the root link.

    ``values`` maps joint names to N values each [rad | m]; ``<mimic>`` joints follow them
    (a coupled telescope's segments); other joints sit at the value nearest 0 within their
    limits.
    """
    values = _with_followers(kin, values)
    model = kin.model
    fid = kin.frame_id(frame)
    count = len(next(iter(values.values())))
    chain = []
    joint = int(model.frames[fid].parentJoint)
    while joint > 0:
        chain.append(joint)
        joint = int(model.parents[joint])
    rotation = np.broadcast_to(np.eye(3), (count, 3, 3)).copy()
    position = np.zeros((count, 3))
    for index in reversed(chain):
        name = model.names[index]
        placement = model.jointPlacements[index]
        position = position + np.einsum("nij,j->ni", rotation, placement.translation)
        rotation = _times(rotation, placement.rotation)
        q = values.get(name)
        if q is None:
            q = np.full(count, kin.default_value(name))
        kind, axis = _joint_motion(model.joints[index])
        if kind == "revolute":
            rotation = _turned(rotation, axis, q)
        else:
            position = position + np.einsum("nij,j->ni", rotation, axis) * q[:, None]
    frame_placement = model.frames[fid].placement
    position = position + np.einsum("nij,j->ni", rotation, frame_placement.translation)
    return _times(rotation, frame_placement.rotation), position
